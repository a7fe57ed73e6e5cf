// pxflow flow: one frame pair, or every consecutive pair of a sequence (a video, a folder or glob
// of frames, raw frames back to back, a list file of pairs), through one backend; the estimate
// as text, JSON (--json), JSON lines (--jsonl) or CSV (--csv), and pictures (--draw).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "counted.hpp"
#include "draw_flow.hpp"
#include "errors.hpp"
#include "estimate.hpp"
#include "flow_report.hpp"
#include "frame_io.hpp"
#include "frame_ops.hpp"
#include "frame_sequence.hpp"
#include "grid.hpp"
#include "interrupt.hpp"
#include "json_document.hpp"
#include "output_file.hpp"
#include "registry.hpp"

namespace pxflow::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct FlowOptions {
  ProblemOptions problem;
  std::string size, crop;
  int bin = 1;
  int max_pairs = 0;                        // 0 = all
  std::string backend = kReferenceBackend;  // the executable spec, and it counts its work
  BackendOptions backend_options;
  std::string json, jsonl, csv, draw, pairs;
  bool json_given = false, jsonl_given = false, csv_given = false, draw_given = false;
  bool pairs_given = false, progress = false;
  std::string first, second;  // PREV NEXT, or SOURCE
};

// One machine-readable output: a file (written whole at the end, atomically) or stdout (line by
// line, as the pairs finish).
struct Sink {
  bool on = false, to_stdout = false;
  std::string path, text;
  void add(const std::string& s) {
    if (!on) return;
    if (to_stdout) {
      std::fwrite(s.data(), 1, s.size(), stdout);
      std::fflush(stdout);
    } else {
      text += s;
    }
  }
  void finish() const {
    if (on && !to_stdout) write_output_file(path, text);
  }
};

Sink make_sink(bool given, const std::string& option, const std::string& path,
               std::span<const std::string> inputs) {
  Sink s;
  if (!given) return s;
  s.on = true, s.to_stdout = path == kStdoutPath, s.path = path;
  if (!s.to_stdout) check_output_path(option, path, inputs);
  return s;
}

// The backend opened for `p`, or one line saying why not; a problem it does not support (a
// frame too large for its memory) names the options that make the frames smaller.
std::unique_ptr<Backend> open_for(const BackendRow& row, const FlowOptions& o, const Params& p) {
  if (const std::string why = row.probe(); !why.empty())
    throw InputError("backend " + row.name + " cannot run here: " + why);
  std::unique_ptr<Backend> b = row.create(o.backend_options);
  if (const std::string why = b->unsupported(p); !why.empty())
    throw InputError("backend " + row.name + " does not support this problem: " + why +
                     "; make the frames smaller with --crop WxH+X+Y (a window) or --bin N (N x N "
                     "pixels averaged) (see pxflow flow --help)");
  return b;
}

class FlowRunner {
 public:
  FlowRunner(const FlowOptions& o, const BackendRow& row) : o_(o), row_(row) {}

  // Runs one pair; the first pair fixes the parameters and opens the backend.
  PairRun run(const NamedFrame& prev, const NamedFrame& next) {
    if (prev.frame.width != next.frame.width || prev.frame.height != next.frame.height)
      throw InputError("frames differ in size: " + prev.name + " is " + size_text(prev.frame) +
                       ", " + next.name + " is " + size_text(next.frame));
    if (!backend_) {
      params_ = o_.problem.resolve(std::pair{prev.frame.width, prev.frame.height});
      backend_ = open_for(row_, o_, params_);
      records_.resize(poi_count(params_));
    } else if (prev.frame.width != params_.width || prev.frame.height != params_.height) {
      throw InputError("frames differ in size: " + prev.name + " is " + size_text(prev.frame) +
                       ", the sequence's first frame " + std::to_string(params_.width) + "x" +
                       std::to_string(params_.height));
    }
    const FramePair pair{prev.frame.view(), next.frame.view()};
    check_batch({&pair, 1}, params_, records_);
    PairRun r;
    const auto t0 = Clock::now();
    backend_->run({&pair, 1}, params_, records_, r.counts);
    r.host_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    r.device_time = backend_->last_device_time();
    r.prev_name = prev.name, r.next_name = next.name;
    if (!o_.crop.empty()) parse_crop(o_.crop, r.shaping);
    r.shaping.bin = o_.bin;
    r.backend = row_.name, r.implementation = backend_->describe().implementation;
    r.device = device_or_host(backend_->describe());
    r.profile = o_.problem.profile;
    r.params = &params_;
    r.result = estimate_flow(records_, params_);
    r.records = records_;
    return r;
  }

