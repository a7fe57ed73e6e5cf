#include "flow_report.hpp"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands.hpp"

namespace pxflow::cli {
namespace {

const char* status_name(int status) {
  switch (status) {
    case kAccepted:
      return "accepted";
    case kRejected:
      return "rejected";
    default:
      return "dropped";
  }
}

struct StatusCounts {
  int dropped = 0, rejected = 0, accepted = 0;
};

StatusCounts count_status(std::span<const PoiRecord> records) {
  StatusCounts c;
  for (const auto& r : records)
    (r.status == kAccepted ? c.accepted : r.status == kRejected ? c.rejected : c.dropped)++;
  return c;
}

std::string thousands(std::uint64_t v) {
  const std::string digits = std::to_string(v);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string format(const char* fmt, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, a);
  return buf;
}

// RFC 4180: a field with a comma, a quote or a line break is quoted, quotes doubled.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string what_ran(const PairRun& r) {
  std::string s = r.backend;
  if (!r.implementation.empty() && r.implementation != r.backend) s += " -> " + r.implementation;
  if (r.device != "host") s += " on " + r.device;
  return s;
}

std::string mincount_note(const PairRun& run) {
  const int accepted = count_status(run.records).accepted;
  if (accepted > run.params->min_count) return {};
  return "flow is 0 because only " + std::to_string(accepted) +
         " POIs were accepted and MINCOUNT=" + std::to_string(run.params->min_count) +
         " needs more than " + std::to_string(run.params->min_count);
}

Json pair_json(const PairRun& run) {
  Json j;
  j["backend"] = run.backend;
  j["implementation"] = run.implementation.empty() ? run.backend : run.implementation;
  j["device"] = run.device;
  const std::string crop = crop_text(run.shaping);
  j["inputs"] = {{"prev", run.prev_name},
                 {"next", run.next_name},
                 {"crop", crop.empty() ? Json() : Json(crop)},
                 {"bin", run.shaping.bin}};
  j["width"] = run.params->width;
  j["height"] = run.params->height;
  j["profile"] = run.profile;
  j["params"] = params_json(*run.params);
  const std::string note = mincount_note(run);
  if (!note.empty()) j["zero_flow_reason"] = note;
  Json result = flow_result_json(run.result, run.records, run.counts);
  for (Json& poi : result["pois"]) poi["status_name"] = status_name(poi["status"].get<int>());
  for (auto& [key, value] : result.items()) j[key] = value;
  return j;
}

std::string crop_text(const FrameShaping& s) {
  if (!s.cropped) return {};
  return std::to_string(s.crop_w) + "x" + std::to_string(s.crop_h) + "+" +
         std::to_string(s.crop_x) + "+" + std::to_string(s.crop_y);
}

DrawCaption draw_caption(const PairRun& run) {
  const auto file_name = [](const std::string& path) {
    return std::filesystem::path(path).filename().string();
  };
  std::string frames = file_name(run.prev_name) + " -> " + file_name(run.next_name);
  if (run.shaping.cropped) frames += ", crop " + crop_text(run.shaping);
  if (run.shaping.bin > 1) frames += ", bin " + std::to_string(run.shaping.bin);
  return {frames, run.backend, run.profile};
}

std::string csv_header() {
  return "pair,prev,next,crop,bin,backend,profile,width,height,flow_x,flow_y,flow_x_bits,"
         "flow_y_bits,quality,meancount,accepted,rejected,dropped\n";
}

std::string csv_row(int index, const PairRun& run) {
  const StatusCounts c = count_status(run.records);
  const auto& r = run.result;
  char flow[64];
  std::snprintf(flow, sizeof flow, "%.9g,%.9g", r.flow_x, r.flow_y);
  return std::to_string(index) + "," + csv_field(run.prev_name) + "," + csv_field(run.next_name) +
         "," + crop_text(run.shaping) + "," + std::to_string(run.shaping.bin) + "," +
         csv_field(run.backend) + "," + csv_field(run.profile) + "," +
         std::to_string(run.params->width) + "," + std::to_string(run.params->height) + "," + flow +
         "," + float_bits_hex(r.flow_x) + "," + float_bits_hex(r.flow_y) + "," +
         std::to_string(r.quality) + "," + std::to_string(r.meancount) + "," +
         std::to_string(c.accepted) + "," + std::to_string(c.rejected) + "," +
         std::to_string(c.dropped) + "\n";
}

std::string pair_summary(const PairRun& run) {
  const Params& p = *run.params;
  const StatusCounts c = count_status(run.records);
  const auto& r = run.result;
  char buf[512];
  std::string s = "backend   " + what_ran(run) + "\n";
  s += "frames    " + run.prev_name + " -> " + run.next_name + " (" + std::to_string(p.width) +
       "x" + std::to_string(p.height) + ")\n";
  std::snprintf(buf, sizeof buf, "profile   %s (S=%d, B=%d, FT=%d, VT=%d, HF %s, MINCOUNT=%d)\n",
                run.profile.c_str(), p.search_radius, p.blocks, p.feature_threshold,
                p.sad_threshold, p.hist_filter ? "on" : "off", p.min_count);
  s += buf;
  std::snprintf(buf, sizeof buf, "flow      x = %+.4f px, y = %+.4f px  (bits %s %s)\n", r.flow_x,
                r.flow_y, float_bits_hex(r.flow_x).c_str(), float_bits_hex(r.flow_y).c_str());
  s += buf;
  if (const std::string note = mincount_note(run); !note.empty()) s += "          " + note + "\n";
  std::snprintf(buf, sizeof buf,
                "quality   %d  (%d of %zu POIs accepted, %d dropped by the feature test, %d "
                "rejected)\n",
                r.quality, c.accepted, run.records.size(), c.dropped, c.rejected);
  s += buf;
  if (run.counts.counted)
    s += "counts    " + thousands(run.counts.sad_ops) + " SAD ops (4-byte), " +
         thousands(run.counts.interpolations) + " interpolations\n";
  s += "time      " + format("%.3f ms", run.host_seconds * 1e3) + " (host steady_clock, run only)";
  if (const auto& d = run.device_time) {
    s += "; " + d->source + ": ";
    if (d->cycles) s += thousands(static_cast<std::uint64_t>(*d->cycles)) + " cycles = ";
    s += format("%.3f ms", d->ns / 1e6);
  }
  return s + "\n";
}

std::string pair_line(int index, const PairRun& run) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "  flow x %+.4f y %+.4f  quality %3d  %.2f ms", run.result.flow_x,
                run.result.flow_y, run.result.quality, run.host_seconds * 1e3);
  std::string s =
      "pair " + std::to_string(index) + "  " + run.prev_name + " -> " + run.next_name + buf;
  if (run.device_time && run.device_time->cycles)
    s += "  " + thousands(static_cast<std::uint64_t>(*run.device_time->cycles)) + " cycles";
  if (!mincount_note(run).empty()) s += "  (MINCOUNT)";
  return s + "\n";
}

}  // namespace pxflow::cli
