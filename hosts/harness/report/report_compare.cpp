// The report's comparison of several bench files (pxflow report --bench-json A B ...): one chart
// across the files, then one section per machine compared with the first (pxflow compare's rows).
#include <map>

#include "report_sections.hpp"

namespace pxflow::report {
namespace {

// A file's marker in the chart (a backend keeps its colour in every file).
constexpr const char* kFileMarkers[] = {"circle", "square", "triangle", "diamond",
                                        "down",   "cross",  "plus"};

// frames/s by batch of every file's batch sweep (or --batch list), host-clock and device-clock
// rows alike but never a deterministic model's: a series per file, backend and clock, named by
// its file's machine when the files come from several (`several_machines`).
Chart batch_chart(std::span<const BenchFile> files, bool several_machines) {
  Chart chart;
  chart.title = "Frames per second by batch, every bench file (marker: file; colour: backend)";
  chart.x = {"batch (pairs per call, log scale)", true};
  chart.y = {"frames/s (log scale)", true};
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::map<std::pair<std::size_t, std::string>, Series> by_backend;  // registry order
    for (const Json& r : files[i].bench["rows"]) {
      const std::string sweep = r.value("sweep", "");
      if ((sweep != "batch" && sweep != "custom") || r.value("exact_clock", false) ||
          !r.contains("frames_per_s") || !r["frames_per_s"].is_number())
        continue;
      const std::string backend = r.value("backend", ""), source = r.value("source", "");
      const std::size_t rank = registry_rank(backend);
      Series& s = by_backend[{rank, backend + " " + source}];
      if (s.name.empty()) {
        s.name = files[i].label + " " + backend +
                 (source.rfind("host", 0) == 0 ? "" : " (" + source + ")") +
                 (several_machines ? " — " + file_machine(files[i]) : "");
        s.style = backend_style(rank);
        s.style.marker = kFileMarkers[i % std::size(kFileMarkers)];
        s.style.dashed = i > 0;
      }
      s.points.push_back({r.value("batch", 0) * 1.0, r["frames_per_s"].get<double>()});
    }
    for (auto& [_, s] : by_backend) chart.series.push_back(std::move(s));
  }
  return chart;
}

}  // namespace

std::vector<Section> comparison_sections(std::span<const BenchFile> files, const BenchComparison& c,
                                         bool several_machines) {
  Section all{
      "comparison", "Comparison of bench files", "", {"file", "machine and build"}, {}, {}, {}};
  all.text =
      "The bench files given, the first (A) the baseline; each other file has a section of its "
      "rows against A's, as `pxflow compare` prints them. Rows are compared when backend, point "
      "and clock are equal; ratio = median / A's median (> 1: slower), in the interval that the "
      "two medians' 95 % intervals bound; a change is significant when the Mann-Whitney U test "
      "on the two rows' samples gives p < 0.05 (docs/harness.md, \"Comparing bench files\").";
  for (std::size_t i = 0; i < files.size(); ++i) all.rows.push_back({files[i].label, c.files[i]});
  for (const std::string& w : c.warnings) all.text += "\nWarning: " + w + ".";
  if (Chart chart = batch_chart(files, several_machines); !chart.empty())
    all.charts.push_back(std::move(chart));
  std::vector<Section> out{all};
  for (const BenchFile& f : files.subspan(1)) {
    std::string key = "comparison-" + f.label;  // section keys are lower case
    key.back() = static_cast<char>(key.back() - 'A' + 'a');
    Section s{key,
              "Comparison: " + f.label + ", " + file_machine(f) + ", against A, " +
                  file_machine(files.front()),
              "",
              {"backend", "point", "clock", "A ns/frame", f.label + " ns/frame", "ratio [95% CI]",
               "p", "verdict"},
              {},
              {},
              {}};
    int slower = 0, faster = 0;
    for (const CompareRow& r : c.rows) {
      if (r.file != f.label) continue;
      slower += r.verdict == "slower", faster += r.verdict == "faster";
      char a[32], b[32], p[32];
      std::snprintf(a, sizeof a, "%.1f", r.base_median_ns);
      std::snprintf(b, sizeof b, "%.1f", r.median_ns);
      std::snprintf(p, sizeof p, "%.4f", r.p_value);
      s.rows.push_back({r.backend, point_text(r), r.source, a, b, ratio_text(r),
                        r.p_value < 0 ? "exact clock" : p, r.verdict});
    }
    s.text = f.label + ": " + c.files[&f - files.data()] + ". " + std::to_string(s.rows.size()) +
             " rows compared: " + std::to_string(slower) + " significantly slower, " +
             std::to_string(faster) + " significantly faster than A.";
    std::string missing;
    for (const std::string& n : c.not_compared)
      if (n.rfind(f.label + ":", 0) == 0) missing += "\n" + n;
    if (!missing.empty()) s.text += " Not compared:" + missing;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace pxflow::report
