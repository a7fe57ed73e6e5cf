// pxflow report: runs (or reads) check and bench results and writes the report files.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

#include "accuracy_json.hpp"
#include "accuracy_run.hpp"
#include "bench.hpp"
#include "check.hpp"
#include "cli_extension.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "draw_flow.hpp"
#include "errors.hpp"
#include "estimate.hpp"
#include "grid.hpp"
#include "input_file.hpp"
#include "interrupt.hpp"
#include "json_document.hpp"
#include "list_option.hpp"
#include "output_plan.hpp"
#include "path_options.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "registry.hpp"
#include "report.hpp"
#include "sample_data.hpp"
#include "system_files.hpp"
#include "truth_pairs.hpp"

namespace pxflow::cli {
namespace {

struct ReportArgs {
  std::string out_dir, check_json, bench_json, backends, backend;
  std::vector<std::string> bench_files;  // --bench-json: the first is bench_json
  std::string data_dir = kSampleDataDir;
  std::uint64_t seed = 1;
  int threads = 0;  // check and bench (accuracy keeps its one thread, like for like with OpenCV)
  std::string device;
  bool quick = false, no_accuracy = false;
  std::vector<std::pair<CliExtension, bool>> extensions;  // each with its skip flag's value
  std::string command;                                    // as run (command_line.hpp)
  std::string globals;  // the global options given (--dut, --disable-isa ...), as typed
  std::vector<std::string> check_workers;  // the check's worker command (command_line.hpp)
  std::set<std::string> given;             // the report's own options given ("--seed", "--quick")

  // "pxflow --dut ... check": a command this report runs, with the global options that shape it.
  std::string pxflow(const std::string& subcommand) const {
    return "pxflow" + globals + " " + subcommand;
  }

