// Shared by the Vulkan tests: backend creation that fails loudly (the build enabled Vulkan, so
// a backend that cannot run here is a failure, not a skip), the bit-exact comparison against
// ref-original through the shared exactness checker, and the real frames cropped to a size.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "params.hpp"
#include "synthetic.hpp"
#include "vulkan/vulkan_backend.hpp"

namespace pxflow::test {

// The backend, or a Catch2 FAIL naming the reason it cannot be created.
std::unique_ptr<VulkanBackend> make_vulkan(const VulkanConfig& config = {});

// Runs all pairs as ONE batch on `backend` through the shared exactness checker
// (hosts/harness/common/exactness.hpp: sentinel-filled records, each compared byte for byte with
// ref-original's, the frame flow by its float bits) and CHECKs that nothing differs.
// Mismatches print in `pxflow check`'s format, labelled "FAIL vulkan case=vulkan-corpus[<WxH S
// B>]" with the pair's name.
void expect_exact(VulkanBackend& backend, const std::vector<OwnedPair>& pairs, const Params& p);
void expect_exact(VulkanBackend& backend, std::span<const FramePair> views,
                  std::span<const std::string> names, const Params& p);

// A named profile with overrides, validated.
Params make_params(const std::string& profile, int width, int height, int search_radius = -1,
                   int blocks = -1);

// The OpenCV sample frame pairs (rubberwhale, basketball) cropped at the top left to w x h, or
// whole when w and h are 0 (then both frames must have the same size).
std::vector<OwnedPair> real_pairs(int w = 0, int h = 0);

// `n` random pairs from seeds first_seed, first_seed + 1, ...
std::vector<OwnedPair> random_pairs(int w, int h, int search_radius, int n,
                                    std::uint64_t first_seed = 1);

}  // namespace pxflow::test
