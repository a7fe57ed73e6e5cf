// pxflow's command line: parses the subcommand, runs it, and turns every error into one line on
// stderr: exit 2 for bad input, 1 for a failure while running.
#include <cstdio>
#include <new>

#include "commands.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
#include "pxflow_app.hpp"
#ifdef PXFLOW_WITH_CPU_SIMD
#include "isa_mask.hpp"
#endif

namespace pxflow {

int run_pxflow(int argc, char** argv) {
  quiet_opencv();
  CLI::App app{"pxflow: the PX4FLOW optical-flow kernel, cross-checked bit for bit across backends"};
  app.set_version_flag("--version", "pxflow 0.1");
  app.require_subcommand(1);
  app.fallthrough();  // global options may follow the subcommand
#ifdef PXFLOW_WITH_CPU_SIMD
  std::string disabled_isas;
  app.add_option("--disable-isa", disabled_isas,
                 "Mask CPU ISAs for this run, e.g. avx512bw,avx2 (replaces PXFLOW_DISABLE)");
#endif
  std::vector<cli::Command> commands = {cli::add_flow_command(app), cli::add_check_command(app),
                                        cli::add_bench_command(app), cli::add_report_command(app),
                                        cli::add_accuracy_command(app),
                                        cli::add_backends_command(app)};
#ifdef PXFLOW_WITH_GAP8
  commands.push_back(cli::add_gap8_command(app));
#endif
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    for (const auto& c : commands) known |= c.app->get_name() == argv[1];
    if (!known) {
      std::fprintf(stderr, "pxflow: error: unknown command '%s' (see pxflow --help)\n", argv[1]);
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "pxflow: error: %s (see pxflow --help)\n", e.what());
    return 2;
  }
  try {
#ifdef PXFLOW_WITH_CPU_SIMD
    if (!disabled_isas.empty()) cpu::set_disabled_isas(disabled_isas);
#endif
    for (const auto& c : commands)
      if (c.app->parsed()) return c.run();
    return 2;
  } catch (const InputError& e) {
    std::fprintf(stderr, "pxflow: error: %s\n", e.what());
    return 2;
  } catch (const BackendError& e) {
    std::fprintf(stderr, "pxflow: backend failed: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "pxflow: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pxflow: internal error: %s\n", e.what());
    return 1;
  }
}

}  // namespace pxflow
