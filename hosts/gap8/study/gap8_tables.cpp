// `pxflow gap8` output: the paper's Tables I-III with the model beside them, then the figures
// the paper does not have (every core count, fps, latency, energy, counters per core), and JSON.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "counted.hpp"
#include "gap8_study.hpp"

namespace pxflow::gap8_study {
namespace {

constexpr double kPaperPowerW = 0.025;  // the paper's GAP8 figure at 50 MHz

std::string diff(double model, std::optional<double> paper) {
  if (!paper || *paper == 0) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.1f%%", (model - *paper) / *paper * 100.0);
  return buf;
}

std::string num(std::optional<double> v, const char* fmt = "%.1fk", double scale = 1000.0) {
  if (!v) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, fmt, *v / scale);
  return buf;
}

PaperLine line(const std::string& label, Gap8Variant variant, double model,
               std::optional<double> paper, const char* fmt = "%.1fk", double scale = 1000.0) {
  return {label, gap8_variant(variant).name, num(model, fmt, scale), num(paper, fmt, scale),
          diff(model, paper)};
}

// The variants in the order asked for (original, local, global), not the map's.
std::vector<std::pair<Gap8Variant, const std::map<int, Measure>&>> in_order(const Study& s) {
  std::vector<std::pair<Gap8Variant, const std::map<int, Measure>&>> out;
  for (Gap8Variant v : s.options.variants) out.emplace_back(v, s.results.at(v));
  return out;
}

double per_core_sum(const Measure& m, int event) {
  double s = 0;
  for (const auto& c : m.cores) s += double(c[event]);
  return s;
}

// The paper's figure, only when the study ran the paper's problem: the model's figures are
// never set beside the paper's for other parameters.
std::optional<PaperFigures> paper_for(const Study& s, Gap8Variant v, int cores) {
  return s.options.paper_problem ? paper(v, cores) : std::nullopt;
}

}  // namespace

std::vector<PaperTable> paper_tables(const Study& s) {
  std::vector<PaperTable> out(3);
  out[0].title =
      "Table I: interpolations and instructions per frame (instructions: 1 core, whole run)";
  for (const auto& [v, by] : in_order(s)) {
    const auto p1 = paper_for(s, v, 1);
    const Measure& m = by.at(1);
    out[0].lines.push_back(line("interpolations", v, m.interpolations,
                                p1 ? p1->interpolations : std::nullopt, "%.0f", 1));
    out[0].lines.push_back(
        line("instructions", v, m.instructions, p1 ? p1->instructions : std::nullopt));
    out[0].lines.push_back(
        line("4-byte SAD ops", v, m.sad_ops, p1 ? p1->sad_ops : std::nullopt, "%.0f", 1));
  }
  out[1].title = "Table II: cycles per frame (core 0) and speed-up";
  for (const auto& [v, by] : in_order(s)) {
    for (const auto& [cores, m] : by) {
      const auto pp = paper_for(s, v, cores);
      out[1].lines.push_back(
          line("cycles, " + counted(cores, "core"), v, m.cycles, pp ? pp->cycles : std::nullopt));
      if (cores == 1) continue;
      out[1].lines.push_back(line("speed-up, " + counted(cores, "core"), v, speedup(s, v, cores),
                                  pp ? pp->speedup : std::nullopt, "%.2fx", 1));
    }
  }
  out[2].title = "Table III: cycles per phase (1 core), ideal 8-core flow, Amdahl's limit";
  for (const auto& [v, by] : in_order(s)) {
    const Measure& m = by.at(1);
    const auto p1 = paper_for(s, v, 1);
    auto phase = [&](double Phases::*field) -> std::optional<double> {
      if (p1 && p1->phases) return (*p1->phases).*field;
      return std::nullopt;
    };
    auto& t = out[2].lines;
    t.push_back(line("initialisation (in DMA)", v, m.phases.init, phase(&Phases::init)));
    t.push_back(line("DMA copy", v, m.phases.dma, phase(&Phases::dma)));
    t.push_back(line("flow estimation", v, m.phases.flow, phase(&Phases::flow)));
    t.push_back(line("averaging", v, m.phases.averaging, phase(&Phases::averaging)));
    t.push_back(line("records to L2 (not in paper)", v, m.phases.output, std::nullopt));
    const auto p8 = paper_for(s, v, 8);
    const auto flow = phase(&Phases::flow);
    t.push_back(line("flow, 8 cores ideal", v, m.phases.flow / 8,
                     flow ? std::optional(*flow / 8) : std::nullopt));
    if (by.count(8)) {
      t.push_back(line("flow, 8 cores actual", v, by.at(8).phases.flow,
                       p8 && p8->phases ? std::optional(p8->phases->flow) : std::nullopt));
      t.push_back(line("Amdahl's limit, 8 cores", v, amdahl_limit(s, v, 8),
                       p8 ? p8->amdahl_limit : std::nullopt, "%.3fx", 1));
      t.push_back(line("actual speed-up, 8 cores", v, speedup(s, v, 8),
                       p8 ? p8->speedup : std::nullopt, "%.2fx", 1));
    }
  }
  return out;
}

