// pxflow flow: one frame pair, or every consecutive pair of a sequence (a video, a folder or glob
// of frames, raw frames back to back, a list file of pairs), through one backend; the estimate
// as text, JSON (--json), JSON lines (--jsonl) or CSV (--csv), and pictures (--draw).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

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
#include "output_plan.hpp"
#include "path_options.hpp"
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
  // `sizes_may_change`: each pair is its own problem (--pairs), so a pair of another size
  // resolves the parameters again and reopens the backend; in a sequence the first frame's size
  // holds for every frame.
  FlowRunner(const FlowOptions& o, const BackendRow& row, bool sizes_may_change)
      : o_(o), row_(row), sizes_may_change_(sizes_may_change) {}

  // Runs one pair; the first pair (and, with sizes_may_change, a pair of a new size) fixes the
  // parameters and opens the backend.
  PairRun run(const NamedFrame& prev, const NamedFrame& next) {
    if (prev.frame.width != next.frame.width || prev.frame.height != next.frame.height)
      throw InputError("frames differ in size: " + prev.name + " is " + size_text(prev.frame) +
                       ", " + next.name + " is " + size_text(next.frame));
    const bool new_size =
        !backend_ || prev.frame.width != params_.width || prev.frame.height != params_.height;
    if (new_size && backend_ && !sizes_may_change_)
      throw InputError("frames differ in size: " + prev.name + " is " + size_text(prev.frame) +
                       ", the sequence's first frame " + std::to_string(params_.width) + "x" +
                       std::to_string(params_.height));
    if (new_size) {
      params_ = o_.problem.resolve(std::pair{prev.frame.width, prev.frame.height});
      backend_.reset();  // one backend open at a time (a device's memory)
      backend_ = open_for(row_, o_, params_);
      records_.resize(poi_count(params_));
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
  bool sizes_may_change_;
  Params params_;
  std::unique_ptr<Backend> backend_;
  std::vector<PoiRecord> records_;
};

std::string picture(const NamedFrame& prev, const PairRun& r) {
  return flow_png(prev.frame.view(), *r.params, r.records, r.result, draw_caption(r));
}

NamedFrame shaped(NamedFrame f, const FrameShaping& s) {
  if (s.any()) f.frame = shape_frame(f.frame, s);
  return f;
}

int run_single(const FlowOptions& o, const BackendRow& row, const FrameShaping& shaping,
               std::optional<FrameSize> raw_size) {
  OutputPlan plan;
  plan.read_all({o.first, o.second});
  auto planned = [&](bool given, const char* option, const std::string& path) {
    return given ? &plan.file(option, path) : nullptr;
  };
  if (o.draw_given) check_png_name("--draw", o.draw);
  OutputFile* const draw = planned(o.draw_given, "--draw", o.draw);
  OutputFile* const json = planned(o.json_given, "--json", o.json);
  OutputFile* const jsonl = planned(o.jsonl_given, "--jsonl", o.jsonl);
  OutputFile* const csv = planned(o.csv_given, "--csv", o.csv);
  plan.prepare();
  const NamedFrame prev = shaped({o.first, load_frame(o.first, raw_size)}, shaping);
  const NamedFrame next = shaped({o.second, load_frame(o.second, raw_size)}, shaping);
  FlowRunner runner(o, row, false);
  const PairRun r = runner.run(prev, next);
  if (draw) draw->write(picture(prev, r));
  const std::string object = json_document(pair_json(r), -1);
  if (json) json->write(object);
  if (jsonl) jsonl->write(object);
  if (csv) csv->write(csv_header() + csv_row(0, r));
  bool stdout_taken = false;
  for (const OutputFile* f : {json, jsonl, csv}) stdout_taken |= f && f->to_stdout();
  if (!stdout_taken) std::cout << pair_summary(r);
  return 0;
}

// What a sequence that stopped early (a signal, EPIPE, a bad frame, a failed backend) kept: each
// stream in `kept` holds every completed pair and ends in its incomplete marker (OutputStream),
// and the summary says the run is incomplete.
void say_incomplete(int pairs, const std::vector<const OutputStream*>& kept) {
  std::string where;
  for (const OutputStream* s : kept)
    if (!s->to_stdout())
      where += (where.empty() ? "" : ", ") + s->option() + " " + s->path() + " (marked incomplete)";
  if (!where.empty()) where = "; kept " + counted(kept.front()->records(), "pair") + " in " + where;
  std::fprintf(stderr, "flow: incomplete: %d pair%s done before the stop%s\n", pairs,
               pairs == 1 ? "" : "s", where.c_str());
}

// What ended a run early, for the marker's "stopped_by" (io/output_plan.hpp).
std::string stop_reason(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const Interrupted& i) {
    return signal_name(i.signal);
  } catch (const InputError&) {
    return "bad input";
  } catch (const OutputError&) {
    return "write error";
  } catch (const BackendError&) {
    return "backend error";
  } catch (...) {
    return "error";
  }
}

