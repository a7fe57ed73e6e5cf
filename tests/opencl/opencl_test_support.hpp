// Shared by the opencl tests: the device requirement, the corpus per profile (with
// frame strides: real-frame windows), and the bit-exact comparison of
// a batch against ref-original through the shared exactness checker.
#pragma once
#include <string>
#include <vector>

#include "exactness.hpp"
#include "frame.hpp"
#include "opencl_backend.hpp"
#include "params.hpp"
#include "synthetic.hpp"

namespace pxflow::test {

// FAILs the current test with the probe's reason unless the opencl row can run here: a
// backend that cannot run is never counted as passed.
void require_opencl_device();

// A named set of frame pairs of one size (views into owned or loaded pixels).
struct Corpus {
  std::string profile;
  Params params;
  std::vector<OwnedPair> owned;
  std::vector<std::string> names;  // one per pair of `pairs`
  std::vector<FramePair> pairs;
};

// px4flow-64 or px4flow-head (64x64): seeded random pairs, every hostile pair, and windows of the
// real OpenCV sample frames (stride = the full image).
const Corpus& corpus(const std::string& profile);

// ref-original's answer for every pair of the corpus, computed once.
const ReferenceAnswer& reference(const std::string& profile);

// Runs the whole corpus as one batch through `backend` into sentinel-filled records and
// compares them with ref-original's through the shared exactness checker
// (hosts/harness/common/exactness.hpp): one line per mismatch, in `pxflow check`'s format, labelled
// "FAIL <who> case=opencl-corpus[<profile>]".
Comparison compare(OpenclBackend& backend, const std::string& profile, const std::string& who);

}  // namespace pxflow::test
