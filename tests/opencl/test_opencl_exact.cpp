// Bit-exact where the layouts differ from a plain run: several work-group sizes and forced
// chunking, for both kernel layouts (the rows opencl-item and opencl-group), whose records must
// equal ref-original's byte for byte. The fixed corpus on each row is its conformance test
// (tests/conformance). Mismatches print in `pxflow check`'s format.
#include <catch2/catch.hpp>

#include "opencl_test_support.hpp"
#include "registry.hpp"

namespace pxflow::test {
namespace {

std::string row_of(OpenclLayout layout) {
  return layout == OpenclLayout::kGroupPerPoi ? "opencl-group" : "opencl-item";
}

// Runs `profile`'s corpus as one batch and fails with the first differing records.
void check_corpus(const std::string& profile, const OpenclTuning& tuning) {
  OpenclBackend backend({}, tuning);
  const std::string who =
      row_of(backend.layout()) + "(group size " + std::to_string(backend.group_size()) + ")";
  const Comparison c = compare(backend, profile, who);
  INFO(who << " on " << profile << " [" << corpus(profile).pairs.size()
           << " pairs]: " << c.mismatches << " mismatches\n"
           << c.text());
  CHECK(c.ok());
}

}  // namespace

TEST_CASE("opencl: is bit-exact at any work-group size", "[opencl]") {
  require_opencl_device();
  // 1: one item does every candidate; 7: candidates do not divide evenly; 256: idle items.
  for (std::size_t size : {1, 7, 32, 256})
    check_corpus("px4flow-head", {OpenclLayout::kGroupPerPoi, size, 0});
  check_corpus("px4flow-head", {OpenclLayout::kItemPerPoi, 1, 0});
}

TEST_CASE("opencl: the default layout follows the device type", "[opencl]") {
  require_opencl_device();
  OpenclBackend backend({});
  const bool cpu = cl::choose_device(cl::list_devices(), "").cpu;
  CHECK(backend.layout() == (cpu ? OpenclLayout::kItemPerPoi : OpenclLayout::kGroupPerPoi));
}

TEST_CASE("opencl: every kernel layout is a registry row", "[opencl]") {
  require_opencl_device();
  for (auto [name, layout] : {std::pair{"opencl-item", OpenclLayout::kItemPerPoi},
                              std::pair{"opencl-group", OpenclLayout::kGroupPerPoi}}) {
    INFO(name);
    const auto backend = find_backend(name).create({});
    const auto* opencl = dynamic_cast<const OpenclBackend*>(backend.get());
    REQUIRE(opencl != nullptr);
    CHECK(opencl->layout() == layout);
  }
}

TEST_CASE("opencl: splits a batch larger than its buffer limit into exact chunks", "[opencl]") {
  require_opencl_device();
  const std::size_t pair_bytes = 2 * 64 * 64;
  for (auto layout : {OpenclLayout::kGroupPerPoi, OpenclLayout::kItemPerPoi}) {
    OpenclBackend backend({}, {layout, 0, 7 * pair_bytes});  // 7 pairs per launch
    const Comparison c = compare(backend, "px4flow-64", row_of(layout) + "(7-pair chunks)");
    INFO(c.mismatches << " mismatches\n" << c.text());
    CHECK(c.ok());
    const auto pairs = corpus("px4flow-64").pairs.size();
    CHECK(backend.last_timing().launches == static_cast<int>((pairs + 6) / 7));
  }
}

}  // namespace pxflow::test