// What a sequence run reads: the pairs of a list file (--pairs), or a sequence's frames.
struct SequenceSource {
  std::vector<std::pair<std::string, std::string>> list;
  std::unique_ptr<FrameSequence> sequence;
  std::vector<std::string> inputs;  // every file read, for the output plan
};

SequenceSource open_source(const FlowOptions& o, std::optional<FrameSize> raw_size) {
  SequenceSource src;
  if (o.pairs_given) {
    src.list = read_pair_list("--pairs", o.pairs);
    for (const auto& [a, b] : src.list) src.inputs.push_back(a), src.inputs.push_back(b);
  } else {
    src.sequence = open_frame_sequence(o.first, raw_size);
    src.inputs = src.sequence->files();
  }
  return src;
}

// Where a sequence's results go, planned before any work.
struct SequenceOutputs {
  OutputStream* jsonl = nullptr;
  OutputStream* csv = nullptr;
  OutputFolder* draw = nullptr;
  bool stdout_taken = false;   // by --jsonl - or --csv -
  std::FILE* lines = nullptr;  // the line per pair, or nowhere
};

SequenceOutputs plan_sequence_outputs(OutputPlan& plan, const FlowOptions& o) {
  SequenceOutputs out;
  out.jsonl = o.jsonl_given ? &plan.stream("--jsonl", o.jsonl) : nullptr;
  out.csv = o.csv_given ? &plan.stream("--csv", o.csv, StreamFormat::csv) : nullptr;
  out.draw = o.draw_given ? &plan.folder("--draw", o.draw, "pair-NNNNNN.png") : nullptr;
  plan.prepare();
  if (out.csv) out.csv->header(csv_header());
  out.stdout_taken = (out.jsonl && out.jsonl->to_stdout()) || (out.csv && out.csv->to_stdout());
  // Lines per pair: on stdout when it is free, else on stderr on a terminal or with --progress.
  out.lines = !out.stdout_taken ? stdout : (o.progress || ::isatty(2) == 1) ? stderr : nullptr;
  return out;
}

// Runs the pairs one by one into the outputs, and keeps the tallies of the summary.
class SequenceRun {
 public:
  SequenceRun(const FlowOptions& o, const BackendRow& row, const SequenceOutputs& out)
      : runner_(o, row, o.pairs_given), out_(out), max_pairs_(o.max_pairs) {}

  bool wants_more() const { return max_pairs_ == 0 || pairs_ < max_pairs_; }

  void pair(const NamedFrame& a, const NamedFrame& b) {
    stop_if_interrupted(counted(pairs_, "pair") + " done");
    const PairRun r = runner_.run(a, b);
    if (out_.draw) {
      char name[32];
      std::snprintf(name, sizeof name, "pair-%06d.png", pairs_);
      out_.draw->write(name, picture(a, r));
    }
    if (out_.jsonl) out_.jsonl->add(json_document(pair_json(r), -1));
    if (out_.csv) out_.csv->add(csv_row(pairs_, r));
    backend_seconds_ += r.host_seconds;
    last_what_ = what_ran(r);
    ++pairs_;  // done: in every output (its line is not an output a stop could keep)
    if (out_.lines) std::fputs(pair_line(pairs_ - 1, r).c_str(), out_.lines);
    if (out_.lines == stdout) check_stdout();  // a reader that went away stops the run now
  }

  int pairs() const { return pairs_; }
  double backend_seconds() const { return backend_seconds_; }
  const std::string& last_what() const { return last_what_; }

 private:
  FlowRunner runner_;
  const SequenceOutputs& out_;
  int max_pairs_;
  int pairs_ = 0;
  double backend_seconds_ = 0;
  std::string last_what_;
};

// Every pair of the list, or every consecutive pair of the sequence (at least one).
void run_pairs(SequenceSource& src, const FlowOptions& o, const FrameShaping& shaping,
               std::optional<FrameSize> raw_size, SequenceRun& run) {
  if (o.pairs_given) {
    for (const auto& [a, b] : src.list)
      if (run.wants_more())
        run.pair(shaped({a, load_frame(a, raw_size)}, shaping),
                 shaped({b, load_frame(b, raw_size)}, shaping));
    return;
  }
  NamedFrame prev, next;
  bool have_prev = false;
  while (run.wants_more() && src.sequence->next(next)) {
    next = shaped(std::move(next), shaping);
    if (have_prev) run.pair(prev, next);
    prev = std::move(next), have_prev = true;
  }
  if (run.pairs() == 0)
    throw InputError(o.first + ": holds " + std::string(have_prev ? "1 frame" : "no frame") +
                     "; a sequence needs at least 2");
}