  // The backend of the accuracy table and the flow pictures: --backend, else the default one.
  std::string picture_backend() const { return backend.empty() ? default_backend().name : backend; }
  BackendOptions backend_options() const { return {threads, device}; }
  // " --threads N --device D" as given, for the commands the report records.
  std::string shared_flags() const {
    return (threads ? " --threads " + std::to_string(threads) : std::string()) +
           (device.empty() ? std::string() : " --device " + shell_word(device));
  }
};

// The families' sections: each extension whose family has a row among the report's backends
// (all, when none are named), unless its skip flag was given.
void add_family_sections(ReportInputs& in, const ReportArgs& a) {
  const std::vector<std::string> names = split_list(a.backends);
  for (const auto& [e, skipped] : a.extensions) {
    if (!e.add_report_section || skipped) continue;
    bool wanted = names.empty();
    for (const std::string& n : names) wanted |= find_backend(n).family == e.family;
    if (wanted) e.add_report_section(in);
  }
}

accuracy::AccuracyOptions accuracy_options(const ReportArgs& a) {
  accuracy::AccuracyOptions o;
  o.backend = a.picture_backend();
  o.backend_options.device = a.device;
  o.data_dir = a.data_dir;
  if (a.quick) o.pairs = 40, o.video_pairs = 2;
  return o;
}

void add_accuracy(ReportInputs& in, const ReportArgs& a) {
  const accuracy::AccuracyOptions o = accuracy_options(a);
  in.accuracy_command = a.pxflow("accuracy") + " --backend " + o.backend +
                        (a.quick ? " --cases 40 --video-pairs 2" : "") +
                        (a.device.empty() ? "" : " --device " + shell_word(a.device)) +
                        (a.data_dir == kSampleDataDir ? "" : " --data " + shell_word(a.data_dir));
  std::cout << "== " << in.accuracy_command << "\n";
  in.measured_here.push_back("accuracy");
  const auto report = accuracy::run_accuracy(o);
  in.accuracy.push_back({"pairs", "pxflow setting", "against", "method", "frames", "with flow",
                         "mean error px", "p95 error px", "median us/frame"});
  auto fixed = [](double v, const char* f) {
    char b[32];
    std::snprintf(b, sizeof b, f, v);
    return std::string(b);
  };
  for (const auto& set : report.sets)
    for (const auto& r : set.rows) {
      in.accuracy.push_back(
          {set.set, set.setting, set.against, r.method, std::to_string(r.frames),
           std::to_string(r.valid), r.has_error ? fixed(r.mean_error, "%.3f") : "(reference)",
           r.has_error ? fixed(r.p95_error, "%.3f") : "(reference)", fixed(r.median_us, "%.0f")});
    }
  in.accuracy_rows = accuracy::accuracy_rows_json(report);
}

// The flow picture of each of accuracy::kVideos.
std::string picture_file(const std::string& video) { return "flow-" + video + ".png"; }

// Flow pictures of the real sequences: first two frames of each video at full size.
void add_pictures(ReportInputs& in, const ReportArgs& a, ReportOutputs& out) {
  const std::string backend = a.picture_backend();
  for (const char* video : accuracy::kVideos) {
    const auto pairs = accuracy::video_pairs(a.data_dir + "/" + video, 1);
    if (pairs.empty()) continue;
    const auto& vp = pairs.front();
    const Params p = accuracy::video_setting(vp.prev.width, vp.prev.height);
    auto b = open_backend_for(find_backend(backend), a.backend_options(), p);
    const FramePair pair{vp.prev.view(), vp.next.view()};
    std::vector<PoiRecord> records(poi_count(p));
    OpCounts counts;
    b->run({&pair, 1}, p, records, counts);
    const std::string file = picture_file(video);
    out.pictures.at(file)->write(flow_png(pair.prev, p, records, estimate_flow(records, p),
                                          {vp.name, backend, accuracy::video_setting_name(p)}));
    in.pictures.push_back({vp.name + ": POIs and vectors by status (" + backend + ", " +
                               accuracy::video_setting_name(p) + "), frame flow in cyan",
                           file});
  }
}

// A results file of `pxflow check --json` (kind "check") or `pxflow bench --json` ("bench"),
// checked for the keys the report reads before any work: the wrong or a malformed file is one
// line and exit 2, never an internal error half-way through.
Json read_json(const std::string& option, const std::string& path, const char* kind) {
  const std::string text = read_input_text(option + " " + path, path);
  Json j;
  try {
    j = Json::parse(text);
  } catch (const std::exception&) {
    throw InputError(option + " " + path + ": not valid JSON (expected the output of pxflow " +
                     kind + " --json)");
  }
  const bool is_check = j.is_object() && j.contains("backends") && j["backends"].is_array() &&
                        j.contains("passed") && j.contains("failed");
  const bool is_bench = j.is_object() && j.contains("rows") && j["rows"].is_array();
  if (std::string(kind) == "check" ? !is_check : !is_bench)
    throw InputError(option + " " + path + ": not the output of pxflow " + kind + " --json" +
                     (is_check   ? " (it is a check file)"
                      : is_bench ? " (it is a bench file)"
                                 : ""));
  try {  // every field the report reads, with its type
    if (is_check)
      for (const auto& b : j["backends"]) {
        (void)b.at("backend").get<std::string>(), (void)b.at("state").get<std::string>();
        (void)b.at("passed").get<long>(), (void)b.at("failed").get<long>();
      }
    else
      for (const auto& r : j["rows"]) (void)r.at("backend").get<std::string>();
  } catch (const std::exception& e) {
    throw InputError(option + " " + path + ": a malformed " + kind + " file (" + e.what() + ")");
  }
  if (is_bench) {  // keys older bench files lack, so that results.json keeps its schema
    if (!j.contains("backends") || !j["backends"].is_array()) j["backends"] = Json::array();
    if (!j.contains("command")) j["command"] = nullptr;
    for (auto& r : j["rows"])
      if (!r.contains("exact_clock")) r["exact_clock"] = false;
  }
  return j;
}

// The command a results file records ("command", written by pxflow bench and check), or what is
// known: the file it was read from.
std::string recorded_command(const Json& j, const char* kind, const std::string& path) {
  if (j.contains("command") && j["command"].is_string() && !j["command"].get<std::string>().empty())
    return j["command"].get<std::string>() + " (read from " + path + ")";
  return std::string("read from ") + path + "; the pxflow " + kind +
         " command that wrote it is not recorded in the file";
}

// What each backend of the report runs: the bench's own descriptions (what it opened), else the
// rows of the check opened here for their description.
void describe_opened_backends(ReportInputs& in, const ReportArgs& a) {
  // The bench file's (A's) machine, never this one's, when the bench was read from a file.
  const std::string bench_from = in.bench_files.empty()
                                     ? std::string("this report's bench, on this machine")
                                     : "bench file " + in.bench_files.front().label + " (" +
                                           in.bench_files.front().path + "), on " +
                                           file_machine(in.bench_files.front());
  if (!in.bench.is_null() && in.bench.contains("backends") && in.bench["backends"].is_array() &&
      !in.bench["backends"].empty()) {
    in.backends = in.bench["backends"];
    in.backends_source = "As " + bench_from +
                         ", opened each backend (all threads). Device and driver strings come "
                         "from the backends themselves (OpenCL platform and driver versions, "
                         "Vulkan driver properties, the GAP8 model's source trees).";
    return;
  }
  std::vector<std::string> names = split_list(a.backends);
  if (names.empty() && !in.check.is_null())
    for (const auto& b : in.check["backends"]) names.push_back(b.value("backend", ""));
  for (const BackendRow& row : backend_rows()) {
    if (std::find(names.begin(), names.end(), row.name) == names.end()) continue;
    OpenedBackend opened = open_backend(row, a.backend_options());
    if (opened.backend) in.backends.push_back(describe_backend(row.name, *opened.backend));
  }
  in.backends_source =
      in.bench_files.empty()
          ? "The bench results do not describe the backends, so this report opened the rows it "
            "knows on this machine to describe them."
          : "The bench file does not describe its backends, so this report opened the rows it "
            "knows on this machine to describe them; what " +
                bench_from + ", ran may differ.";
}

// What the descriptions above leave out of the check's backends that ran (a --dut row the bench
// did not run, or one this report was not given): as the check file records it.
void describe_check_backends(ReportInputs& in) {
  if (in.check.is_null()) return;
  std::set<std::string> described;
  for (const auto& b : in.backends) described.insert(b.value("backend", ""));
  bool added = false;
  for (const auto& b : in.check["backends"]) {
    const std::string name = b.value("backend", "");
    Json d{{"backend", name}};
    for (const char* key : {"implementation", "device"})
      if (!b.value(key, "").empty()) d[key] = b[key];
    if (described.contains(name) || d.size() == 1) continue;  // described, or never opened
    in.backends.push_back(d);
    added = true;
  }
  if (added)
    in.backends_source +=
        " Rows only the check ran are described as the check file records them (implementation "
        "and device).";
}

void describe_backends(ReportInputs& in, const ReportArgs& a) {
  describe_opened_backends(in, a);
  describe_check_backends(in);
}

// The parts of the work a report may run; --check-json, --bench-json and --no-accuracy leave
// some out.
enum Part { kCheck = 1, kBench = 2, kAccuracy = 4 };

// Each option that shapes only some parts: with none of them running it would do nothing, so it
// is refused like a wrong value, before any work.
struct Shaping {
  const char* option;
  int parts;
  const char* what;
};
constexpr Shaping kShapings[] = {
    {"--seed", kCheck, "the check's pairs"},  // the accuracy table keeps its own seed
    {"--threads", kCheck | kBench, "the check and the bench"},
    {"--device", kCheck | kBench | kAccuracy, "the check, the bench and the accuracy table"},
    {"--backend", kAccuracy, "the accuracy table and the flow pictures"},
    {"--quick", kBench | kAccuracy, "the bench and the accuracy table"},
    {"--data", kCheck | kAccuracy, "the check, the accuracy table and the flow pictures"},
};

void refuse_options_without_effect(const ReportArgs& a) {
  const int runs = (a.check_json.empty() ? kCheck : 0) | (a.bench_json.empty() ? kBench : 0) |
                   (a.no_accuracy ? 0 : kAccuracy);
  for (const Shaping& s : kShapings) {
    if (!a.given.contains(s.option) || (s.parts & runs) != 0) continue;
    std::string why;
    for (auto [part, option] : {std::pair{kCheck, "--check-json"},
                                {kBench, "--bench-json"},
                                {kAccuracy, "--no-accuracy"}})
      if (s.parts & part) why += (why.empty() ? "" : " and ") + std::string(option);
    throw InputError(std::string(s.option) + ": has no effect with " + why + ": it shapes only " +
                     s.what + "; leave it out (see pxflow report --help)");
  }
}

// Every name and option checked, and the files given read, before any work: a wrong file or
// name is refused before minutes of work.
void read_given_results(ReportInputs& in, const ReportArgs& a) {
  for (const std::string& name : split_list(a.backends)) (void)find_backend(name);
  if (!a.backend.empty()) (void)find_backend(a.backend);
  refuse_options_without_effect(a);
  if (!a.check_json.empty()) in.check = read_json("--check-json", a.check_json, "check");
  for (const std::string& path : a.bench_files) {  // several: compared with the first
    Json j = read_json("--bench-json", path, "bench");
    check_bench_file("--bench-json " + path, j);
    if (in.bench.is_null()) in.bench = j;
    in.bench_files.push_back({path, file_label(in.bench_files.size()), std::move(j)});
  }
  // The accuracy table's and the pictures' backend runs last: one it cannot run is refused now.
  if (!a.no_accuracy) accuracy::require_backend_runs(accuracy_options(a));
}

// A stopped report keeps the check it ran here in its folder, and the next `report --out` with
// the same check reuses it (complete) or finishes it (stopped in the check); a report that
// completes removes it (its results.json holds the check).
constexpr const char* kKeptCheck = "check.json";

// The report's folder and files, planned and prepared in `plan` before any work: a folder or
// file that cannot be made fails first.
ReportOutputs plan_report_outputs(OutputPlan& plan, const ReportArgs& a) {
  plan.read_all({a.check_json});
  plan.read_all(a.bench_files);
  if (a.check_json.empty() || !a.no_accuracy) plan.read_folder("--data", a.data_dir);
  // The files written besides report_file_names(): planned even with --no-accuracy (a previous
  // report's pictures go) and without a stop (a kept check goes).
  std::vector<std::string> pictures{kKeptCheck};
  for (const char* video : accuracy::kVideos) pictures.push_back(picture_file(video));
  ReportOutputs out = plan_report(plan, a.out_dir, pictures);
  plan.prepare();
  return out;
}

std::string backends_flag(const ReportArgs& a) {
  return a.backends.empty() ? "" : " --backends " + a.backends;
}

// The check a stopped report kept in the folder, when it is this report's check (the same
// command and build); anything else there is set aside with a line, and the check runs anew.
std::optional<CheckReport> kept_check(const ReportArgs& a, const std::string& command) {
  const std::string path = (std::filesystem::path(a.out_dir) / kKeptCheck).string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  CheckReport r;
  try {
    // The report's own file in its own folder: read back, not an input (the run replaces it).
    r = check_from_json(Json::parse(read_own_output(path)));
  } catch (const std::exception& e) {
    std::cout << "== " << path << ": not a check file (" << e.what() << "): checked anew\n";
    return std::nullopt;
  }
  const BuildIdentity built = build_identity();
  if (r.command != command || r.pxflow_version != built.version ||
      r.pxflow_commit != built.commit || !r.merged_from.empty()) {
    std::cout << "== " << path << ": another check (" << r.command << ", pxflow "
              << r.pxflow_version << "): checked anew\n";
    return std::nullopt;
  }
  return r;
}

// The check: read from --check-json, or run here with the report's options (reusing or
// finishing the check a stopped report kept). A signal that stops it throws Interrupted, with
// in.check holding what was checked.
void add_check(ReportInputs& in, const ReportArgs& a) {
  if (!a.check_json.empty()) {
    in.check_command = recorded_command(in.check, "check", a.check_json);
    return;
  }
  CheckOptions o;
  o.backends = split_list(a.backends);
  o.corpus.seed = a.seed;
  o.corpus.data_dir = a.data_dir;
  o.backend_options = a.backend_options();
  o.isolation.worker_command = a.check_workers;
  o.global_options = a.globals;
  const BuildIdentity built = build_identity();
  o.pxflow_version = built.version, o.pxflow_commit = built.commit;
  in.check_command = a.pxflow("check") + " --seed " + std::to_string(a.seed) + backends_flag(a) +
                     a.shared_flags() +
                     (a.data_dir == kSampleDataDir ? "" : " --data " + shell_word(a.data_dir));
  o.command = in.check_command;
  in.measured_here.push_back("check");
  const std::optional<CheckReport> kept = kept_check(a, o.command);
  const std::string kept_path = (std::filesystem::path(a.out_dir) / kKeptCheck).string();
  if (kept && kept->complete) {
    std::cout << "== " << in.check_command << ": reusing " << kept_path
              << ", a stopped report's complete check\n";
    in.check = check_json(*kept);
    return;
  }
  if (kept) o.resume = &*kept, o.resume_file = kept_path;
  std::cout << "== " << in.check_command
            << (kept ? " (resuming " + kept_path + " after " + std::to_string(kept->cases) +
                           " cases)"
                     : "")
            << "\n";
  const CheckReport r = run_check(o, std::cout);
  std::cout << r.passed << " passed, " << r.failed << " failed, " << r.skipped << " skipped\n";
  in.check = check_json(r);
  if (r.stop) throw *r.stop;
}

// The bench: read from --bench-json, or run here with its own default profile and sweeps, so
// that the recorded command reruns them.
void add_bench(ReportInputs& in, const ReportArgs& a) {
  if (!a.bench_json.empty()) {
    in.bench_command = recorded_command(in.bench, "bench", a.bench_json);
    return;
  }
  BenchOptions o;
  o.backends = split_list(a.backends);
  o.backend_options = a.backend_options();
  const Params base = profile(kDefaultProfile);
  o.points = a.quick ? quick_bench_points(base, std::string(kDefaultProfile))
                     : default_bench_points(base, std::string(kDefaultProfile));
  set_sweep_threads(o.points, a.threads);
  if (a.quick) o.min_seconds = kQuickMinSeconds;
  in.bench_command = a.pxflow("bench") + backends_flag(a) +
                     (a.device.empty() ? "" : " --device " + shell_word(a.device)) +
                     (a.threads ? " --threads " + std::to_string(a.threads) : "") +
                     (a.quick ? " --quick" : "");
  std::cout << "== " << in.bench_command << "\n";
  in.measured_here.push_back("bench");
  BenchReport r = run_bench(o, std::cout);
  if (r.stop) throw *r.stop;  // the report's bench is not kept: it reruns whole
  r.command = in.bench_command;
  in.bench = bench_json(r);
}

// A signal stopped the report's work: the check it ran here is kept in the folder (with the
// manifest that keeps the folder the report's), and the line says how to go on.
Interrupted keep_check(ReportOutputs& out, const ReportInputs& in, const ReportArgs& a,
                       const Interrupted& stop) {
  if (!a.check_json.empty() || in.check.is_null()) return stop;
  out.pictures.at(kKeptCheck)->write(json_document(in.check));
  write_stopped_manifest(out, {kKeptCheck});
  const std::string path = (std::filesystem::path(a.out_dir) / kKeptCheck).string();
  return Interrupted(stop.signal, std::string(stop.what()) + "; " + path + " keeps the check (" +
                                      (in.check.value("complete", true) ? "complete" : "stopped") +
                                      "): pxflow report --out " + shell_word(a.out_dir) +
                                      " goes on from it");
}

// As `pxflow check` and `pxflow merge`: a failure, an incomplete merge or a check that compared
// nothing is not green (a check file older than its "verdict" key: the first and the last).
int report_exit_code(const Json& check) {
  std::string verdict = check.value("verdict", "");
  if (verdict.empty())
    verdict = check.value("failed", 0) > 0      ? "failed"
              : check.value("compared", 0) == 0 ? "nothing-checked"
                                                : "passed";
  if (verdict == "nothing-checked")
    std::cout << "the check compared nothing but the reference: the report is not a pass\n";
  if (verdict == "incomplete")
    std::cout << (check.value("complete", true)
                      ? "the check is an incomplete merge (see Conformance): the report is not a "
                        "pass\n"
                      : "the check was stopped before its end (see Conformance; pxflow check "
                        "--resume finishes it): the report is not a pass\n");
  return verdict == "passed" ? 0 : 1;
}

int run_report(const ReportArgs& a) {
  ReportInputs in;
  in.report_command = a.command;
  read_given_results(in, a);
  OutputPlan plan;
  ReportOutputs out = plan_report_outputs(plan, a);
  try {
    add_check(in, a);
    add_bench(in, a);
    describe_backends(in, a);
    if (!a.no_accuracy) add_accuracy(in, a);
    add_family_sections(in, a);
    for (const auto& s : in.sections) in.measured_here.push_back(s.key);
    stop_if_interrupted("the report's measurements, before any report file was written");
  } catch (const Interrupted& e) {
    throw keep_check(out, in, a, e);
  }
  if (!a.no_accuracy) add_pictures(in, a, out);
  write_report(out, in);
  std::cout << "wrote " << a.out_dir << "/report.md, report.html, results.json and CSV files\n";
  return report_exit_code(in.check);
}

}  // namespace

const std::vector<std::string> kReportExamples = {
    "report --out out/report  # report.md, report.html, results.json and results.csv",
};

Command add_report_command(CommandSpec& app) {
  auto a = std::make_shared<ReportArgs>();
  CommandSpec* sub =
      &app.add_subcommand("report", "Write report.md, report.html, results.json and results.csv");
  sub->add("--out", &a->out_dir, "Folder to write the report into")
      .needed()
      .type("DIR")
      .path_kind(PathKind::OwnedFolder);
  sub->add("--check-json", &a->check_json,
           "Use this `pxflow check --json` file instead of running the check")
      .type("FILE")
      .path_kind(PathKind::InputFile);
  sub->add("--bench-json", &a->bench_files,
           "Use this `pxflow bench --json` file instead of running the bench; more "
           "than one: the report also compares them with the first (pxflow compare)")
      .type("FILE")
      .path_kind(PathKind::InputFile);
  add_backends_option(*sub, a->backends, "of the check, the bench and the family sections");
  add_backend_option(*sub, a->backend, "of the accuracy table and the flow pictures");
  add_threads_option(*sub, a->threads,
                     "of the check and of the bench's default sweeps (the thread sweep still "
                     "runs its own)");
  add_device_option(*sub, a->device);
  add_data_option(*sub, a->data_dir, "for the check, the accuracy table and the pictures");
  add_seed_option(*sub, a->seed, "of the check's random pairs");
  sub->flag("--quick", a->quick,
            "A shorter bench (batch <= 256, no radius or thread sweeps) and accuracy run");
  sub->flag("--no-accuracy", a->no_accuracy, "Leave out the accuracy table and flow pictures");
  add_progress_flag(*sub);
  for (const CliExtension& e : registered_cli_extensions()) a->extensions.push_back({e, false});
  for (auto& [e, skipped] : a->extensions)
    if (e.add_report_section && !e.report_skip_flag.empty())
      sub->flag(e.report_skip_flag, skipped, e.report_skip_help);
  return {sub,
          [a, sub] {
            a->bench_json = a->bench_files.empty() ? "" : a->bench_files.front();
            a->command = given_command_line(*sub);
            a->globals = global_options(*sub);
            a->check_workers = check_worker_command(*sub, a->backend_options());
            for (const OptionSpec& o : sub->options)
              if (o.count() > 0) a->given.insert(o.name());
            return run_report(*a);
          },
          kReportExamples,
          {"--check-json {CHECK} --bench-json {BENCH} --no-accuracy --backends "
           "ref-original,ref-local"},
          {"--out {OUT} --backends ref-original,ref-local --no-accuracy"}};
}

}  // namespace pxflow::cli
