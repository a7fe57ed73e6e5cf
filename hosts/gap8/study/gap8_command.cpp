// pxflow gap8: the GAP8 kernel's variants on 1..8 simulated cores, beside the ISCAS 2022
// paper's tables (hosts/gap8/gap8_study.hpp does the work).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "errors.hpp"
#include "frame_io.hpp"
#include "frame_ops.hpp"
#include "gap8_cli.hpp"
#include "gap8_flow_runner.hpp"
#include "gap8_study.hpp"
#include "json_document.hpp"
#include "output_plan.hpp"
#include "path_options.hpp"

namespace pxflow::cli {
namespace {

struct Gap8Options {
  ProblemOptions problem;
  std::string variant = "all";
  std::string cores = "1,8";
  double mhz = 50;
  std::string json_path;
  bool no_contention = false;
  bool chunked = false;
  std::string crop;
  int bin = 1;
  std::vector<std::string> frames;  // PREV NEXT, or none for the default pair
};

// "1,8", "1-8" or a mix ("1,2,4-8"): core counts in 1..8.
std::vector<int> parse_cores(const std::string& text) {
  std::vector<int> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    const std::size_t dash = item.find('-');
    const int lo = parse_int(item.substr(0, dash), "--cores", 1, 8);
    const int hi =
        dash == std::string::npos ? lo : parse_int(item.substr(dash + 1), "--cores", 1, 8);
    if (hi < lo) throw InputError("--cores: empty range " + item);
    for (int c = lo; c <= hi; ++c)
      if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
    start = comma + 1;
  }
  return out;
}

// "all": the paper's variants; else one name of gap8_variants().
std::vector<Gap8Variant> parse_variants(const std::string& v) {
  std::vector<Gap8Variant> out;
  if (v == "all") {
    for (const Gap8VariantInfo& info : gap8_variants())
      if (info.in_paper) out.push_back(info.id);
    return out;
  }
  try {
    return {find_gap8_variant(v).id};
  } catch (const InputError&) {
    throw InputError("--variant must be " + gap8_variant_names() + " or all (the paper's), not '" +
                     v + "'");
  }
}

int run_gap8(const Gap8Options& o) {
  OutputPlan plan;
  plan.read_all(o.frames);
  OutputFile* const json_file = o.json_path.empty() ? nullptr : &plan.file("--json", o.json_path);
  plan.prepare();
  gap8_study::Options options;
  options.variants = parse_variants(o.variant);
  options.cores = parse_cores(o.cores);
  if (!(o.mhz > 0 && o.mhz <= 1000)) throw InputError("--mhz must be in (0, 1000]");
  options.mhz = o.mhz;
  options.contention = !o.no_contention;
  options.chunked = o.chunked;
  FrameShaping shaping;
  if (!o.crop.empty()) parse_crop(o.crop, shaping);
  shaping.bin = o.bin;
  gap8_study::NamedFrames frames;
  if (o.frames.empty() && shaping.any())
    throw InputError("--crop and --bin shape the frames PREV NEXT; give them too");
  if (o.frames.empty()) {
    frames = gap8_study::default_pair(o.problem.resolve(std::pair{64, 64}));
  } else {
    if (o.frames.size() != 2) throw InputError("give both PREV and NEXT, or neither");
    frames = {o.frames[0] + " -> " + o.frames[1], load_frame(o.frames[0], std::nullopt),
              load_frame(o.frames[1], std::nullopt)};
    if (frames.prev.width != frames.next.width || frames.prev.height != frames.next.height)
      throw InputError("PREV and NEXT differ in size");
    if (shaping.any()) {
      frames.prev = shape_frame(frames.prev, shaping);
      frames.next = shape_frame(frames.next, shaping);
      frames.name += " (" + (o.crop.empty() ? "" : "--crop " + o.crop + " ") + "--bin " +
                     std::to_string(shaping.bin) + ": " + std::to_string(frames.prev.width) + "x" +
                     std::to_string(frames.prev.height) + ")";
    }
  }
  const Params p = o.problem.resolve(std::pair{frames.prev.width, frames.prev.height});
  // A problem outside L1 or L2 is the user's input, checked before any work.
  for (Gap8Variant v : options.variants)
    if (const std::string why = gap8_host::FlowRunner(v).unsupported(p); !why.empty())
      throw InputError("PREV NEXT (" + std::to_string(p.width) + "x" + std::to_string(p.height) +
                       "): " + why +
                       "; make the frames smaller with --crop WxH+X+Y (a window) or --bin N (N x N "
                       "pixels averaged) (see pxflow gap8 --help)");
  options.paper_problem = p == profile(kDefaultProfile);
  const FramePair pair{frames.prev.view(), frames.next.view()};
  const gap8_study::Study study = gap8_study::run_study(pair, frames.name, p, options);
  // `--json -` puts the JSON alone on standard output, so that it can be piped.
  if (o.json_path != kStdoutPath) gap8_study::print_tables(study);
  if (json_file) json_file->write(json_document(gap8_study::to_json(study)));
  return 0;
}

}  // namespace

const std::vector<std::string> kGap8Examples = {
    "gap8 --variant all --cores 1-8  # the GAP8 model beside the paper's tables",
};

Command add_gap8_command(CommandSpec& app) {
  auto o = std::make_shared<Gap8Options>();
  CommandSpec* sub = &app.add_subcommand(
      "gap8", "The GAP8 kernel on the cluster model beside the ISCAS 2022 paper's tables");
  o->problem.add_to(*sub);
  sub->add("--variant", &o->variant, gap8_variant_names() + ", or all (the paper's three)")
      .with_default()
      .type("NAME|all");
  sub->add("--cores", &o->cores, "Core counts, e.g. 1,8 or 1-8").with_default().type("LIST");
  sub->add("--mhz", &o->mhz, "Cluster clock for fps and latency").with_default();
  add_json_option(*sub, o->json_path, "the figures; with '-' instead of the tables");
  sub->flag("--no-contention", o->no_contention, "Do not model TCDM bank conflicts");
  sub->flag("--chunked", o->chunked, "Split POIs in contiguous chunks, not round robin");
  sub->add("--crop", &o->crop,
           "Use the window WxH+X+Y of PREV and NEXT (e.g. 64x64+100+40), before --bin")
      .type("WxH+X+Y");
  sub->add("--bin", &o->bin, "Average N x N pixels of PREV and NEXT into one (after --crop)")
      .in_range(1, 64);
  sub->add("frames", &o->frames, "PREV NEXT (default: a real pair, all 64 POIs accepted)")
      .type("PREV NEXT")
      .path_kind(PathKind::InputFile);
  return {
      sub, [o] { return run_gap8(*o); }, kGap8Examples, {"--variant fast --cores 1 {PREV} {NEXT}"}};
}

}  // namespace pxflow::cli