 private:
  static std::string size_text(const Frame& f) {
    return std::to_string(f.width) + "x" + std::to_string(f.height);
  }
  const FlowOptions& o_;
  const BackendRow& row_;
  Params params_;
  std::unique_ptr<Backend> backend_;
  std::vector<PoiRecord> records_;
};

void draw_pair(const std::string& path, const NamedFrame& prev, const PairRun& r) {
  draw_flow(path, prev.frame.view(), *r.params, r.records, r.result, draw_caption(r));
}

// --json, --jsonl and --csv may not all claim standard output.
void check_stdout_claims(const FlowOptions& o) {
  int claims = 0;
  for (auto [given, path] :
       {std::pair{o.json_given, &o.json}, {o.jsonl_given, &o.jsonl}, {o.csv_given, &o.csv}})
    claims += given && *path == kStdoutPath;
  if (claims > 1)
    throw InputError("--json, --jsonl, --csv: only one of them can write to standard output (-)");
}

NamedFrame shaped(NamedFrame f, const FrameShaping& s) {
  if (s.any()) f.frame = shape_frame(f.frame, s);
  return f;
}

int run_single(const FlowOptions& o, const BackendRow& row, const FrameShaping& shaping,
               std::optional<FrameSize> raw_size) {
  const std::string inputs[] = {o.first, o.second};
  if (o.draw_given) check_draw_path(o.draw, inputs);
  Sink json = make_sink(o.json_given, "--json", o.json, inputs);
  Sink jsonl = make_sink(o.jsonl_given, "--jsonl", o.jsonl, inputs);
  Sink csv = make_sink(o.csv_given, "--csv", o.csv, inputs);
  const NamedFrame prev = shaped({o.first, load_frame(o.first, raw_size)}, shaping);
  const NamedFrame next = shaped({o.second, load_frame(o.second, raw_size)}, shaping);
  FlowRunner runner(o, row);
  const PairRun r = runner.run(prev, next);
  if (o.draw_given) draw_pair(o.draw, prev, r);
  const std::string object = json_document(pair_json(r), -1);
  json.add(object);
  jsonl.add(object);
  csv.add(csv_header() + csv_row(0, r));
  for (const Sink* s : {&json, &jsonl, &csv}) s->finish();
  const bool stdout_taken =
      (json.on && json.to_stdout) || (jsonl.on && jsonl.to_stdout) || (csv.on && csv.to_stdout);
  if (!stdout_taken) std::cout << pair_summary(r);
  return 0;
}

