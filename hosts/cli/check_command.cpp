// pxflow check: the cross-check of every backend against ref-original.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "check.hpp"
#include "check_resume.hpp"
#include "check_worker.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "counted.hpp"
#include "device_wait.hpp"
#include "errors.hpp"
#include "input_file.hpp"
#include "json_document.hpp"
#include "list_option.hpp"
#include "output_plan.hpp"
#include "progress.hpp"
#include "shard_auto.hpp"

namespace pxflow::cli {
namespace {

constexpr const char* kHelp = " (see pxflow check --help)";

struct CheckArgs {
  std::string backend, backends, require, json_path, shard, repro_dir;
  std::string resume_path;  // --resume FILE: the stopped check to finish
  double repro_seconds = ShrinkLimits{}.seconds;
  bool no_repro = false;
  std::string data_dir = CorpusOptions{}.data_dir;
  std::uint64_t seed = 1;
  long cases = 0;
  double case_timeout = 0;
  std::string worker_row;  // the hidden --check-worker ROW: serve that row to a checking pxflow
  std::vector<std::string> worker_command;
  bool verbose = false, generated_only = false, limits_only = false;
  ParamOverride params;  // --profile, --set: the corpus at other parameters
  BackendOptions backend_options;
  std::string globals;  // the global options given (--dut, --disable-isa ...): they shape the run
  const CommandSpec* sub = nullptr;
};

// --backend NAME runs one backend, --backends LIST several: one meaning each, never both.
std::vector<std::string> chosen_backends(const CheckArgs& a) {
  const bool one = a.sub->count("--backend") > 0, list = a.sub->count("--backends") > 0;
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

// The command that reproduces this run, for the results file: with the shard it ran (`--shard
// auto` resolved), so that pxflow merge and a rerun see K/M.
std::string command_line(const CheckArgs& a, const Shard& shard) {
  std::string c = "pxflow" + a.globals + " check";
  if (a.sub->count("--backend") > 0) c += " --backend " + a.backend;
  if (a.sub->count("--backends") > 0) c += " --backends " + a.backends;
  if (!a.require.empty()) c += " --require " + a.require;
  if (a.cases > 0) c += " --cases " + std::to_string(a.cases);
  c += " --seed " + std::to_string(a.seed);
  if (a.sub->count("--shard") > 0) c += " --shard " + shard.text();
  if (a.generated_only) c += " --generated-only";
  if (a.limits_only) c += " --limits-only";
  if (!a.params.profile.empty()) c += " --profile " + shell_word(a.params.profile);
  for (const std::string& kv : a.params.sets) c += " --set " + shell_word(kv);
  if (a.sub->count("--data") > 0) c += " --data " + shell_word(a.data_dir);
  if (!a.backend_options.device.empty()) c += " --device " + shell_word(a.backend_options.device);
  if (a.backend_options.threads != 0)
    c += " --threads " + std::to_string(a.backend_options.threads);
  if (a.case_timeout > 0) c += " --case-timeout " + setting_text(a.case_timeout);
  if (!a.json_path.empty()) c += " --json " + shell_word(a.json_path);
  if (a.no_repro) c += " --no-repro";
  if (a.sub->count("--repro-dir") > 0) c += " --repro-dir " + shell_word(a.repro_dir);
  return c;
}

// Where reproducers go: --repro-dir, else the --json file's folder, else the working folder. The
// default is used only where files can be made (a check in a read-only folder still runs).
OutputFolder* plan_reproducers(const CheckArgs& a, const std::string& json_path, OutputPlan& plan) {
  if (a.no_repro) return nullptr;
  std::string dir = a.repro_dir;
  if (a.sub->count("--repro-dir") == 0) {
    const std::filesystem::path json(json_path);
    dir = json_path.empty() || json_path == kStdoutPath || !json.has_parent_path()
              ? "."
              : json.parent_path().string();
    if (::access(dir.c_str(), W_OK) != 0) return nullptr;
  }
  return &plan.folder("--repro-dir", dir, "pxflow-repro-N");
}

// The options of a new campaign, from the command line.
CheckOptions options_from_args(const CheckArgs& a) {
  CheckOptions o;
  o.backends = chosen_backends(a);
  o.require = split_list(a.require);
  o.fuzz_pairs = a.cases;
  std::string shard_source;  // with --shard auto: the engine and variables K/M came from
  if (a.sub->count("--shard") > 0 && a.shard == "auto") {
    const AutoShard found = shard_from_environment();
    o.shard = found.shard;
    shard_source = " (--shard auto: " + found.source + ")";
  } else if (a.sub->count("--shard") > 0) {
    o.shard = parse_shard("--shard", a.shard);
  }
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
  if (!a.params.empty() && a.limits_only)
    throw InputError(a.params.options().substr(1) +
                     " with --limits-only: the limit cases are each row's own limits and keep "
                     "their parameters; --profile and --set apply to the rest of the corpus" +
                     std::string(kHelp));
  a.params.check();
  o.corpus.params = a.params;
  o.command = command_line(a, o.shard);
  o.banner = "pxflow check: seed " + std::to_string(a.seed) +
             (a.cases > 0 ? ", fuzz campaign of " + std::to_string(a.cases) + " random pairs"
                          : ", fixed corpus") +
             (o.shard.count > 1 || !shard_source.empty() ? ", shard " + o.shard.text() : "") +
             shard_source;
  return o;
}

// With --resume, the options that shape no result; the campaign's come from the file.
constexpr std::string_view kResumeTakes[] = {"--resume",        "--json",    "--repro-dir",
                                             "--no-repro",      "--verbose", "--progress",
                                             "--repro-seconds", "--help"};

// The stopped check of --resume FILE, refused (one line, exit 2) unless this run can finish it.
CheckReport read_stopped_check(const CheckArgs& a, const BuildIdentity& built) {
  for (const OptionSpec& opt : a.sub->options)
    if (opt.count() > 0 && std::ranges::find(kResumeTakes, opt.name()) == std::end(kResumeTakes))
      throw InputError(
          opt.name() + " given with --resume: the campaign's options come from " +
          "the file (only --json, --repro-dir, --no-repro, --repro-seconds, --verbose " +
          "and --progress go with it)" + kHelp);
  const std::string label = "--resume " + a.resume_path;
  Json j;
  try {
    j = Json::parse(read_updated_text(label, a.resume_path));
  } catch (const Json::exception&) {
    throw InputError(label + ": not valid JSON (expected a file of pxflow check --json)");
  }
  CheckReport r;
  try {
    r = check_from_json(j);
  } catch (const InputError& e) {
    throw InputError(label + ": " + e.what());
  }
  if (!j.contains("options") && j.value("merged_from", Json()).is_null())
    throw InputError(label + ": has no \"options\": not a check file of this pxflow" + kHelp);
  check_resumable(label, r, built.version, built.commit);
  if (r.options.global_options != a.globals)
    throw InputError(label + ": ran with the global options '" + r.options.global_options +
                     "' (here '" + a.globals + "'): resume it as " +
                     shell_word(own_command_name()) + r.options.global_options +
                     " check --resume " + shell_word(a.resume_path));
  return r;
}

// The options of the stopped campaign `r`: the rest of it runs as its beginning ran.
CheckOptions options_from_file(const CheckArgs& a, const CheckReport& r) {
  CheckOptions o;
  o.backends = r.campaign.backends;
  o.require = r.campaign.require;
  o.fuzz_pairs = r.campaign.fuzz_pairs;
  o.shard = r.shard;
  o.backend_options = {r.options.threads, r.options.device};
  o.isolation = {check_worker_command(*a.sub, o.backend_options), r.options.case_timeout};
  o.corpus.seed = r.seed;
  o.corpus.data_dir = r.options.data_dir;
  o.corpus.limits_only = r.options.limits_only;
  o.corpus.real = !r.campaign.generated_only && !r.options.limits_only;
  o.corpus.params = r.options.params;
  o.command = r.command;
  o.resume = &r;
  o.resume_file = a.resume_path;
  o.banner = "pxflow check: resuming " + a.resume_path + " after " + std::to_string(r.cases) +
             " of " + counted(r.cases_total(), "case") + " (seed " + std::to_string(r.seed) + ")";
  return o;
}

// Where the result goes: --json, else (with --resume) back to the stopped check's file, which is
// then read first and replaced whole by the combined result.
std::string json_output(const CheckArgs& a) {
  return a.json_path.empty() && !a.resume_path.empty() ? a.resume_path : a.json_path;
}

// The line an interrupted check ends with (app.cpp prints it, exit 128 + the signal).
Interrupted stopped(const Interrupted& stop, const std::string& json_path) {
  const std::string where =
      json_path.empty() ? "nothing written (--json FILE keeps a stopped check's work)"
      : json_path == kStdoutPath
          ? "the JSON on standard output holds them"
          : json_path + " holds them; pxflow check --resume " + shell_word(json_path) + " goes on";
  return Interrupted(stop.signal, std::string(stop.what()) + "; " + where);
}

int run_check_command(const CheckArgs& a) {
  if (!a.worker_row.empty()) return worker::serve(a.worker_row, a.backend_options);
  const BuildIdentity built = build_identity();
  std::optional<CheckReport> before;
  if (!a.resume_path.empty()) before = read_stopped_check(a, built);
  CheckOptions o = before ? options_from_file(a, *before) : options_from_args(a);
  o.global_options = a.globals;
  o.verbose = a.verbose;
  o.pxflow_version = built.version;
  o.pxflow_commit = built.commit;
  const std::string json_path = json_output(a);
  const bool json_to_stdout = json_path == kStdoutPath;
  OutputPlan plan;
  if (o.corpus.real) plan.read_folder("--data", o.corpus.data_dir);
  std::error_code ec;  // the file resumed is an input, unless it is the one the result replaces
  if (before && !std::filesystem::equivalent(a.resume_path, json_path, ec))
    plan.read(a.resume_path);
  OutputFile* const json_file =
      json_path.empty() ? nullptr
                        : &plan.file(a.json_path.empty() ? "--resume" : "--json", json_path);
  OutputFolder* const repro = plan_reproducers(a, json_path, plan);
  plan.prepare();
  if (repro) {
    o.repro.dir = repro->dir();
    o.repro.write = [repro](const std::string& path, std::string_view bytes) {
      repro->write(path, bytes);
    };
    o.repro.make_folder = [repro](const std::string& path) { return repro->make_subfolder(path); };
  }
  o.repro.program = shell_word(own_command_name()) + a.globals;
  o.repro.limits.seconds = a.repro_seconds;
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
  if (json_file) json_file->write(json_document(check_json(r)));
  if (r.stop) throw stopped(*r.stop, json_path);
  return r.ok() || merge_judges ? 0 : 1;
}

// check's options, in the order its --help lists them, a function per group.

// Which backends run, and which must.
void add_row_options(CommandSpec& sub, CheckArgs& a) {
  add_backend_option(sub, a.backend, "the one to check");
  add_backends_option(sub, a.backends, "the ones to check");
  sub.add("--require", &a.require,
          "Backends that must run (comma-separated, or 'all': every row but those needing "
          "hardware this machine lacks, an ISA extension): their skips fail")
      .type("LIST|all");
}

// The campaign: its seed and size, the shard of it, its results file and resuming from it.
void add_campaign_options(CommandSpec& sub, CheckArgs& a) {
  add_seed_option(sub, a.seed, "printed; it reproduces any failure");
  sub.add("--cases", &a.cases, "Fuzz campaign: N random pairs instead of the fixed corpus")
      .in_range(1L, 100000000L);
  sub.add("--shard", &a.shard,
          "Run the K-th of M disjoint parts of the campaign (K/M, e.g. 2/4; "
          "`pxflow merge` combines the parts' --json files). auto: K and M "
          "from the CI engine's variables, the first set of GitLab "
          "parallel: (CI_NODE_INDEX/CI_NODE_TOTAL), a Kubernetes Indexed "
          "Job (JOB_COMPLETION_INDEX/PXFLOW_SHARD_TOTAL), a Slurm array "
          "(SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT); the --json file "
          "records the K/M found")
      .type("K/M|auto");
  add_json_option(sub, a.json_path,
                  "also written when a signal stops the check: what it checked, \"complete\": "
                  "false; --resume goes on from it");
  sub.add("--resume", &a.resume_path,
          "Finish the check a signal stopped, from its --json FILE: the "
          "cases not done, with the file's campaign and options; the "
          "result (the uninterrupted run's) replaces FILE, or goes to "
          "--json (docs/harness.md, Stopping and resuming a campaign)")
      .type("FILE")
      .path_kind(PathKind::UpdatedFile);
}

// Which cases of the corpus run, and at which parameters.
void add_corpus_options(CommandSpec& sub, CheckArgs& a) {
  add_data_option(sub, a.data_dir);
  sub.flag("--generated-only", a.generated_only,
           "Skip the real frames (random, hostile, threshold cases only)");
  sub.flag("--limits-only", a.limits_only,
           "Only the limit cases: each backend at the edges its unsupported() declares, and "
           "SPEC's corners (docs/harness.md)");
  std::string profiles;
  for (const auto& n : profile_names()) profiles += (profiles.empty() ? "" : ", ") + n;
  sub.add("--profile", &a.params.profile,
          "Run the corpus at this profile's parameters (" + profiles +
              "), each case at its own frame size; the limit cases keep theirs "
              "(default: each case's own parameters)")
      .type("NAME");
  sub.add("--set", &a.params.sets,
          "Run the corpus with one parameter overridden, KEY=VALUE (repeatable; every "
          "key of flow --set but width and height): e.g. --set search_radius=20. Cases "
          "whose frames are too small for it are left out, each named")
      .type("KEY=VALUE")
      .one_word_each();
}

// What a mismatch leaves behind: the blocks behind it, its reproducer.
void add_mismatch_options(CommandSpec& sub, CheckArgs& a) {
  sub.flag("--verbose", a.verbose, "Dump the 8x8 blocks behind each mismatch");
  sub.add("--repro-dir", &a.repro_dir,
          "Existing folder for the reproducers of mismatches, one pxflow-repro-N per "
          "run (default: the --json file's folder, else the working folder)")
      .type("DIR")
      .path_kind(PathKind::OutputFolder);
  sub.flag("--no-repro", a.no_repro,
           "Write no reproducers (the first differing stage is still named)");
  sub.add("--repro-seconds", &a.repro_seconds,
          "Time each backend's reproducer may spend shrinking its failing pair")
      .with_default()
      .real_in(0, 3600);
}

// How the backends run: progress, the hang timeout, the worker mode, threads and device.
void add_run_options(CommandSpec& sub, CheckArgs& a) {
  add_progress_flag(sub);
  sub.add("--case-timeout", &a.case_timeout,
          "Seconds a backend may take for one case before it is called hung (default: "
          "an allowance scaled to the case's work and the backend's measured speed; "
          "docs/harness.md, Isolation)")
      .type("SECONDS")
      .real_in(0.001, 1e6);
  // Hidden: the worker mode of the check's own worker processes
  // (hosts/harness/check/check_worker.hpp).
  sub.add(worker::kWorkerOption, &a.worker_row).unlisted();
  add_threads_option(sub, a.backend_options.threads);
  add_device_option(sub, a.backend_options.device);
}

}  // namespace

const std::vector<std::string> kCheckExamples = {
    "check  # every backend against ref-original, bit for bit",
    "check --dut ref=exec:pxflow-dut-ref --require ref  # a kernel outside pxflow",
    "check --backends m4-qemu --require m4-qemu  # the Cortex-M4 firmware under QEMU",
    "check --cases 10000 --seed 7 --shard 2/4 --json s2.json  # one quarter of a campaign",
    "check --cases 10000 --shard auto --json s.json  # a GitLab, Kubernetes or Slurm matrix's part",
    "check --resume ci.json  # finish a check a signal stopped (Ctrl-C: its --json file kept it)",
    "check --backends ref-original,avx2 --set search_radius=20  # the corpus at S = 20",
};

Command add_check_command(CommandSpec& app) {
  auto a = std::make_shared<CheckArgs>();
  CommandSpec* sub =
      &app.add_subcommand("check", "Check every backend against ref-original, bit for bit");
  add_row_options(*sub, *a);
  add_campaign_options(*sub, *a);
  add_corpus_options(*sub, *a);
  add_mismatch_options(*sub, *a);
  add_run_options(*sub, *a);
  return {sub,
          [a, sub] {
            a->sub = sub;
            a->globals = global_options(*sub);
            a->worker_command = check_worker_command(*sub, a->backend_options);
            return run_check_command(*a);
          },
          kCheckExamples,
          {"--backends ref-original,ref-local --limits-only"},
          {"--backends ref-original,ref-local --cases 20000 --json {KEPT}.json"}};
}

}  // namespace pxflow::cli
