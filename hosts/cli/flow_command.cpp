// pxflow flow: one frame pair through one backend, the estimate as text or JSON.
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "draw_flow.hpp"
#include "errors.hpp"
#include "estimate.hpp"
#include "frame_io.hpp"
#include "grid.hpp"
#include "registry.hpp"
#include "result_json.hpp"

namespace pxflow::cli {
namespace {

struct FlowOptions {
  ProblemOptions problem;
  std::string size;
  std::string backend = kReferenceBackend;  // the executable spec, and it counts its work
  BackendOptions backend_options;
  bool json = false;
  std::string draw;  // PNG path
  bool draw_given = false;
  std::string prev_path, next_path;
};

std::string thousands(std::uint64_t v) {
  const std::string digits = std::to_string(v);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

void print_summary(const FlowOptions& o, const Params& p, const FrameResult& r,
                   std::span<const PoiRecord> recs, const OpCounts& counts) {
  int status_count[3] = {0, 0, 0};
  for (const auto& rec : recs) ++status_count[rec.status];
  std::printf("backend   %s\n", o.backend.c_str());
  std::printf("frames    %s -> %s (%dx%d)\n", o.prev_path.c_str(), o.next_path.c_str(), p.width,
              p.height);
  std::printf("profile   %s (S=%d, B=%d, FT=%d, VT=%d, HF %s, MINCOUNT=%d)\n",
              o.problem.profile.c_str(), p.search_radius, p.blocks, p.feature_threshold,
              p.sad_threshold, p.hist_filter ? "on" : "off", p.min_count);
  std::printf("flow      x = %+.4f px, y = %+.4f px  (bits %s %s)\n", r.flow_x, r.flow_y,
              float_bits_hex(r.flow_x).c_str(), float_bits_hex(r.flow_y).c_str());
  std::printf(
      "quality   %d  (%d of %zu POIs accepted, %d dropped by the feature test, %d rejected)\n",
      r.quality, status_count[kAccepted], recs.size(), status_count[kDropped],
      status_count[kRejected]);
  if (counts.counted)
    std::printf("counts    %s SAD ops (4-byte), %s interpolations\n",
                thousands(counts.sad_ops).c_str(), thousands(counts.interpolations).c_str());
}

int run_flow(const FlowOptions& o) {
  const BackendRow& row = find_backend(o.backend);  // unknown names fail before any work
  const BackendRow* const rows[] = {&row};
  check_device_option(rows, o.backend_options.device);
  if (o.draw_given) {
    const std::string inputs[] = {o.prev_path, o.next_path};
    check_draw_path(o.draw, inputs);
  }
  std::optional<FrameSize> raw_size;
  if (!o.size.empty()) raw_size = parse_frame_size(o.size);
  const Frame prev = load_frame(o.prev_path, raw_size);
  const Frame next = load_frame(o.next_path, raw_size);
  if (prev.width != next.width || prev.height != next.height)
    throw InputError("frames differ in size: " + o.prev_path + " is " + std::to_string(prev.width) +
                     "x" + std::to_string(prev.height) + ", " + o.next_path + " is " +
                     std::to_string(next.width) + "x" + std::to_string(next.height));
  const Params p = o.problem.resolve(std::pair{prev.width, prev.height});

  auto backend = open_backend_for(row, o.backend_options, p);

  const FramePair pair{prev.view(), next.view()};
  std::vector<PoiRecord> records(poi_count(p));
  check_batch({&pair, 1}, p, records);
  OpCounts counts;
  backend->run({&pair, 1}, p, records, counts);
  const FrameResult result = estimate_flow(records, p);
  if (o.draw_given) {
    const auto file = [](const std::string& path) {
      return std::filesystem::path(path).filename().string();
    };
    std::string frames = file(o.prev_path);
    frames += " -> ";
    frames += file(o.next_path);
    draw_flow(o.draw, prev.view(), p, records, result, {frames, o.backend, o.problem.profile});
  }
  if (o.json)
    std::cout << flow_result_json(result, records, counts).dump() << "\n";
  else
    print_summary(o, p, result, records, counts);
  return 0;
}

}  // namespace

Command add_flow_command(CLI::App& app) {
  auto o = std::make_shared<FlowOptions>();
  CLI::App* sub =
      app.add_subcommand("flow", "Estimate the flow between two frames with one backend");
  o->problem.add_to(*sub);
  sub->add_option("--size", o->size, "Frame size of .raw inputs, WIDTHxHEIGHT (e.g. 64x64)");
  sub->add_option("--backend", o->backend, "Backend to run (see `pxflow backends`)")
      ->capture_default_str();
  sub->add_option("--threads", o->backend_options.threads,
                  "Host worker threads of the CPU backends and the GAP8 model (0 = all cores)")
      ->check(CLI::Range(0, 1024));
  sub->add_option("--device", o->backend_options.device,
                  "Device index or name substring (GPU backends)");
  sub->add_flag("--json", o->json,
                "Print one JSON object: flow, bits, histograms, counts, records");
  CLI::Option* draw = sub->add_option(
      "--draw", o->draw, "Also draw the POIs, their vectors and the frame flow into FILE (.png)");
  sub->add_option("PREV", o->prev_path, "First frame (image file or .raw)")->required();
  sub->add_option("NEXT", o->next_path, "Second frame (same size)")->required();
  return {sub, [o, draw] {
            o->draw_given = draw->count() > 0;
            return run_flow(*o);
          }};
}

}  // namespace pxflow::cli