void print_tables(const Study& s) {
  std::printf("pxflow gap8: %s; %.0f MHz; TCDM contention %s; POIs split %s\n", s.pair_name.c_str(),
              s.options.mhz, s.options.contention ? "on" : "off",
              s.options.chunked ? "in chunks" : "round robin");
  if (!s.options.paper_problem)
    std::printf(
        "note: the paper's tables are for px4flow-64 on 64x64 frames; these parameters "
        "differ, so no paper figure is shown beside the model's\n");
  for (const PaperTable& t : paper_tables(s)) {
    std::printf("\n%s\n  %-28s %-9s %12s %12s %9s\n", t.title.c_str(), "", "variant", "model",
                "paper", "diff");
    for (const PaperLine& l : t.lines)
      std::printf("  %-28s %-9s %12s %12s %9s\n", l.label.c_str(), l.variant.c_str(),
                  l.model.c_str(), l.paper.c_str(), l.diff.c_str());
  }
  std::printf("\nEvery core count (fps, latency at %.0f MHz; energy at the paper's 25 mW)\n",
              s.options.mhz);
  std::printf("  %-9s %5s %10s %8s %9s %9s %8s %8s %10s %9s\n", "variant", "cores", "cycles", "fps",
              "latency", "energy", "speedup", "amdahl", "tcdm_cont", "ld_stall");
  for (const auto& [v, by] : in_order(s))
    for (const auto& [cores, m] : by) {
      const double seconds = m.cycles / (s.options.mhz * 1e6);
      std::printf("  %-9s %5d %10.0f %8.1f %7.3fms %7.1fuJ %7.2fx %7.2fx %10.0f %9.0f\n",
                  gap8_variant(v).name, cores, m.cycles, fps(s, m.cycles), seconds * 1e3,
                  seconds * kPaperPowerW * 1e6, speedup(s, v, cores), amdahl_limit(s, v, cores),
                  per_core_sum(m, GAP8_EVT_TCDM_CONT), per_core_sum(m, GAP8_EVT_LD_STALL));
    }
  std::printf(
      "\nBeyond the paper: a one-cycle SAD instruction (as the Cortex-M4's USADA8) would save 3 "
      "of the 4 single-cycle Xpulp instructions of every 4-byte SAD\n");
  for (const auto& [v, by] : in_order(s))
    for (const auto& [cores, m] : by) {
      if (cores != 1 && cores != by.rbegin()->first) continue;
      // On several cores the saving is shared: core 0's SAD work is about 1/cores of the total.
      const double saved = 3.0 * m.sad_ops / cores;
      std::printf("  %-9s %s: %.1fk cycles -> about %.1fk with a one-cycle SAD (-%.1f%%)\n",
                  gap8_variant(v).name, counted(cores, "core").c_str(), m.cycles / 1000,
                  (m.cycles - saved) / 1000, saved / m.cycles * 100);
    }
  std::printf(
      "\nPer core at the largest core count: IPC (instructions / active cycles), "
      "load stalls, TCDM contention\n");
  for (const auto& [v, by] : in_order(s)) {
    const Measure& m = by.rbegin()->second;
    for (std::size_t c = 0; c < m.cores.size(); ++c) {
      const auto& t = m.cores[c];
      const double active = double(t[GAP8_EVT_ACTIVE_CYCLES]);
      std::printf("  %-9s core %zu: IPC %.3f, instructions %llu, ld_stall %llu, tcdm_cont %llu\n",
                  gap8_variant(v).name, c, active > 0 ? double(t[GAP8_EVT_INSTR]) / active : 0.0,
                  (unsigned long long)t[GAP8_EVT_INSTR], (unsigned long long)t[GAP8_EVT_LD_STALL],
                  (unsigned long long)t[GAP8_EVT_TCDM_CONT]);
    }
  }
}

