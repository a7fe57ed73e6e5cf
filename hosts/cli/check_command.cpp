// pxflow check: the cross-check of every backend against ref-original.
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "check.hpp"
#include "check_worker.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "device_wait.hpp"
#include "errors.hpp"
#include "json_document.hpp"
#include "list_option.hpp"
#include "output_plan.hpp"
#include "path_options.hpp"
#include "progress.hpp"

namespace pxflow::cli {
namespace {

constexpr const char* kHelp = " (see pxflow check --help)";

struct CheckArgs {
  std::string backend, backends, require, json_path, shard, repro_dir;
  double repro_seconds = ShrinkLimits{}.seconds;
  bool no_repro = false;
  std::string data_dir = CorpusOptions{}.data_dir;
  std::uint64_t seed = 1;
  long cases = 0;
  double case_timeout = 0;
  std::string worker_row;  // the hidden --check-worker ROW: serve that row to a checking pxflow
  std::vector<std::string> worker_command;
  bool verbose = false, generated_only = false, limits_only = false;
  BackendOptions backend_options;
  std::string globals;  // the global options given (--dut, --disable-isa ...): they shape the run
  CLI::Option *backend_opt = nullptr, *backends_opt = nullptr, *data_opt = nullptr,
              *shard_opt = nullptr, *repro_dir_opt = nullptr;
};

// --backend NAME runs one backend, --backends LIST several: one meaning each, never both.
std::vector<std::string> chosen_backends(const CheckArgs& a) {
  const bool one = a.backend_opt->count() > 0, list = a.backends_opt->count() > 0;
  if (one && list)
    throw InputError("--backend " + a.backend + " and --backends " + a.backends +
                     ": give one of them (--backend NAME for one, --backends LIST for several)" +
                     kHelp);
  if (one && (a.backend.empty() || a.backend.find(',') != std::string::npos))
    throw InputError("--backend: '" + a.backend +
                     "': one backend name (several: --backends LIST; names: pxflow backends)" +
                     kHelp);
  if (one) return {a.backend};
  if (list && split_list(a.backends).empty())
    throw InputError("--backends: '" + a.backends +
                     "': a comma-separated list of backend names (names: pxflow backends)" + kHelp);
  return split_list(a.backends);
}

// The command that reproduces this run, for the results file.
std::string command_line(const CheckArgs& a) {
  std::string c = "pxflow" + a.globals + " check";
  if (a.backend_opt->count() > 0) c += " --backend " + a.backend;
  if (a.backends_opt->count() > 0) c += " --backends " + a.backends;
  if (!a.require.empty()) c += " --require " + a.require;
  if (a.cases > 0) c += " --cases " + std::to_string(a.cases);
  c += " --seed " + std::to_string(a.seed);
  if (a.shard_opt->count() > 0) c += " --shard " + a.shard;
  if (a.generated_only) c += " --generated-only";
  if (a.limits_only) c += " --limits-only";
  if (a.data_opt->count() > 0) c += " --data " + shell_word(a.data_dir);
  if (!a.backend_options.device.empty()) c += " --device " + shell_word(a.backend_options.device);
  if (a.backend_options.threads != 0)
    c += " --threads " + std::to_string(a.backend_options.threads);
  if (a.case_timeout > 0) c += " --case-timeout " + setting_text(a.case_timeout);
  if (!a.json_path.empty()) c += " --json " + shell_word(a.json_path);
  if (a.no_repro) c += " --no-repro";
  if (a.repro_dir_opt->count() > 0) c += " --repro-dir " + shell_word(a.repro_dir);
  return c;
}

// Where reproducers go: --repro-dir, else the --json file's folder, else the working folder. The
// default is used only where files can be made (a check in a read-only folder still runs).
OutputFolder* plan_reproducers(const CheckArgs& a, OutputPlan& plan) {
  if (a.no_repro) return nullptr;
  std::string dir = a.repro_dir;
  if (a.repro_dir_opt->count() == 0) {
    const std::filesystem::path json(a.json_path);
    dir = a.json_path.empty() || a.json_path == kStdoutPath || !json.has_parent_path()
              ? "."
              : json.parent_path().string();
    if (::access(dir.c_str(), W_OK) != 0) return nullptr;
  }
  return &plan.folder("--repro-dir", dir, "pxflow-repro-N");
}

int run_check_command(const CheckArgs& a) {
  if (!a.worker_row.empty()) return worker::serve(a.worker_row, a.backend_options);
  CheckOptions o;
  o.backends = chosen_backends(a);
  o.require = split_list(a.require);
  o.fuzz_pairs = a.cases;
  if (a.shard_opt->count() > 0) o.shard = parse_shard("--shard", a.shard);
  o.verbose = a.verbose;
  o.backend_options = a.backend_options;
  o.isolation = {a.worker_command, a.case_timeout};
  o.corpus.seed = a.seed;
  o.corpus.data_dir = a.data_dir;
  if (a.limits_only && a.cases > 0)
    throw InputError(
        "--limits-only: the limit cases are part of the fixed corpus, not of a fuzz "
        "campaign (--cases)" +
        std::string(kHelp));
  o.corpus.limits_only = a.limits_only;
  o.corpus.real = !a.generated_only && !a.limits_only;
  o.command = command_line(a);
  const BuildIdentity built = build_identity();
  o.pxflow_version = built.version;
  o.pxflow_commit = built.commit;
  const bool json_to_stdout = a.json_path == kStdoutPath;
  OutputPlan plan;
  if (o.corpus.real) plan.read_folder("--data", a.data_dir);
  OutputFile* const json_file = a.json_path.empty() ? nullptr : &plan.file("--json", a.json_path);
  OutputFolder* const repro = plan_reproducers(a, plan);
  plan.prepare();
  if (repro) {
    o.repro.dir = repro->dir();
    o.repro.write = [repro](const std::string& path, std::string_view bytes) {
      repro->write(path, bytes);
    };
    o.repro.make_folder = [repro](const std::string& path) { return repro->make_subfolder(path); };
  }
  o.repro.program = "pxflow" + a.globals;
  o.repro.limits.seconds = a.repro_seconds;
  o.banner = "pxflow check: seed " + std::to_string(a.seed) +
             (a.cases > 0 ? ", fuzz campaign of " + std::to_string(a.cases) + " random pairs"
                          : ", fixed corpus") +
             (o.shard.count > 1 ? ", shard " + o.shard.text() : "");
  // With the JSON on stdout, everything for humans goes to stderr.
  std::ostream& human = json_to_stdout ? std::cerr : std::cout;
  const CheckReport r = run_check(o, human);
  print_check_summary(r, human);
  // A shard whose cases are all n/a for its backends (say the 640x480 ones for the GAP8 rows)
  // compared nothing, rightly: whether the campaign tested anything is merge's verdict.
  const bool merge_judges = o.shard.count > 1 && r.verdict() == "nothing-checked";
  if (merge_judges)
    human << "shard " << o.shard.text()
          << " compared nothing: exit 0, pxflow merge judges the whole campaign\n";
  const std::string json = json_document(check_json(r));
  if (json_file) json_file->write(json);
  return r.ok() || merge_judges ? 0 : 1;
}

}  // namespace

// What --help and the man page show under Examples (the command line after "pxflow ").
const std::vector<std::string> kCheckExamples = {
    "check  # every backend against ref-original, bit for bit",
    "check --dut ref=exec:pxflow-dut-ref --require ref  # a kernel outside pxflow",
    "check --backends m4-qemu --require m4-qemu  # the Cortex-M4 firmware under QEMU",
    "check --cases 10000 --seed 7 --shard 2/4 --json s2.json  # one quarter of a campaign",
};

Command add_check_command(CLI::App& app) {
  auto a = std::make_shared<CheckArgs>();
  CLI::App* sub =
      app.add_subcommand("check", "Check every backend against ref-original, bit for bit");
  a->backend_opt = add_backend_option(*sub, a->backend, "the one to check");
  a->backends_opt = add_backends_option(*sub, a->backends, "the ones to check");
  sub->add_option("--require", a->require,
                  "Backends that must run (comma-separated, or 'all': every row but those needing "
                  "hardware this machine lacks, an ISA extension): their skips fail")
      ->type_name("LIST|all");
  add_seed_option(*sub, a->seed, "printed; it reproduces any failure");
  sub->add_option("--cases", a->cases, "Fuzz campaign: N random pairs instead of the fixed corpus")
      ->check(CLI::Range(1L, 100000000L));
  a->shard_opt = sub->add_option("--shard", a->shard,
                                 "Run the K-th of M disjoint parts of the campaign (K/M, e.g. 2/4; "
                                 "`pxflow merge` combines the parts' --json files)")
                     ->type_name("K/M");
  add_json_option(*sub, a->json_path);
  a->data_opt = add_data_option(*sub, a->data_dir);
  sub->add_flag("--generated-only", a->generated_only,
                "Skip the real frames (random, hostile, threshold cases only)");
  sub->add_flag("--limits-only", a->limits_only,
                "Only the limit cases: each backend at the edges its unsupported() declares, and "
                "SPEC's corners (docs/harness.md)");
  sub->add_flag("--verbose", a->verbose, "Dump the 8x8 blocks behind each mismatch");
  a->repro_dir_opt = declare_path(
      sub->add_option("--repro-dir", a->repro_dir,
                      "Existing folder for the reproducers of mismatches, one pxflow-repro-N per "
                      "run (default: the --json file's folder, else the working folder)")
          ->type_name("DIR"),
      PathKind::OutputFolder);
  sub->add_flag("--no-repro", a->no_repro,
                "Write no reproducers (the first differing stage is still named)");
  sub->add_option("--repro-seconds", a->repro_seconds,
                  "Time each backend's reproducer may spend shrinking its failing pair")
      ->check(CLI::Range(0.0, 3600.0))
      ->capture_default_str();
  add_progress_flag(*sub);
  sub->add_option("--case-timeout", a->case_timeout,
                  "Seconds a backend may take for one case before it is called hung (default: "
                  "an allowance scaled to the case's work and the backend's measured speed; "
                  "docs/harness.md, Isolation)")
      ->type_name("SECONDS")
      ->check(CLI::Range(0.001, 1e6));
  // Hidden: the worker mode of the check's own worker processes (hosts/harness/check_worker.hpp).
  sub->add_option(worker::kWorkerOption, a->worker_row)->group("");
  add_threads_option(*sub, a->backend_options.threads);
  add_device_option(*sub, a->backend_options.device);
  return {sub,
          [a, sub] {
            a->globals = global_options(*sub);
            a->worker_command = check_worker_command(*sub, a->backend_options);
            return run_check_command(*a);
          },
          kCheckExamples,
          {"--backends ref-original,ref-local --limits-only"},
          {"--backends ref-original,ref-local --cases 20000 --json {KEPT}.json"}};
}

}  // namespace pxflow::cli
