// The inputs the CPU kernels are checked on, and the check itself: the harness's exactness
// checker (hosts/harness/common/exactness.hpp), so a mismatch is the same line as in `pxflow
// check`. Pure C++ so that the NEON cross test, built for AArch64 without OpenCV, shares it; real
// frames are added by the callers that can load them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "exactness.hpp"
#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow::cpu_test {

// One frame pair with its own pixels and a row stride that may exceed the width.
struct Case {
  std::string name;
  int width = 0, height = 0;
  std::ptrdiff_t stride = 0;
  std::vector<std::uint8_t> prev, next;  // stride * (height - 1) + width bytes: nothing after
  FramePair view() const {
    return {{width, height, stride, prev.data()}, {width, height, stride, next.data()}};
  }
};

// Cases sharing one set of parameters: checked as one batch.
struct Group {
  std::string name;     // e.g. "synthetic", "real/rubberwhale 64x64 crops"
  std::string setting;  // the parameter set, e.g. "px4flow-64", "96x80 S=13 B=3"
  Params params;
  std::vector<Case> cases;
};

// A case from packed pixels, re-laid with `stride` (>= width); the last row ends the buffer
// so that a read past the frame is a read past the allocation.
Case make_case(std::string name, int width, int height, std::ptrdiff_t stride,
               const std::uint8_t* prev, const std::uint8_t* next, std::ptrdiff_t src_stride);

// Seeded random pairs (`seeds` per group at 64x64, fewer at larger sizes) and every hostile
// pair, at px4flow-64, px4flow-head, 320x240 (S=7, B=16) and wide radii (S=13, S=31) that
// exercise the multi-chunk paths. Some cases get an odd stride.
std::vector<Group> synthetic_corpus(int seeds);

// One real frame pair (packed, width x height) as groups: the whole frame with px4flow-64,
// px4flow-head and S=7 B=32, and 64x64 crops at px4flow-64 that keep the frame's stride.
std::vector<Group> real_groups(const std::string& name, int width, int height,
                               const std::uint8_t* prev, const std::uint8_t* next);

// Runs a whole group as one batch through `run` with check_exact (sentinel-filled output, every
// record and the frame flow compared with ref-original) and prints its mismatch lines, "FAIL
// <who> case=<group>[<setting>] pair=<case> poi=..." as `pxflow check` does. True when it matched.
bool check_group(const std::string& who, const Group& g, const BatchRun& run);

}  // namespace pxflow::cpu_test