namespace {
// Cycles, instructions and operations are whole counts, written as JSON integers; the Study keeps
// them as double for its ratios (and the paper's are "k" figures, 624.2 * 1000).
std::int64_t whole(double count) { return std::llround(count); }

using nlohmann::json;

json phases_json(const Phases& p) {
  return json{{"init", whole(p.init)},
              {"dma", whole(p.dma)},
              {"flow", whole(p.flow)},
              {"averaging", whole(p.averaging)},
              {"output", whole(p.output)}};
}

// Per core: its counters and its IPC (instructions / active cycles).
json cores_json(const std::vector<gap8::EventTotals>& cores) {
  json out = json::array();
  for (const auto& t : cores) {
    const double active = double(t[GAP8_EVT_ACTIVE_CYCLES]);
    out.push_back({{"instructions", t[GAP8_EVT_INSTR]},
                   {"active_cycles", t[GAP8_EVT_ACTIVE_CYCLES]},
                   {"ipc", active > 0 ? double(t[GAP8_EVT_INSTR]) / active : 0.0},
                   {"ld_stall", t[GAP8_EVT_LD_STALL]},
                   {"tcdm_cont", t[GAP8_EVT_TCDM_CONT]}});
  }
  return out;
}

// The figures the paper gives (those it does not are left out).
json paper_json(const PaperFigures& p) {
  json pj = json::object();
  auto put = [&](const char* key, std::optional<double> x) {
    if (x) pj[key] = *x;
  };
  auto put_count = [&](const char* key, std::optional<double> x) {
    if (x) pj[key] = whole(*x);
  };
  put_count("cycles", p.cycles);
  put_count("instructions", p.instructions);
  put_count("interpolations", p.interpolations);
  put_count("sad_ops", p.sad_ops);
  put("speedup", p.speedup);
  put("amdahl_limit", p.amdahl_limit);
  put("fps", p.fps);
  if (p.phases) {
    pj["phases"] = {{"init", whole(p.phases->init)},
                    {"dma", whole(p.phases->dma)},
                    {"flow", whole(p.phases->flow)},
                    {"averaging", whole(p.phases->averaging)}};
  }
  return pj;
}

// One variant on one core count: the model's figures, its cores', and the paper's beside them.
json measure_json(const Study& s, Gap8Variant v, int cores, const Measure& m) {
  json e{{"cycles", whole(m.cycles)},
         {"instructions", whole(m.instructions)},
         {"interpolations", whole(m.interpolations)},
         {"sad_ops", whole(m.sad_ops)},
         {"phases", phases_json(m.phases)},
         {"speedup", speedup(s, v, cores)},
         {"amdahl_limit", amdahl_limit(s, v, cores)},
         {"fps", fps(s, m.cycles)},
         {"accepted_pois", m.accepted}};
  e["per_core"] = cores_json(m.cores);
  if (const auto p = paper_for(s, v, cores)) e["paper"] = paper_json(*p);
  return e;
}

}  // namespace

Json to_json(const Study& s) {
  json variants = json::object();
  for (const auto& [v, by] : in_order(s)) {
    json per = json::object();
    for (const auto& [cores, m] : by) per[std::to_string(cores)] = measure_json(s, v, cores, m);
    variants[gap8_variant(v).name] = per;
  }
  json out{{"pair", s.pair_name},
           {"mhz", s.options.mhz},
           {"contention", s.options.contention},
           {"split", s.options.chunked ? "chunked" : "round-robin"},
           {"variants", variants}};
  return out;
}

}  // namespace pxflow::gap8_study
