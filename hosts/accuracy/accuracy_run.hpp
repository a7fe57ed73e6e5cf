// `pxflow accuracy`: pxflow, OpenCV's Lucas-Kanade and OpenCV's DIS flow on the same frames,
// error against known motion (synthetic pairs) or agreement with DIS (real video), and the time
// per frame of each, all measured in one run, pair by pair.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "backend.hpp"
#include "params.hpp"
#include "sample_data.hpp"

namespace pxflow::accuracy {

struct AccuracyOptions {
  std::string backend;  // a registry name
  BackendOptions backend_options;
  int threads = 1;      // OpenCV's threads and the backend's, for a like-for-like clock
  int pairs = 200;      // synthetic pairs at 64x64; a quarter of that (at least 1) at 320x240
  int video_pairs = 6;  // per video (vtest.avi, tree.avi); 0 leaves the videos out
  std::uint64_t seed = 1;
  std::string data_dir = kSampleDataDir;
  bool by_kind = false;  // also one block of rows per kind of motion
};

// One row of the table.
struct MethodRow {
  std::string method;  // "pxflow (cpu)", "LK", "DIS"
  int frames = 0;
  int valid = 0;                         // frames with a flow (see FlowEstimate::valid)
  bool has_error = true;                 // false for DIS where DIS is the reference
  double mean_error = 0, p95_error = 0;  // pixels, Euclidean
  double median_us = 0;                  // time per frame, steady_clock
};

// The rows of one set of pairs.
struct SetRows {
  std::string set;      // e.g. "synthetic camera 64x64", "vtest.avi 768x576"
  std::string setting;  // pxflow's parameters, e.g. "px4flow-64"
  std::string against;  // "true motion" or "DIS (agreement, not ground truth)"
  std::vector<MethodRow> rows;
};

struct AccuracyReport {
  std::vector<std::string> images;  // the source images of the synthetic pairs
  std::vector<SetRows> sets;
};

// The real videos of the agreement rows and the report's flow pictures, in opencv-doc's folder.
inline constexpr const char* kVideos[] = {"vtest.avi", "tree.avi"};

// pxflow's setting for a real video's frames: px4flow-64 at their size with S=7, B=32 (as
// pxflow check's real frames); the agreement rows and the report's flow pictures use it.
Params video_setting(int width, int height);
// Its name, made from it: "px4flow-64 S=7 B=32".
std::string video_setting_name(const Params& p);

// Throws InputError unless o.backend runs here and supports every set of pairs run_accuracy
// makes (a backend with a small memory may not take the videos' frames): called before any work.
void require_backend_runs(const AccuracyOptions& o);

// Throws InputError for a missing data file, an unknown backend or one that cannot run here.
AccuracyReport run_accuracy(const AccuracyOptions& o);

// The report as a Markdown table with a header naming the backend, clock and threads.
std::string format_accuracy(const AccuracyReport& r, const AccuracyOptions& o);

}  // namespace pxflow::accuracy
