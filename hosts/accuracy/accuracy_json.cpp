#include "accuracy_json.hpp"

#include <nlohmann/json.hpp>

namespace pxflow::accuracy {

Json accuracy_rows_json(const AccuracyReport& report) {
  Json rows = Json::array();
  for (const auto& set : report.sets)
    for (const auto& r : set.rows)
      rows.push_back({{"set", set.set},
                      {"setting", set.setting},
                      {"against", set.against},
                      {"method", r.method},
                      {"frames", r.frames},
                      {"with_flow", r.valid},
                      {"mean_error_px", r.has_error ? Json(r.mean_error) : Json()},
                      {"p95_error_px", r.has_error ? Json(r.p95_error) : Json()},
                      {"median_us_per_frame", r.median_us}});
  return rows;
}

}  // namespace pxflow::accuracy
