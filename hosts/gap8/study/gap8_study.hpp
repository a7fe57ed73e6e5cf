// `pxflow gap8`: the kernel's variants on 1..8 simulated cores beside the ISCAS 2022 paper's
// Tables I-III (../shared/paper-iscas2022.tex). Measurement here, printing in gap8_tables.cpp.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frame.hpp"
#include "gap8/perf.h"
#include "gap8_variants.hpp"
#include "params.hpp"
#include "result_json.hpp"

namespace pxflow::gap8_study {

struct Phases {
  double init = 0, dma = 0, flow = 0, averaging = 0, output = 0;
};

// One variant on one core count, on one frame pair.
struct Measure {
  double cycles = 0;        // on core 0, DMA start to records back in L2 (the paper's primary core)
  double instructions = 0;  // every core, the whole run
  double interpolations = 0, sad_ops = 0;
  int accepted = 0;
  Phases phases;
  std::vector<gap8::EventTotals> cores;
};

// The paper's figures for a variant on 1 or 8 cores (absent fields are NaN-free: std::nullopt).
struct PaperFigures {
  std::optional<double> cycles, instructions, interpolations, sad_ops, speedup, amdahl_limit, fps;
  std::optional<Phases> phases;
};
std::optional<PaperFigures> paper(Gap8Variant variant, int cores);

struct Options {
  std::vector<Gap8Variant> variants;
  std::vector<int> cores;
  double mhz = 50;
  bool contention = true;
  bool chunked = false;
  // The problem is the paper's (px4flow-64, 64x64): only then are the paper's figures shown.
  bool paper_problem = true;
};

struct Study {
  Options options;
  std::string pair_name;
  std::map<Gap8Variant, std::map<int, Measure>> results;  // variant -> cores -> measure
};

// Runs every variant on every core count (1 is always measured: speed-ups are relative to it).
Study run_study(const FramePair& pair, const std::string& pair_name, const Params& p,
                Options options);

// The default pair: the first 64x64 window (raster order, step 8) of rubberwhale1/2 binned 2x2
// where ref-original accepts all 64 POIs of px4flow-64. Throws InputError when the frames are
// missing.
struct NamedFrames {
  std::string name;
  Frame prev, next;
};
NamedFrames default_pair(const Params& p);

// Speed-up over 1 core, Amdahl's limit from the 1-core phases (every phase but the flow is
// serial), frames per second at the clock.
double speedup(const Study& s, Gap8Variant variant, int cores);
double amdahl_limit(const Study& s, Gap8Variant variant, int cores);
double fps(const Study& s, double cycles);

// Tables I-III of the paper with the model beside them, one line per figure, already formatted
// ("1027.0k", "7.40x", "+43.2%"; "-" where the paper has no figure). pxflow gap8 prints them;
// pxflow report puts them into the report.
struct PaperLine {
  std::string label, variant, model, paper, diff;
};
struct PaperTable {
  std::string title;
  std::vector<PaperLine> lines;
};
std::vector<PaperTable> paper_tables(const Study& s);

void print_tables(const Study& s);
Json to_json(const Study& s);  // {"variants": {"original": {"1": {...}, ...}, ...}, ...}

}  // namespace pxflow::gap8_study
