// `vulkan` against ref-original through the shared exactness checker, on the corpus of the
// correctness bar: seeded random pairs, hostile patterns and real frames at px4flow-64,
// px4flow-head and larger frames, plus the layouts the host must get right (odd widths,
// strides, S = 31).
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "build_paths.hpp"
#include "record.hpp"
#include "vulkan_test_util.hpp"

using namespace pxflow;
using namespace pxflow::test;

namespace {

void corpus_at(VulkanBackend& vk, const Params& p, int random_count) {
  expect_exact(vk, random_pairs(p.width, p.height, p.search_radius, random_count), p);
  expect_exact(vk, hostile_pairs(p.width, p.height, p.search_radius), p);
}

}  // namespace

TEST_CASE("vulkan: corpus at px4flow-64 is bit-exact with ref-original", "[vulkan]") {
  auto vk = make_vulkan();
  const Params p = make_params("px4flow-64", 64, 64);
  corpus_at(*vk, p, 500);
  expect_exact(*vk, real_pairs(64, 64), p);
}

TEST_CASE("vulkan: the production build alone, as bench times it, is bit-exact", "[vulkan]") {
  // make_vulkan()'s run() runs both builds (VulkanShaders::both), as every other case here does.
  auto vk = make_vulkan();
  vk->select_timed(true);
  const Params p = make_params("px4flow-64", 64, 64);
  corpus_at(*vk, p, 100);
  expect_exact(*vk, real_pairs(64, 64), p);
}

TEST_CASE("vulkan: corpus at px4flow-head is bit-exact with ref-original", "[vulkan]") {
  auto vk = make_vulkan();
  const Params p = make_params("px4flow-head", 64, 64);
  corpus_at(*vk, p, 500);
  expect_exact(*vk, real_pairs(64, 64), p);
}

TEST_CASE("vulkan: 320x240 S=7 B=16 is bit-exact with ref-original", "[vulkan]") {
  auto vk = make_vulkan();
  const Params p = make_params("px4flow-64", 320, 240, 7, 16);
  corpus_at(*vk, p, 24);
  expect_exact(*vk, real_pairs(320, 240), p);
}

TEST_CASE("vulkan: whole real frames at S=7 B=32 are bit-exact with ref-original", "[vulkan]") {
  auto vk = make_vulkan();
  for (const auto& pair : real_pairs()) {
    INFO(pair.name);
    expect_exact(*vk, {pair}, make_params("px4flow-64", pair.width, pair.height, 7, 32));
  }
  const Params p = make_params("px4flow-head", 640, 480, 7, 32);
  expect_exact(*vk, random_pairs(640, 480, 7, 4), p);
}

TEST_CASE("vulkan: every search radius, odd sizes and S = 31 are bit-exact", "[vulkan]") {
  auto vk = make_vulkan();
  for (int s = 1; s <= 9; ++s) {
    INFO("S=" << s);
    corpus_at(*vk, make_params("px4flow-64", 64, 64, s), 40);
  }
  // Widths that are not a multiple of 4: rows start mid-word in the packed frame.
  corpus_at(*vk, make_params("px4flow-64", 67, 53, 4, 5), 40);
  corpus_at(*vk, make_params("px4flow-head", 81, 79, 3, 6), 40);
  corpus_at(*vk, make_params("px4flow-64", 128, 128, 31, 2), 10);
}

TEST_CASE("vulkan: frames with a row stride larger than the width", "[vulkan]") {
  auto vk = make_vulkan();
  const Params p = make_params("px4flow-64", 64, 64);
  const auto pairs = random_pairs(64, 64, p.search_radius, 16, 900);
  // The same pixels with 13 bytes of garbage after each row.
  const int stride = 64 + 13;
  std::vector<std::vector<std::uint8_t>> storage;
  std::vector<FramePair> strided;
  for (const auto& op : pairs) {
    FramePair fp{};
    for (int k = 0; k < 2; ++k) {
      const auto& src = k == 0 ? op.prev : op.next;
      std::vector<std::uint8_t> buf(std::size_t(stride) * 64, 0xEE);
      for (int y = 0; y < 64; ++y)
        std::copy(src.begin() + y * 64, src.begin() + y * 64 + 64, buf.begin() + y * stride);
      storage.push_back(std::move(buf));
      (k == 0 ? fp.prev : fp.next) = {64, 64, stride, storage.back().data()};
    }
    strided.push_back(fp);
  }
  std::vector<std::string> names;
  for (const auto& op : pairs) names.push_back(op.name + "/stride77");
  expect_exact(*vk, strided, names, p);
}

TEST_CASE("vulkan: the shader's status and direction values are reference/record.hpp's",
          "[vulkan]") {
  std::ifstream file(build_paths::vulkan_shader_source, std::ios::binary);
  REQUIRE(file);
  std::ostringstream text;
  text << file.rdbuf();
  const std::string source = text.str();
  for (const auto& [name, value] :
       {std::pair{"kStatusDropped", int{kDropped}}, std::pair{"kStatusRejected", int{kRejected}},
        std::pair{"kStatusAccepted", int{kAccepted}}, std::pair{"kDirNone", int{kDirNone}}}) {
    const std::string line =
        "const uint " + std::string(name) + " = " + std::to_string(value) + "u;";
    INFO(line);
    CHECK(source.find(line) != std::string::npos);
  }
}