// Every consecutive pair of a sequence, or every pair of a list file.
int run_sequence(const FlowOptions& o, const BackendRow& row, const FrameShaping& shaping,
                 std::optional<FrameSize> raw_size) {
  if (o.json_given)
    throw InputError(
        "--json writes one pair's object; for a sequence use --jsonl FILE|- (one "
        "object per pair, the same keys) or --csv FILE|-");
  std::vector<std::pair<std::string, std::string>> list;
  std::unique_ptr<FrameSequence> sequence;
  std::vector<std::string> inputs;
  if (o.pairs_given) {
    list = read_pair_list(o.pairs);
    for (const auto& [a, b] : list) inputs.push_back(a), inputs.push_back(b);
  } else {
    sequence = open_frame_sequence(o.first, raw_size);
    inputs = sequence->files();
  }
  if (o.draw_given) {
    std::error_code ec;
    if (o.draw.empty() || !fs::is_directory(o.draw, ec))
      throw InputError("--draw " + o.draw +
                       ": for a sequence, --draw names an existing folder (one PNG per pair)");
  }
  Sink jsonl = make_sink(o.jsonl_given, "--jsonl", o.jsonl, inputs);
  Sink csv = make_sink(o.csv_given, "--csv", o.csv, inputs);
  csv.add(csv_header());
  const bool stdout_taken = (jsonl.on && jsonl.to_stdout) || (csv.on && csv.to_stdout);
  // Lines per pair: on stdout when it is free, else on stderr on a terminal or with --progress.
  std::FILE* lines = !stdout_taken ? stdout : (o.progress || ::isatty(2) == 1) ? stderr : nullptr;
  FlowRunner runner(o, row);
  const auto t0 = Clock::now();
  double backend_seconds = 0;
  int pairs = 0;
  std::string last_what;
  NamedFrame prev, next;
  bool have_prev = false;
  auto one_pair = [&](const NamedFrame& a, const NamedFrame& b) {
    stop_if_interrupted(counted(pairs, "pair") + " done");
    const PairRun r = runner.run(a, b);
    if (o.draw_given) {
      char name[32];
      std::snprintf(name, sizeof name, "pair-%06d.png", pairs);
      const std::string path = (fs::path(o.draw) / name).string();
      check_output_path("--draw", path, inputs);
      draw_pair(path, a, r);
    }
    jsonl.add(json_document(pair_json(r), -1));
    csv.add(csv_row(pairs, r));
    if (lines) std::fputs(pair_line(pairs, r).c_str(), lines);
    backend_seconds += r.host_seconds;
    last_what =
        r.backend +
        (r.implementation.empty() || r.implementation == r.backend ? ""
                                                                   : " -> " + r.implementation) +
        (r.device == "host" ? "" : " on " + r.device);
    ++pairs;
  };
  const auto more = [&] { return o.max_pairs == 0 || pairs < o.max_pairs; };
  if (o.pairs_given) {
    for (const auto& [a, b] : list)
      if (more())
        one_pair(shaped({a, load_frame(a, raw_size)}, shaping),
                 shaped({b, load_frame(b, raw_size)}, shaping));
  } else {
    while (more() && sequence->next(next)) {
      next = shaped(std::move(next), shaping);
      if (have_prev) one_pair(prev, next);
      prev = std::move(next), have_prev = true;
    }
    if (pairs == 0)
      throw InputError(o.first + ": holds " + std::string(have_prev ? "1 frame" : "no frame") +
                       "; a sequence needs at least 2");
  }
  jsonl.finish();
  csv.finish();
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%s (%s) in %.3f s: %.1f pairs/s with decoding, %.1f pairs/s in the "
                "backend (%.3f s, host steady_clock)\n",
                counted(pairs, "pair").c_str(),
                counted(o.pairs_given ? 2 * pairs : pairs + 1, "frame").c_str(), wall, pairs / wall,
                backend_seconds > 0 ? pairs / backend_seconds : 0.0, backend_seconds);
  std::FILE* summary = stdout_taken ? stderr : stdout;
  std::fprintf(summary, "flow: %s, %s: %s", last_what.c_str(), o.problem.profile.c_str(), buf);
  return 0;
}

int run_flow(const FlowOptions& o) {
  const BackendRow& row = find_backend(o.backend);  // unknown names fail before any work
  const BackendRow* const rows[] = {&row};
  check_device_option(rows, o.backend_options.device);
  check_stdout_claims(o);
  FrameShaping shaping;
  if (!o.crop.empty()) parse_crop(o.crop, shaping);
  shaping.bin = o.bin;
  std::optional<FrameSize> raw_size;
  if (!o.size.empty()) raw_size = parse_frame_size(o.size);
  const int positionals = !o.first.empty() + !o.second.empty();
  if (o.pairs_given && positionals > 0)
    throw InputError("--pairs " + o.pairs + ": give either a list of pairs or frames, not both");
  if (o.pairs_given || positionals == 1) return run_sequence(o, row, shaping, raw_size);
  if (positionals == 0)
    throw InputError("give PREV NEXT (one pair) or SOURCE (a sequence) (see pxflow flow --help)");
  return run_single(o, row, shaping, raw_size);
}

}  // namespace

