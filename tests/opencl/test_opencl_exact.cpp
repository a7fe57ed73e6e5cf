// Bit-exact: the opencl backend's records equal ref-original's, byte for byte, on the corpus at
// every profile, for both work decompositions, several work-group sizes and forced chunking.
#include <catch2/catch.hpp>

#include "opencl_test_support.hpp"

namespace pxflow::test {
namespace {

// Runs `profile`'s corpus as one batch and fails with the first differing records.
void check_exact(const std::string& profile, const OpenclTuning& tuning, const std::string& what) {
  OpenclBackend backend({}, tuning);
  const auto lines = mismatches(backend, profile);
  std::string shown;
  for (std::size_t i = 0; i < lines.size() && i < 10; ++i) shown += "\n  " + lines[i];
  INFO("opencl (" << what << ", group size " << backend.group_size() << ") on " << profile << " ["
                  << corpus(profile).pairs.size() << " pairs]: " << lines.size()
                  << " records differ from ref-original" << shown);
  CHECK(lines.empty());
}

void check_both_layouts(const std::string& profile) {
  require_opencl_device();
  check_exact(profile, {OpenclLayout::kGroupPerPoi, 0, 0}, "group-per-poi");
  check_exact(profile, {OpenclLayout::kItemPerPoi, 0, 0}, "item-per-poi");
}

}  // namespace

TEST_CASE("opencl: is bit-exact on the px4flow-64 corpus", "[opencl]") {
  check_both_layouts("px4flow-64");
}

TEST_CASE("opencl: is bit-exact on the px4flow-head corpus", "[opencl]") {
  check_both_layouts("px4flow-head");
}

TEST_CASE("opencl: is bit-exact at the largest search radius, S=31", "[opencl]") {
  check_both_layouts("128x128-S31");
}

TEST_CASE("opencl: is bit-exact on the 320x240 S=7 B=16 corpus", "[opencl]") {
  check_both_layouts("320x240");
}

TEST_CASE("opencl: is bit-exact on the 640x480 S=7 B=32 corpus", "[opencl]") {
  check_both_layouts("640x480");
}

TEST_CASE("opencl: is bit-exact at any work-group size", "[opencl]") {
  require_opencl_device();
  // 1: one item does every candidate; 7: candidates do not divide evenly; 256: idle items.
  for (std::size_t size : {1, 7, 32, 256})
    check_exact("px4flow-head", {OpenclLayout::kGroupPerPoi, size, 0},
                "group-per-poi, asked for " + std::to_string(size));
  check_exact("px4flow-head", {OpenclLayout::kItemPerPoi, 1, 0}, "item-per-poi");
}

TEST_CASE("opencl: the default layout follows the device type", "[opencl]") {
  require_opencl_device();
  OpenclBackend backend({});
  const bool cpu = cl::choose_device(cl::list_devices(), "").cpu;
  CHECK(backend.layout() == (cpu ? OpenclLayout::kItemPerPoi : OpenclLayout::kGroupPerPoi));
}

TEST_CASE("opencl: splits a batch larger than its buffer limit into exact chunks", "[opencl]") {
  require_opencl_device();
  const std::size_t pair_bytes = 2 * 64 * 64;
  for (auto layout : {OpenclLayout::kGroupPerPoi, OpenclLayout::kItemPerPoi}) {
    OpenclBackend backend({}, {layout, 0, 7 * pair_bytes});  // 7 pairs per launch
    const auto lines = mismatches(backend, "px4flow-64");
    INFO(lines.size() << " records differ; first: " << (lines.empty() ? "" : lines.front()));
    CHECK(lines.empty());
    const auto pairs = corpus("px4flow-64").pairs.size();
    CHECK(backend.last_timing().launches == static_cast<int>((pairs + 6) / 7));
  }
}

}  // namespace pxflow::test
