#include "gap8_study.hpp"

#include <algorithm>
#include <cstring>

#include "errors.hpp"
#include "frame_io.hpp"
#include "frame_ops.hpp"
#include "gap8_backend.hpp"
#include "grid.hpp"
#include "interrupt.hpp"
#include "kernel.hpp"
#include "sample_data.hpp"

namespace pxflow::gap8_study {
namespace {

constexpr double k = 1000.0;

Measure measure(Gap8Variant variant, int cores, const FramePair& pair, const Params& p,
                const Options& o) {
  gap8_host::FlowRunner runner(variant);
  std::vector<PoiRecord> records(poi_count(p));
  const gap8_host::BatchStats stats =
      runner.run({&pair, 1}, p, records, gap8_host::RunOptions{cores, o.contention, o.chunked});
  const pxflow_gap8_result& r = stats.pairs.at(0);
  Measure m;
  m.cycles = r.cycles_total;
  m.phases = {double(r.cycles_init), double(r.cycles_dma), double(r.cycles_flow),
              double(r.cycles_averaging), double(r.cycles_output)};
  m.cores = stats.cores;
  for (const auto& c : stats.cores) m.instructions += double(c[GAP8_EVT_INSTR]);
  const OpCounts counts = gap8_counts(variant, records, p, 1);
  m.interpolations = double(counts.interpolations);
  m.sad_ops = double(counts.sad_ops);
  m.accepted = r.estimate.meancount;
  return m;
}

}  // namespace

std::optional<PaperFigures> paper(Gap8Variant variant, int cores) {
  // Tables I-III of the paper; "k" figures as printed (rounded to 0.1k).
  struct Row {
    Gap8Variant variant;
    double interp, instr, cyc1, cyc8, speedup8, flow1, flow8, amdahl8;
  };
  static const Row rows[] = {{Gap8Variant::kOriginal, 49152, 624.2 * k, 717.2 * k, 99.0 * k, 7.24,
                              711.5 * k, 93.3 * k, 7.578},
                             {Gap8Variant::kLocal, 19200, 585.9 * k, 681.8 * k, 94.5 * k, 7.21,
                              676.1 * k, 88.8 * k, 7.558},
                             {Gap8Variant::kGlobal, 12288, 594.3 * k, 691.3 * k, 96.4 * k, 7.17,
                              685.6 * k, 90.7 * k, 7.563}};
  for (const Row& r : rows) {
    if (variant != r.variant || (cores != 1 && cores != 8)) continue;
    PaperFigures f;
    f.interpolations = r.interp;
    f.sad_ops = 91520;
    f.phases = Phases{0.8 * k, 1.6 * k, cores == 1 ? r.flow1 : r.flow8, 4.1 * k, 0};
    f.cycles = cores == 1 ? r.cyc1 : r.cyc8;
    f.fps = kGap8ClockHz / *f.cycles;  // the paper's clock, the model's
    if (cores == 1) f.instructions = r.instr;
    if (cores == 8) {
      f.speedup = r.speedup8;
      f.amdahl_limit = r.amdahl8;
    }
    return f;
  }
  return std::nullopt;
}

Study run_study(const FramePair& pair, const std::string& pair_name, const Params& p,
                Options options) {
  if (std::find(options.cores.begin(), options.cores.end(), 1) == options.cores.end())
    options.cores.insert(options.cores.begin(), 1);
  std::sort(options.cores.begin(), options.cores.end());
  Study s{options, pair_name, {}};
  std::size_t done = 0;
  const std::size_t runs = options.variants.size() * options.cores.size();
  for (Gap8Variant v : options.variants)
    for (int c : options.cores) {
      stop_if_interrupted(std::to_string(done++) + " of " + std::to_string(runs) + " model runs");
      s.results[v][c] = measure(v, c, pair, p, options);
    }
  return s;
}

NamedFrames default_pair(const Params& p) {
  const std::string dir = std::string(kSampleDataDir) + "/";
  const Frame a = bin(load_frame(dir + "rubberwhale1.png", std::nullopt), 2);
  const Frame b = bin(load_frame(dir + "rubberwhale2.png", std::nullopt), 2);
  for (int y = 0; y + p.height <= a.height; y += 8) {
    for (int x = 0; x + p.width <= a.width; x += 8) {
      NamedFrames f{"", crop(a, x, y, p.width, p.height), crop(b, x, y, p.width, p.height)};
      std::vector<PoiRecord> rec(poi_count(p));
      OpCounts counts;
      reference_flow(RefVariant::kOriginal, {f.prev.view(), f.next.view()}, p, rec, counts);
      if (std::all_of(rec.begin(), rec.end(),
                      [](const PoiRecord& r) { return r.status == kAccepted; })) {
        f.name = "rubberwhale1/2 binned 2x2, window at (" + std::to_string(x) + ", " +
                 std::to_string(y) + ")";
        return f;
      }
    }
  }
  throw InputError("no window of rubberwhale1/2 has every POI accepted; give PREV NEXT");
}

double speedup(const Study& s, Gap8Variant v, int cores) {
  return s.results.at(v).at(1).cycles / s.results.at(v).at(cores).cycles;
}

double amdahl_limit(const Study& s, Gap8Variant v, int cores) {
  const Measure& one = s.results.at(v).at(1);
  const double serial = one.cycles - one.phases.flow;
  return one.cycles / (serial + one.phases.flow / cores);
}

double fps(const Study& s, double cycles) { return s.options.mhz * 1e6 / cycles; }

}  // namespace pxflow::gap8_study
