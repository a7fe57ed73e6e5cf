#include "result_json.hpp"

#include <bit>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "param_fields.hpp"

namespace pxflow {

std::string float_bits_hex(float f) {
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08x", std::bit_cast<std::uint32_t>(f));
  return buf;
}

Json record_json(const PoiRecord& r) {
  Json sub = Json::array();
  for (auto s : r.sub) sub.push_back(s);
  return Json{{"x", r.x},   {"y", r.y},   {"status", r.status}, {"feature", r.feature},
              {"dx", r.dx}, {"dy", r.dy}, {"sad", r.sad},       {"dir", r.dir},
              {"sub", sub}, {"hx", r.hx}, {"hy", r.hy}};
}

Json params_json(const Params& p) {
  Json j = Json::object();
  for (const ParamField& f : param_fields()) j[f.key] = f.get(p);
  return j;
}

Json flow_result_json(const FrameResult& result, std::span<const PoiRecord> records,
                      const OpCounts& counts) {
  Json j;
  j["flow_x"] = result.flow_x;
  j["flow_y"] = result.flow_y;
  j["flow_x_bits"] = float_bits_hex(result.flow_x);
  j["flow_y_bits"] = float_bits_hex(result.flow_y);
  j["quality"] = result.quality;
  j["meancount"] = result.meancount;
  j["histx"] = result.histx;
  j["histy"] = result.histy;
  j["counts"] = Json::object();
  if (counts.counted) {
    j["counts"]["sad_ops"] = counts.sad_ops;
    j["counts"]["interpolations"] = counts.interpolations;
  }
  Json pois = Json::array();
  for (const auto& r : records) pois.push_back(record_json(r));
  j["pois"] = std::move(pois);
  return j;
}

}  // namespace pxflow
