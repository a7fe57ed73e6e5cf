#include <cstdio>
#include <iostream>

#include "errors.hpp"
#include "gap8_cli.hpp"
#include "gap8_study.hpp"
#include "report.hpp"
#include "svg_chart.hpp"

namespace pxflow::cli {
namespace {

std::string fixed(double v, const char* fmt) {
  char b[32];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

// Every core count: cycles, frame rate and latency at the clock, speed-up against Amdahl's limit.
ReportInputs::Table core_counts(const gap8_study::Study& s, const std::string& command) {
  ReportInputs::Table t{
      "GAP8 model: every core count",
      "Core 0's cycles per frame at " + fixed(s.options.mhz, "%.0f") +
          " MHz; speed-up over 1 core against Amdahl's limit from the 1-core phases. "
          "Command: `" +
          command + "`.",
      {"variant", "cores", "cycles", "frames/s (model clock)", "latency ms", "speed-up",
       "Amdahl's limit"},
      {},
      {}};
  // Linear axes: 1 to 8 cores, speed-ups up to 8, every value readable off a labelled tick.
  Chart chart{"GAP8 model: speed-up over 1 core",
              {"cluster cores", false, true},
              {"speed-up over 1 core", false},
              {},
              {},
              ""};
  Series ideal{"linear (ideal)", {}, reference_style()};
  for (Gap8Variant v : s.options.variants) {
    // The colour and marker of the variant's registry row (gap8-<variant>), as in every chart.
    const std::string row = std::string("gap8-") + gap8_variant(v).name;
    Series se{row, {}, backend_style(registry_rank(row))};
    for (const auto& [cores, m] : s.results.at(v)) {
      const double speedup = gap8_study::speedup(s, v, cores);
      t.rows.push_back({gap8_variant(v).name, std::to_string(cores), fixed(m.cycles, "%.0f"),
                        fixed(gap8_study::fps(s, m.cycles), "%.1f"),
                        fixed(m.cycles / (s.options.mhz * 1e3), "%.3f"), fixed(speedup, "%.2fx"),
                        fixed(gap8_study::amdahl_limit(s, v, cores), "%.2fx")});
      se.points.push_back({double(cores), speedup});
      if (v == s.options.variants.front()) ideal.points.push_back({double(cores), double(cores)});
    }
    chart.series.push_back(se);
  }
  chart.series.push_back(ideal);
  t.charts.push_back(chart);
  return t;
}

}  // namespace

void add_gap8_tables(ReportInputs& in) {
  ReportInputs::Section& section = in.sections.emplace_back();
  section.key = "gap8";
  section.command = "pxflow gap8 --cores 1-8";
  std::cout << "== " << section.command << "\n";
  gap8_study::Options options;
  for (const Gap8VariantInfo& v : gap8_variants())
    if (v.in_paper) options.variants.push_back(v.id);
  options.cores = {1, 2, 3, 4, 5, 6, 7, 8};
  const Params p = profile(kDefaultProfile);
  gap8_study::NamedFrames frames;
  try {
    frames = gap8_study::default_pair(p);
  } catch (const InputError& e) {
    section.tables.push_back({"GAP8 model beside the ISCAS 2022 paper",
                              std::string("Not measured: ") + e.what(),
                              {},
                              {},
                              {}});
    return;
  }
  const FramePair pair{frames.prev.view(), frames.next.view()};
  const gap8_study::Study s = gap8_study::run_study(pair, frames.name, p, options);
  const std::string intro =
      "The GAP8 kernel's three variants (kernels/gap8) on our cycle model of the 8-core cluster "
      "(TCDM contention on, POIs round robin) on " +
      frames.name + ", beside the paper's figures. Command: `" + section.command +
      "`; where and why model and paper differ: docs/gap8-kernel.md.";
  // The paper's tables have 1 and 8 cores; the other counts are in the last table.
  gap8_study::Study paper_cores = s;
  for (auto& [variant, by_cores] : paper_cores.results)
    std::erase_if(by_cores, [](const auto& e) { return e.first != 1 && e.first != 8; });
  bool first = true;
  for (const gap8_study::PaperTable& pt : gap8_study::paper_tables(paper_cores)) {
    ReportInputs::Table t{"GAP8 model: " + pt.title,
                          first ? intro : "Same run as above.",
                          {"figure", "variant", "model", "paper", "diff"},
                          {},
                          {}};
    first = false;
    for (const auto& l : pt.lines) t.rows.push_back({l.label, l.variant, l.model, l.paper, l.diff});
    section.tables.push_back(std::move(t));
  }
  section.tables.push_back(core_counts(s, section.command));
  section.data = gap8_study::to_json(s);
}

}  // namespace pxflow::cli
