// The two builds of kernels/vulkan/flow.comp (kernels/vulkan/shader_checks.glsl): copies with one
// planted fault each (tests/vulkan/CMakeLists.txt) that only the checked build's checks of itself
// show on lavapipe, and a wrong production build, which `pxflow check` (both builds) must name
// and bench's timed runs (the production build alone) would not see.
#include <catch2/catch.hpp>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "build_paths.hpp"
#include "errors.hpp"
#include "flow_production_wrong_y_spv.h"
#include "flow_search_above_frame_spv.h"
#include "flow_sub7_unwritten_spv.h"
#include "flow_vote_past_sub_spv.h"
#include "grid.hpp"
#include "vulkan_test_util.hpp"

using namespace pxflow;
using namespace pxflow::test;
using Catch::Matchers::Contains;

namespace {

// A run of random pairs at px4flow-64, which the built-in shaders get right, with `config`
// (its planted SPIR-V and the builds it runs).
struct PlantedRun {
  std::vector<PoiRecord> right;    // the built-in shaders' records
  std::vector<PoiRecord> records;  // the planted run's
  std::string error;  // the planted run's BackendError message, empty when it went through
};

PlantedRun run_planted(const VulkanConfig& config, bool timed = false) {
  const Params p = make_params("px4flow-64", 64, 64);
  const std::vector<OwnedPair> pairs = random_pairs(64, 64, p.search_radius, 4, 11);
  std::vector<FramePair> views;
  for (const auto& pair : pairs) views.push_back(pair.view());
  PlantedRun planted{std::vector<PoiRecord>(views.size() * poi_count(p)),
                     std::vector<PoiRecord>(views.size() * poi_count(p)), ""};
  OpCounts counts;
  CHECK_NOTHROW(make_vulkan()->run(views, p, planted.right, counts));
  try {
    auto vk = make_vulkan(config);
    vk->select_timed(timed);
    vk->run(views, p, planted.records, counts);
  } catch (const BackendError& e) {
    planted.error = e.what();
  }
  return planted;
}

template <std::size_t N>
std::vector<std::uint32_t> spirv(const std::uint32_t (&code)[N]) {
  return {std::begin(code), std::end(code)};
}

// Runs `code` as the checked build, in `shaders`.
template <std::size_t N>
PlantedRun run_checked(const std::uint32_t (&code)[N], VulkanShaders shaders) {
  VulkanConfig config;
  config.shaders = shaders;
  config.checked_spirv = spirv(code);
  return run_planted(config);
}

// The source line of flow.comp that a shader fault's message names.
std::string named_line(const std::string& message) {
  const auto at = message.find("flow.comp:") + std::string("flow.comp:").size();
  const int line = std::stoi(message.substr(at));
  std::ifstream source(build_paths::vulkan_shader_source);
  std::string text;
  for (int n = 1; n <= line && std::getline(source, text); ++n) {
  }
  return text;
}

}  // namespace

TEST_CASE("vulkan: an index past a private array is the shader's failure, naming its line",
          "[vulkan]") {
  // The vote loop one step too long reads sub[8]: lavapipe's records stay right, so only the
  // bounds checks of kernels/vulkan/shader_checks.glsl can fail it. Run as pxflow check runs it.
  const PlantedRun run = run_checked(k_flow_vote_past_sub_spirv, VulkanShaders::both);
  INFO(run.error);
  REQUIRE_THAT(run.error, Contains("vulkan: kernels/vulkan/flow.comp:") &&
                              Contains(": indexed past a private array ("));
  CHECK_THAT(named_line(run.error), Contains("AT(sub, k) < vote"));
}

TEST_CASE("vulkan: a read outside the invocation's frame is the shader's failure, naming its line",
          "[vulkan]") {
  // The search starting two rows too high reads the row above the frame (in the buffer: the other
  // frame of the pair, or the pair before); only the frame check of shader_checks.glsl sees it.
  const PlantedRun run = run_checked(k_flow_search_above_frame_spirv, VulkanShaders::checked);
  INFO(run.error);
  REQUIRE_THAT(run.error, Contains("vulkan: kernels/vulkan/flow.comp:") &&
                              Contains(": read outside its frame (") &&
                              Contains(" invocations of this chunk"));
  CHECK_THAT(named_line(run.error), Contains("FRAME_WORD(kNext, q)"));
}

TEST_CASE("vulkan: a private element the kernel never writes changes the records (poison)",
          "[vulkan]") {
  // The half-pixel sums cleared one short leave sub[7] unwritten. Lavapipe's uninitialised value
  // is 0, which would give the right sum; the poison of shader_checks.glsl makes every accepted
  // POI's sub[7] wrong instead.
  const PlantedRun run = run_checked(k_flow_sub7_unwritten_spirv, VulkanShaders::checked);
  REQUIRE(run.error.empty());
  int accepted = 0;
  for (std::size_t i = 0; i < run.right.size(); ++i) {
    const PoiRecord& right = run.right[i];
    if (right.status != kAccepted) continue;
    ++accepted;
    INFO("record " << i);
    CHECK(run.records[i].sub[7] != right.sub[7]);
    CHECK(std::memcmp(run.records[i].sub, right.sub, 7 * sizeof(right.sub[0])) == 0);
  }
  CHECK(accepted > 0);
}

TEST_CASE("vulkan: both builds run, and the one that differs from ref-original is named",
          "[vulkan]") {
  // Beside the built-in production build, the poisoned sub[7] of the checked build is the wrong
  // one; beside the built-in checked build, a production build with every y one too large is.
  const PlantedRun checked = run_checked(k_flow_sub7_unwritten_spirv, VulkanShaders::both);
  CHECK_THAT(checked.error, Contains("vulkan: the checked and production shaders wrote different "
                                     "records, first for pair 0 POI ") &&
                                Contains("): the checked shader's record differs from "
                                         "ref-original's there"));
  VulkanConfig config;
  config.production_spirv = spirv(k_flow_production_wrong_y_spirv);
  const PlantedRun production = run_planted(config);
  CHECK_THAT(production.error,
             Contains("first for pair 0 POI 0 (x=") &&
                 Contains("): the production shader's record differs from ref-original's there"));
}

TEST_CASE("vulkan: bench's timed runs run the production build alone", "[vulkan]") {
  VulkanConfig config;
  config.production_spirv = spirv(k_flow_production_wrong_y_spirv);
  CHECK(make_vulkan(config)->select_timed(true) == "production shader");
  const PlantedRun run = run_planted(config, true);
  REQUIRE(run.error.empty());
  for (std::size_t i = 0; i < run.right.size(); ++i) {
    INFO("record " << i);
    CHECK(run.records[i].y == run.right[i].y + 1);
  }
}
