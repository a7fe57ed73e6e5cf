#include "report_rows.hpp"

#include <algorithm>
#include <cstdio>

#include "counted.hpp"
#include "number_text.hpp"
#include "report.hpp"

namespace pxflow::report {

std::string num(double v, const char* format) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::string str(const Json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
}

bool timed(const Json& r) { return r.value("median_ns_per_frame", 0.0) > 0; }
bool host_clock(const Json& r) { return str(r, "source").rfind("host", 0) == 0; }
bool exact_clock(const Json& r) { return r.value("exact_clock", false); }

bool counts_instructions(const Json& r) { return r.contains("instructions_per_frame"); }
bool counts_instructions(const Json& bench, const std::string& backend) {
  return std::any_of(bench["rows"].begin(), bench["rows"].end(), [&](const Json& r) {
    return str(r, "backend") == backend && counts_instructions(r);
  });
}
std::string instructions_cell(const Json& r) {
  return num(r["instructions_per_frame"].get<double>(), "%.0f") + " instr";
}
std::string bound_cell(const Json& r) {
  if (!r.contains("bound_per_frame")) return "-";
  return bound_text(r["bound_per_frame"].get<double>(), str(r, "bound_unit"));
}

std::string fraction_cell(const Json& r) {
  if (r.contains("bound_fraction")) return num(100 * r["bound_fraction"].get<double>()) + " %";
  return str(r, "bound").rfind("none: ", 0) == 0 ? "none" : "-";
}

const char* const kInstructionNote =
    " Rows labelled by an instruction count (QEMU -icount) show instructions per frame, tabled, "
    "not charted: they are no time (QEMU's virtual clock ticks per instruction, a speed no core "
    "has).";

std::string threads_text(int n) { return counted(n, "thread"); }

std::string stopped_after(const Json& bench) {
  if (bench.value("complete", true)) return "";
  return "a signal stopped this bench after " + std::to_string(bench.value("points_done", 0L)) +
         " of " + std::to_string(bench.value("points_total", 0L)) + " points";
}

std::string point_name(const Json& r) {
  return str(r, "profile") + ", " + std::to_string(r.value("width", 0)) + "x" +
         std::to_string(r.value("height", 0)) +
         ", S=" + std::to_string(r.value("search_radius", 0)) + ", batch " +
         std::to_string(r.value("batch", 0)) + ", " + threads_text(r.value("threads", 0));
}

std::vector<const Json*> in_registry_order(const Json& rows) {
  std::vector<const Json*> out;
  for (const auto& r : rows) out.push_back(&r);
  std::stable_sort(out.begin(), out.end(), [](const Json* a, const Json* b) {
    return registry_rank(str(*a, "backend")) < registry_rank(str(*b, "backend"));
  });
  return out;
}

ChartStyle style_of(const std::string& backend) { return backend_style(registry_rank(backend)); }

}  // namespace pxflow::report
