#include "report_sections.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <span>

#include "check.hpp"
#include "counted.hpp"
#include "report_rows.hpp"

namespace pxflow::report {
namespace {

bool same_problem(const Json& a, const Json& b) {
  return a["width"] == b["width"] && a["height"] == b["height"] &&
         a["search_radius"] == b["search_radius"] && a["threads"] == b["threads"];
}

bool same_point(const Json& a, const Json& b) {
  return same_problem(a, b) && a["sweep"] == b["sweep"] && a["batch"] == b["batch"];
}

std::vector<std::string> bench_cells(const Json& r) {
  if (!timed(r))
    return {str(r, "backend"), "-", "-", "-", "-", "-", "-", "-", "-", "-", str(r, "note")};
  if (counts_instructions(r))
    return {str(r, "backend"), str(r, "source"), "-", "-",           "-", "-", instructions_cell(r),
            bound_cell(r),     fraction_cell(r), "-", str(r, "note")};
  return {str(r, "backend"),
          str(r, "source"),
          num(r["median_ns_per_frame"], "%.0f"),
          r.contains("median_ci_low_ns")
              ? num(r["median_ci_low_ns"], "%.0f") + ".." + num(r["median_ci_high_ns"], "%.0f")
              : "-",
          num(r["frames_per_s"]),
          num(r["ns_per_poi"]),
          r.contains("cycles_per_frame") ? num(r["cycles_per_frame"], "%.0f") : "-",
          bound_cell(r),
          fraction_cell(r),
          r.contains("speedup_vs_ref_original") ? num(r["speedup_vs_ref_original"], "%.2fx") : "-",
          str(r, "note")};
}

// What the bound columns mean, with the host bound's measured values (docs/harness.md, "The bound
// of every row").
std::string bound_text(const Json& bench) {
  std::string host;
  if (bench.contains("bound")) {
    const Json& b = bench["bound"];
    std::string values;
    for (const auto& t : b.value("by_threads", Json::array()))
      values += (values.empty() ? "" : ", ") + num(t["bytes_per_cycle"], "%.1f") + " on " +
                threads_text(t["threads"].get<int>());
    if (values.empty()) values = num(b["bytes_per_cycle"], "%.1f") + " on one thread";
    host = " Code on the host CPU: " + str(b, "name") + ", measured by this bench run on as many " +
           "threads as the row was given (" + values +
           " bytes per TSC cycle); OpenCL and Vulkan on a CPU device: the same on all cores, in ns "
           "at the TSC's rate.";
  }
  return "\n\nbound/frame: the least the frame's SAD work (every POI's search and half-pixel "
         "SADs, 64 bytes per SAD) can take on the row's hardware, in the row's own unit; of "
         "bound: that over the row's figure (100 % would be a kernel doing nothing but that "
         "work at the hardware's widest SAD rate; above 100 % is a measuring error and says "
         "so)." +
         host +
         " The GAP8 model: 4 bytes per cycle on each core; m4-qemu: one USADA8 (4 bytes) per "
         "instruction. A row without a bound says why in its note. Every point's fractions are "
         "charted in \"Achieved fraction of the bound\".";
}

}  // namespace

Section backends_section(const ReportInputs& in) {
  Section s{"backends",
            "What each backend runs",
            in.backends_source,
            {"backend", "implementation", "device", "driver / version"},
            {},
            {},
            {}};
  for (const Json* b : in_registry_order(in.backends))
    s.rows.push_back(
        {str(*b, "backend"), str(*b, "implementation"), str(*b, "device"), str(*b, "driver")});
  if (s.rows.empty()) s.text += " No backend was opened.";
  return s;
}

// The lines the check printed for a backend's failures, as a list under the table's text (all of
// them are in results.json's `check`).
std::string failure_lines(const Json& backend) {
  constexpr std::size_t kShown = 20;
  const std::vector<std::string> lines = backend.value("failures", std::vector<std::string>{});
  if (lines.empty()) return {};
  std::string s = "\n\nFailures of " + str(backend, "backend") + ", as the check printed them:\n";
  for (std::size_t i = 0; i < lines.size() && i < kShown; ++i) s += "\n- `" + lines[i] + "`";
  if (lines.size() > kShown)
    s += "\n- ... and " + std::to_string(lines.size() - kShown) +
         " more (every line is in results.json, `check`)";
  return s;
}

Section conformance(const Json& check, const std::string& cmd) {
  Section s{
      "conformance",
      "Conformance",
      "Every backend against `ref-original`, records byte for byte and flow by bits, on " +
          counted(check.value("cases", 0), "case") + " (" +
          std::to_string(check.value("pairs", 0)) + " frame pairs), seed " +
          std::to_string(check.value("seed", 0)) + ". Command: `" + cmd + "`.",
      {"backend", "result", "cases passed", "cases failed", "n/a", "pairs", "run time s", "note"},
      {},
      {},
      {}};
  std::vector<const Json*> backends;
  for (const auto& b : check["backends"]) backends.push_back(&b);
  std::stable_sort(backends.begin(), backends.end(), [](const Json* a, const Json* b) {
    return registry_rank(str(*a, "backend")) < registry_rank(str(*b, "backend"));
  });
  for (const Json* b : backends)
    s.rows.push_back({str(*b, "backend"), str(*b, "state"), std::to_string(b->value("passed", 0L)),
                      std::to_string(b->value("failed", 0L)),
                      std::to_string(b->value("not_applicable", 0L)),
                      std::to_string(b->value("pairs", 0L)), num(b->value("seconds", 0.0), "%.2f"),
                      str(*b, "reason")});
  s.text += " Totals: " + std::to_string(check.value("passed", 0)) + " passed, " +
            std::to_string(check.value("failed", 0)) + " failed, " +
            std::to_string(check.value("skipped", 0)) + " skipped.";
  if (const std::vector<int> missing = check.value("missing_shards", std::vector<int>{});
      !missing.empty()) {
    const Json& from = check.value("merged_from", Json::array());
    const int count = from.empty() ? 0 : from.front().value("count", 0);
    s.text += " Incomplete: " + missing_shards_text(missing, count) + ".";
  }
  if (!check.value("complete", true))
    s.text += " **Incomplete: a signal stopped this check after " +
              std::to_string(check.value("cases", 0L)) + " of " +
              std::to_string(check.value("cases_total", 0L)) +
              " cases; the counts are those of the cases done (pxflow check --resume FILE "
              "finishes it).**";
  for (const Json* b : backends) s.text += failure_lines(*b);
  return s;
}

namespace {

// How many points (problem, batch, threads) the bench's custom rows cover.
std::size_t bench_points(const Json& bench) {
  std::set<std::string> points;
  for (const auto& r : bench["rows"])
    if (r["sweep"] == "custom") points.insert(point_name(r));
  return points.size();
}

// A bench a signal stopped ("complete": false) is shown with what it measured, and says so.
std::string stopped_bench_note(const Json& bench) {
  const std::string stopped = stopped_after(bench);
  return stopped.empty() ? "" : " **Incomplete: " + stopped + "; the rows are those it measured.**";
}

// The headline point: the batch sweep at 256 pairs, or the first point a host clock timed; null
// when no row was timed by the host clock.
const Json* headline_row(const Json& bench) {
  const Json* pick = nullptr;
  for (const auto& r : bench["rows"])
    if (timed(r) && host_clock(r) && r["sweep"] == "batch" && r["batch"] == 256) pick = &r;
  for (const auto& r : bench["rows"])
    if (!pick && timed(r) && host_clock(r)) pick = &r;
  return pick;
}

// Exact-clock backends (the GAP8 model) are charted apart, by their own clock: each one's row at
// the headline point, or at the largest batch of the same problem the bench simulated, in
// registry order.
std::vector<const Json*> exact_clock_rows(const Json& bench, const Json& pick) {
  std::map<std::string, const Json*> model;
  for (const Json* r : in_registry_order(bench["rows"]))
    if (exact_clock(*r) && timed(*r) && same_problem(*r, pick) && (*r)["sweep"] == pick["sweep"]) {
      const Json*& best = model[str(*r, "backend")];
      if (!best || (*r)["batch"].get<int>() > (*best)["batch"].get<int>()) best = r;
    }
  std::vector<const Json*> rows;
  for (const auto& [_, r] : model) rows.push_back(r);
  std::stable_sort(rows.begin(), rows.end(), [](const Json* a, const Json* b) {
    return registry_rank(str(*a, "backend")) < registry_rank(str(*b, "backend"));
  });
  return rows;
}

std::string throughput_text(const Json& bench, const std::string& cmd, const Json& pick,
                            std::span<const Json* const> model_rows) {
  std::string text =
      "Median of repeated runs after a warm-up run whose records matched ref-original; a backend "
      "with an exact clock (a deterministic cycle model) is timed by that clock from its one "
      "checked "
      "run and charted apart, never beside the host's figures. Speed-ups compare rows of the "
      "same clock only. Command: `" +
      cmd + "`.";
  if (std::any_of(model_rows.begin(), model_rows.end(),
                  [](const Json* r) { return counts_instructions(*r); }))
    text += kInstructionNote;
  if (bench_points(bench) > 1 && pick["sweep"] == "custom")
    text += " This bench measured " + std::to_string(bench_points(bench)) +
            " points of its own (bench --batch, --sizes, --radius, --thread-sweep): every one "
            "is in \"The bench's points\" below.";
  return text + bound_text(bench) + stopped_bench_note(bench);
}

}  // namespace

Section throughput(const Json& bench, const std::string& cmd, const MachineTag& tag) {
  Section s{"throughput",
            "Throughput",
            "",
            {"backend", "clock", "ns/frame (median)", "95% CI of median", "frames/s", "ns/POI",
             "cycles/frame", "bound/frame", "of bound", "vs ref-original", "note"},
            {},
            {},
            {}};
  const Json* pick = headline_row(bench);
  if (!pick) {
    s.text =
        "No row was timed by the host clock. Command: `" + cmd + "`." + stopped_bench_note(bench);
    return s;
  }
  const std::string point = point_name(*pick);
  s.title += " (" + point + ")" + tag.title;
  Chart host{"Frames per second by the host clock (" + point + ")" + tag.title,
             {"frames per second (log scale)", true},
             {"", false},
             {},
             {},
             "frames/s"};
  for (const Json* r : in_registry_order(bench["rows"]))
    if (same_point(*r, *pick)) {
      s.rows.push_back(bench_cells(*r));
      if (timed(*r) && host_clock(*r))
        host.bars.push_back({str(*r, "backend") + tag.series, (*r)["frames_per_s"].get<double>(),
                             style_of(str(*r, "backend"))});
    }
  Chart sim{"Frames per second by the exact model clock, not the host (" + str(*pick, "profile") +
                ", " + std::to_string(pick->value("width", 0)) + "x" +
                std::to_string(pick->value("height", 0)) + ")" + tag.title,
            {"frames per second at the model's clock (log scale)", true},
            {"", false},
            {},
            {},
            "frames/s"};
  const std::vector<const Json*> model_rows = exact_clock_rows(bench, *pick);
  for (const Json* r : model_rows) {
    if (!same_point(*r, *pick)) s.rows.push_back(bench_cells(*r));
    if (counts_instructions(*r)) continue;
    sim.bars.push_back({str(*r, "backend") + " (batch " + std::to_string((*r)["batch"].get<int>()) +
                            ")" + tag.series,
                        (*r)["frames_per_s"].get<double>(), style_of(str(*r, "backend"))});
  }
  s.text = throughput_text(bench, cmd, *pick, model_rows);
  if (!host.bars.empty()) s.charts.push_back(host);
  if (!sim.bars.empty()) s.charts.push_back(sim);
  return s;
}

Section accuracy(const ReportInputs& in) {
  return {"accuracy",
          "Accuracy",
          "Frame flow against known motion (synthetic pairs) and agreement with OpenCV's DIS on "
          "real video, beside OpenCV's pyramidal Lucas-Kanade and DIS, timed in the same run. "
          "Command: `" +
              in.accuracy_command + "`; method details in docs/accuracy.md.",
          in.accuracy.front(),
          {in.accuracy.begin() + 1, in.accuracy.end()},
          {},
          in.pictures};
}

Json chart_json(const Chart& c) {
  auto style = [](const ChartStyle& st) {
    return Json{{"colour", st.colour}, {"marker", st.marker}, {"dashed", st.dashed}};
  };
  Json j{{"title", c.title},
         {"kind", c.bars.empty() ? "line" : "bar"},
         {"x_axis", {{"label", c.x.label}, {"log", c.x.log}, {"integer", c.x.integer}}},
         {"y_axis", {{"label", c.y.label}, {"log", c.y.log}, {"integer", c.y.integer}}},
         {"unit", c.unit},
         {"series", Json::array()},
         {"bars", Json::array()}};
  for (const Series& se : c.series) {
    Json points = Json::array();
    for (auto [x, y] : se.points) points.push_back({x, y});
    j["series"].push_back({{"name", se.name}, {"style", style(se.style)}, {"points", points}});
  }
  for (const Bar& b : c.bars)
    j["bars"].push_back({{"label", b.label}, {"value", b.value}, {"style", style(b.style)}});
  return j;
}

}  // namespace pxflow::report
