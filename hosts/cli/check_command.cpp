// pxflow check: the cross-check of every backend against ref-original.
#include <fstream>
#include <iostream>

#include "check.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "list_option.hpp"
#include "output_file.hpp"
#include "progress.hpp"

namespace pxflow::cli {
namespace {

struct CheckArgs {
  std::string backends, require, json_path, data_dir = CorpusOptions{}.data_dir;
  std::uint64_t seed = 1;
  long cases = 0;
  bool verbose = false, generated_only = false;
  BackendOptions backend_options;
};

int run_check_command(const CheckArgs& a) {
  CheckOptions o;
  o.backends = split_list(a.backends);
  o.require = split_list(a.require);
  o.fuzz_pairs = a.cases;
  o.verbose = a.verbose;
  o.backend_options = a.backend_options;
  o.corpus.seed = a.seed;
  o.corpus.data_dir = a.data_dir;
  o.corpus.real = !a.generated_only;
  if (!a.json_path.empty()) check_output_path("--json", a.json_path);
  o.banner = "pxflow check: seed " + std::to_string(a.seed) +
             (a.cases > 0 ? ", fuzz campaign of " + std::to_string(a.cases) + " random pairs"
                          : ", fixed corpus");
  const CheckReport r = run_check(o, std::cout);

  std::printf("\n%-14s %-8s %7s %7s %5s %9s  %s\n", "backend", "result", "cases", "pairs", "n/a",
              "run time", "note");
  for (const auto& b : r.backends)
    std::printf("%-14s %-8s %7ld %7ld %5ld %8.2fs  %s\n", b.name.c_str(), state_name(b.state),
                b.passed + b.failed, b.pairs, b.not_applicable, b.seconds, b.reason.c_str());
  std::printf("%ld passed, %ld failed, %ld skipped\n", r.passed, r.failed, r.skipped);
  if (r.compared == 0)
    std::printf(
        "nothing was checked: no backend but the reference ran a case (see the skips above)\n");
  if (!a.json_path.empty()) write_output_file(a.json_path, check_json(r).dump(2) + "\n");
  return r.ok() ? 0 : 1;
}

}  // namespace

Command add_check_command(CLI::App& app) {
  auto a = std::make_shared<CheckArgs>();
  CLI::App* sub =
      app.add_subcommand("check", "Check every backend against ref-original, bit for bit");
  sub->add_option("--backends", a->backends,
                  "Comma-separated backends to check (default: all compiled in)");
  sub->add_option("--require", a->require,
                  "Backends that must run (comma-separated, or 'all'): their skips fail");
  sub->add_option("--seed", a->seed, "Seed of the random pairs (printed; reproduces any failure)")
      ->check(seed_value())
      ->capture_default_str();
  sub->add_option("--cases", a->cases, "Fuzz campaign: N random pairs instead of the fixed corpus")
      ->check(CLI::Range(1L, 100000000L));
  sub->add_option("--json", a->json_path, "Write the results as JSON to FILE");
  sub->add_option("--data", a->data_dir, "Folder of the real frames (opencv-doc)")
      ->capture_default_str();
  sub->add_flag("--generated-only", a->generated_only,
                "Skip the real frames (random, hostile, threshold cases only)");
  sub->add_flag("--verbose", a->verbose, "Dump the 8x8 blocks behind each mismatch");
  add_progress_flag(*sub);
  sub->add_option("--threads", a->backend_options.threads,
                  "Host worker threads of the CPU backends and the GAP8 model (0 = all cores)")
      ->check(CLI::Range(0, 1024));
  sub->add_option("--device", a->backend_options.device,
                  "Device index or name substring (GPU backends)");
  return {sub, [a] { return run_check_command(*a); }};
}

}  // namespace pxflow::cli
