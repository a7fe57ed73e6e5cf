// The backend under the Khronos validation layer: any message (warning or error of any type,
// or any validation message) fails. A deliberate API misuse first proves that the layer is
// loaded and that the messenger sees what it reports, so a silent layer cannot pass.
#include <catch2/catch.hpp>

#include "errors.hpp"
#include "vulkan/context.hpp"
#include "vulkan/vk_error.hpp"
#include "vulkan_test_util.hpp"

using namespace pxflow;
using namespace pxflow::test;

TEST_CASE("vulkan: the validation layer is live and reports a misuse", "[vulkan][validation]") {
  vk::Context ctx({.device = "", .validation = true});
  REQUIRE(ctx.messages().empty());
  // usage = 0 breaks VUID-VkBufferCreateInfo-usage-requiredbitmask; harmless to the driver.
  auto info = vk::zeroed<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = 256;
  VkBuffer buffer = VK_NULL_HANDLE;
  const VkResult r = vkCreateBuffer(ctx.device(), &info, nullptr, &buffer);
  if (r == VK_SUCCESS) vkDestroyBuffer(ctx.device(), buffer, nullptr);
  const auto messages = ctx.messages();
  REQUIRE_FALSE(messages.empty());
  CHECK(messages.front().find("usage") != std::string::npos);
}

TEST_CASE("vulkan: runs clean under the validation layer", "[vulkan][validation]") {
  VulkanConfig config;
  config.validation = true;
  config.max_buffer_bytes = 200000;    // 1 pair of 320x240 or 24 of 64x64 per chunk
  config.max_groups_per_dispatch = 1;  // several dispatches per chunk
  auto vk = make_vulkan(config);
  const Params big = make_params("px4flow-head", 320, 240, 7, 16);
  expect_exact(*vk, random_pairs(320, 240, 7, 2), big);
  const Params p = make_params("px4flow-64", 64, 64);
  expect_exact(*vk, random_pairs(64, 64, p.search_radius, 40), p);  // regrows the buffers
  CHECK(vk->last_chunks() == 2);
  expect_exact(*vk, hostile_pairs(64, 64, p.search_radius), p);
  const auto messages = vk->validation_messages();
  for (const auto& m : messages) UNSCOPED_INFO(m);
  CHECK(messages.empty());
}
