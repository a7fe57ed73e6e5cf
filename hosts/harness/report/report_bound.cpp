// The section of every timed row's bound: one chart per point of the bench, each row's achieved
// fraction of its bound (docs/harness.md, "The bound of every row").
#include <map>

#include "report_rows.hpp"
#include "report_sections.hpp"

namespace pxflow::report {
namespace {

// A point as the bound section groups rows: the sweep it belongs to and its problem.
std::string point_key(const Json& r) { return point_name(r) + " (" + str(r, "sweep") + " sweep)"; }

Chart fraction_chart(const std::string& point, const MachineTag& tag) {
  return Chart{"Achieved fraction of the bound (" + point + ")" + tag.title,
               {"% of the row's bound (log scale)", true},
               {"", false},
               {},
               {},
               "% of bound"};
}

}  // namespace

Section bound_section(const Json& bench, const MachineTag& tag) {
  Section s{"bound",
            "Achieved fraction of the bound" + tag.title,
            "Every timed row's bound per frame (what it is, and its unit) and the fraction of it "
            "the row achieved, one chart per point of the bench (docs/harness.md, \"The bound of "
            "every row\"). A row without a bound has no bar and says why here.",
            {"point", "backend", "clock", "bound/frame", "of bound", "bound"},
            {},
            {},
            {}};
  std::vector<std::string> order;  // points in the bench's order
  std::map<std::string, Chart> charts;
  for (const Json& r : bench["rows"]) {
    const std::string key = point_key(r);
    if (timed(r) && !charts.contains(key)) {
      order.push_back(key);
      charts.emplace(key, fraction_chart(key, tag));
    }
  }
  for (const std::string& key : order)
    for (const Json* r : in_registry_order(bench["rows"])) {
      if (!timed(*r) || point_key(*r) != key) continue;
      s.rows.push_back({key, str(*r, "backend"), str(*r, "source"), bound_cell(*r),
                        fraction_cell(*r), str(*r, "bound")});
      if (r->contains("bound_fraction"))
        charts.at(key).bars.push_back(
            {str(*r, "backend") + " (" + str(*r, "source") + ")" + tag.series,
             100 * (*r)["bound_fraction"].get<double>(), style_of(str(*r, "backend"))});
    }
  for (const std::string& key : order)
    if (!charts.at(key).empty()) s.charts.push_back(charts.at(key));
  if (order.empty()) s.text += " No row was timed.";
  return s;
}

}  // namespace pxflow::report
