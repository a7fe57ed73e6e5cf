#include "report_csv.hpp"

#include <algorithm>

#include "bench.hpp"
#include "check.hpp"
#include "csv_table.hpp"
#include "report.hpp"

namespace pxflow {
namespace {

// Rows of backends in registry order (stable: rows of one backend keep theirs).
void sort_by_rank(std::vector<const Json*>::iterator first,
                  std::vector<const Json*>::iterator last) {
  std::stable_sort(first, last, [](const Json* a, const Json* b) {
    return registry_rank(a->value("backend", "")) < registry_rank(b->value("backend", ""));
  });
}

bool same_bench_point(const Json& a, const Json& b) {
  return a["sweep"] == b["sweep"] && a["batch"] == b["batch"] && a["width"] == b["width"] &&
         a["height"] == b["height"] && a["search_radius"] == b["search_radius"] &&
         a["threads"] == b["threads"];
}

}  // namespace

std::string bench_csv(const Json& bench) {
  // Point by point as the bench ran them, backends in registry order within a point.
  std::vector<const Json*> rows;
  if (!bench.is_null()) {
    const Json& all = bench["rows"];
    for (std::size_t i = 0; i < all.size();) {
      std::size_t j = i;
      while (j < all.size() && same_bench_point(all[j], all[i])) ++j;
      const std::size_t start = rows.size();
      for (std::size_t k = i; k < j; ++k) rows.push_back(&all[k]);
      sort_by_rank(rows.begin() + static_cast<std::ptrdiff_t>(start), rows.end());
      i = j;
    }
  }
  return csv_lines(csv_columns(bench_row_fields()), rows);
}

std::string conformance_csv(const Json& check) {
  std::vector<const Json*> rows;
  if (!check.is_null() && check["backends"].is_array())
    for (const auto& r : check["backends"]) rows.push_back(&r);
  sort_by_rank(rows.begin(), rows.end());
  return csv_lines(csv_columns(backend_outcome_fields()), rows);
}

std::string accuracy_csv(const Json& accuracy_rows) {
  return csv_table({"set", "setting", "against", "method", "frames", "with_flow", "mean_error_px",
                    "p95_error_px", "median_us_per_frame"},
                   accuracy_rows);
}

}  // namespace pxflow