// The last line: pairs, frames, wall time and the backend's share, on stdout when it is free.
void print_summary(const FlowOptions& o, const SequenceRun& run, const SequenceOutputs& out,
                   double wall) {
  const int pairs = run.pairs();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%s (%s) in %.3f s: %.1f pairs/s with decoding, %.1f pairs/s in the "
                "backend (%.3f s, host steady_clock)\n",
                counted(pairs, "pair").c_str(),
                counted(o.pairs_given ? 2 * pairs : pairs + 1, "frame").c_str(), wall, pairs / wall,
                run.backend_seconds() > 0 ? pairs / run.backend_seconds() : 0.0,
                run.backend_seconds());
  std::FILE* summary = out.stdout_taken ? stderr : stdout;
  std::fprintf(summary, "flow: %s, %s: %s", run.last_what().c_str(), o.problem.profile.c_str(),
               buf);
}

// Every consecutive pair of a sequence, or every pair of a list file.
int run_sequence(const FlowOptions& o, const BackendRow& row, const FrameShaping& shaping,
                 std::optional<FrameSize> raw_size) {
  if (o.json_given)
    throw InputError(
        "--json writes one pair's object; for a sequence use --jsonl FILE|- (one "
        "object per pair, the same keys) or --csv FILE|-");
  SequenceSource src = open_source(o, raw_size);
  OutputPlan plan;
  plan.read_all(src.inputs);
  const SequenceOutputs out = plan_sequence_outputs(plan, o);
  SequenceRun run(o, row, out);
  const auto t0 = Clock::now();
  try {
    run_pairs(src, o, shaping, raw_size, run);
    // A signal that ended the source early (Ctrl-C reaches `cat ... |` too) is a stop as well.
    stop_if_interrupted(std::to_string(run.pairs()) + " pairs done");
  } catch (...) {
    if (out.draw) out.draw->remove_earlier();
    // Every stream that holds pairs is kept, cut to its last one and marked incomplete; one
    // whose write failed is not (its previous file stays).
    const std::string why = stop_reason(std::current_exception());
    std::vector<const OutputStream*> kept;
    for (OutputStream* s : {out.jsonl, out.csv})
      if (s && s->stop(why)) kept.push_back(s);
    if (run.pairs() > 0) say_incomplete(run.pairs(), kept);
    throw;
  }
  if (out.draw) out.draw->remove_earlier();
  if (out.jsonl) out.jsonl->finish();
  if (out.csv) out.csv->finish();
  print_summary(o, run, out, std::chrono::duration<double>(Clock::now() - t0).count());
  return 0;
}