Command add_flow_command(CLI::App& app) {
  auto o = std::make_shared<FlowOptions>();
  CLI::App* sub = app.add_subcommand(
      "flow",
      "Estimate the flow between two frames, or between every consecutive pair of a sequence");
  sub->footer(
      "Forms:\n"
      "  pxflow flow [OPTIONS] PREV NEXT     one pair\n"
      "  pxflow flow [OPTIONS] SOURCE        every consecutive pair of SOURCE: a video file\n"
      "                                      (OpenCV videoio), a folder of frames or a quoted\n"
      "                                      glob ('f/*.png'), both sorted by name, a file of raw\n"
      "                                      frames back to back (--size), or - (raw frames on\n"
      "                                      standard input, --size)\n"
      "  pxflow flow [OPTIONS] --pairs LIST  each line of LIST: PREV NEXT (relative to LIST)\n"
      "A sequence prints a line per pair and a summary (pairs, frames, pairs/s); --jsonl and\n"
      "--csv write one object or row per pair (- = stdout, the lines then go to stderr with\n"
      "--progress or on a terminal).");
  o->problem.add_to(*sub);
  sub->add_option("--size", o->size,
                  "Inputs are raw 8-bit frames of WIDTHxHEIGHT (e.g. 64x64), whatever their name");
  sub->add_option("--crop", o->crop,
                  "Use the window WxH+X+Y of every frame (e.g. 64x64+100+40), before --bin");
  sub->add_option("--bin", o->bin, "Average N x N pixels into one (after --crop)")
      ->check(CLI::Range(1, 64));
  sub->add_option("--backend", o->backend, "Backend to run (see `pxflow backends`)")
      ->capture_default_str();
  sub->add_option("--threads", o->backend_options.threads,
                  "Host worker threads of the CPU backends and the GAP8 model (0 = all cores)")
      ->check(CLI::Range(0, 1024));
  sub->add_option("--device", o->backend_options.device,
                  "Device index or name substring (GPU backends)");
  CLI::Option* json =
      sub->add_option("--json", o->json, "Write one JSON object (one pair) to FILE, - for stdout");
  CLI::Option* jsonl = sub->add_option(
      "--jsonl", o->jsonl, "Write one JSON object per pair, one per line, to FILE (- = stdout)");
  CLI::Option* csv =
      sub->add_option("--csv", o->csv, "Write one CSV row per pair to FILE (- = stdout)");
  CLI::Option* draw = sub->add_option(
      "--draw", o->draw,
      "Draw the POIs, their vectors and the frame flow into FILE.png (one pair) or into the "
      "folder DIR as pair-NNNNNN.png (a sequence)");
  CLI::Option* pairs =
      sub->add_option("--pairs", o->pairs, "A list file of pairs: PREV NEXT a line");
  sub->add_option("--max-pairs", o->max_pairs, "Stop a sequence after N pairs (0 = all)")
      ->check(CLI::Range(0, 100000000));
  sub->add_flag("--progress", o->progress,
                "A line per pair on stderr even when stdout is taken and stderr is no terminal");
  sub->add_option("PREV", o->first, "First frame (image file, or raw with --size), or SOURCE");
  sub->add_option("NEXT", o->second, "Second frame (same size)");
  return {sub, [o, json, jsonl, csv, draw, pairs] {
            o->json_given = json->count() > 0;
            o->jsonl_given = jsonl->count() > 0;
            o->csv_given = csv->count() > 0;
            o->draw_given = draw->count() > 0;
            o->pairs_given = pairs->count() > 0;
            return run_flow(*o);
          }};
}

}  // namespace pxflow::cli