int run_flow(const FlowOptions& o) {
  const BackendRow& row = find_backend(o.backend);  // unknown names fail before any work
  const BackendRow* const rows[] = {&row};
  check_device_option(rows, o.backend_options.device);
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

// The footer of flow's --help: its three forms, and what a sequence writes and keeps.
const char* const kFlowForms =
    "Forms:\n"
    "  pxflow flow [OPTIONS] PREV NEXT     one pair\n"
    "  pxflow flow [OPTIONS] SOURCE        every consecutive pair of SOURCE: a video file\n"
    "                                      (OpenCV videoio), a folder of frames or a quoted\n"
    "                                      glob ('f/*.png'), both sorted by name, a file of raw\n"
    "                                      frames back to back (--size), or - (raw frames on\n"
    "                                      standard input, --size)\n"
    "  pxflow flow [OPTIONS] --pairs LIST  each line of LIST: PREV NEXT (relative to LIST's\n"
    "                                      folder; a pipe's to the working directory);\n"
    "                                      pairs may differ in size, each is its own problem\n"
    "Every input may be a file or a pipe (a FIFO, /dev/stdin, bash's <(cat a.raw)).\n"
    "A sequence prints a line per pair and a summary (pairs, frames, pairs/s); --jsonl and\n"
    "--csv write one object or row per pair (- = stdout, the lines then go to stderr with\n"
    "--progress or on a terminal).\n"
    "A sequence that stops early (a signal, a closed pipe, a bad frame, a failed backend)\n"
    "keeps its completed pairs in --jsonl and --csv, each file then ending in one marker line\n"
    "(a finished one has none):\n"
    "  --jsonl  {\"incomplete\": {\"records\": 243, \"stopped_by\": \"SIGINT\"}}\n"
    "  --csv    # incomplete: 243 records, stopped by SIGINT";

// flow's options, in the order its --help lists them, a function per group (the problem's,
// the backend's and the shared ones between them).

// What is read of each frame: a raw size, a window, a binning.
void add_frame_options(CommandSpec& sub, FlowOptions& o) {
  sub.add("--size", &o.size,
          "Inputs are raw 8-bit frames of WIDTHxHEIGHT (e.g. 64x64), whatever their name")
      .type("WxH");
  sub.add("--crop", &o.crop,
          "Use the window WxH+X+Y of every frame (e.g. 64x64+100+40), before --bin")
      .type("WxH+X+Y");
  sub.add("--bin", &o.bin, "Average N x N pixels into one (after --crop)").in_range(1, 64);
}

// What is written: one pair's JSON, a sequence's JSON lines and CSV, the pictures.
void add_output_options(CommandSpec& sub, FlowOptions& o) {
  add_json_option(sub, o.json, "one object, of one pair (a sequence: --jsonl)");
  sub.add("--jsonl", &o.jsonl, "Write one JSON object per pair, one per line, to FILE (- = stdout)")
      .type("FILE")
      .path_kind(PathKind::OutputFile, ".jsonl");
  sub.add("--csv", &o.csv, "Write one CSV row per pair to FILE (- = stdout)")
      .type("FILE")
      .path_kind(PathKind::OutputFile, ".csv");
  sub.add("--draw", &o.draw,
          "Draw the POIs, their vectors and the frame flow into FILE.png (one pair) "
          "or into the folder DIR as pair-NNNNNN.png (a sequence; pictures of an "
          "earlier run beyond this run's last are removed)")
      .type("FILE.png|DIR")
      .path_kind(PathKind::OutputFile, ".png");
}

// Where the pairs come from: a list of pairs, the frames or a source, and how many are run.
void add_source_options(CommandSpec& sub, FlowOptions& o) {
  sub.add("--pairs", &o.pairs, "A list file of pairs: PREV NEXT a line")
      .type("FILE")
      .path_kind(PathKind::InputFile);
  sub.add("--max-pairs", &o.max_pairs, "Stop a sequence after N pairs (0 = all)")
      .in_range(0, 100000000);
  add_progress_flag(sub, &o.progress);
  sub.add("PREV", &o.first, "First frame (image file, or raw with --size), or SOURCE")
      .type("PREV|SOURCE")
      .path_kind(PathKind::InputSource);
  sub.add("NEXT", &o.second, "Second frame (same size)")
      .type("NEXT")
      .path_kind(PathKind::InputFile);
}

}  // namespace

const std::vector<std::string> kFlowExamples = {
    "flow PREV.png NEXT.png  # the flow estimate, a human summary",
    "flow --json - --backend ref-local A.png B.png  # JSON on standard output",
    "flow --size 64x64 prev.raw next.raw  # raw 8-bit frames",
    "flow --jsonl out.jsonl --csv out.csv frames/  # every consecutive pair of a folder",
    "flow --backend gap8-fast --crop 64x64+200+150 A.png B.png  # a window that fits GAP8's L1",
};

Command add_flow_command(CommandSpec& app) {
  auto o = std::make_shared<FlowOptions>();
  CommandSpec* sub = &app.add_subcommand(
      "flow",
      "Estimate the flow between two frames, or between every consecutive pair of a sequence");
  sub->footer = kFlowForms;
  o->problem.add_to(*sub);
  add_frame_options(*sub, *o);
  add_backend_option(*sub, o->backend);
  add_threads_option(*sub, o->backend_options.threads);
  add_device_option(*sub, o->backend_options.device);
  add_output_options(*sub, *o);
  add_source_options(*sub, *o);
  return {sub,
          [o, sub] {
            o->json_given = sub->count("--json") > 0;
            o->jsonl_given = sub->count("--jsonl") > 0;
            o->csv_given = sub->count("--csv") > 0;
            o->draw_given = sub->count("--draw") > 0;
            o->pairs_given = sub->count("--pairs") > 0;
            return run_flow(*o);
          },
          kFlowExamples,
          {"{PREV} {NEXT}", "--pairs {PAIRS}", "--size 64x64 {FRAMES}", "--size 64x64 {RAW}"},
          // About 35 s on one core (vtest.avi alone takes 1.3 s): long enough to be stopped.
          {"--profile px4flow-head --set search_radius=16 --set blocks=32 --jsonl {KEPT}.jsonl "
           "--csv {KEPT}.csv {VIDEO}"}};
}

}  // namespace pxflow::cli
