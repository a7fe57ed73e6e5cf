#include "command_runner.hpp"

#include "errors.hpp"
#include "interrupt.hpp"
#include "vk_error.hpp"

namespace pxflow::vk {

CommandRunner::CommandRunner(Context& ctx)
    : ctx_(&ctx),
      device_(ctx.device()),
      queue_(ctx.queue()),
      timestamp_bits_(ctx.timestamp_valid_bits()),
      timestamp_period_(ctx.properties().limits.timestampPeriod) {
  try {
    auto pool = zeroed<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = ctx.queue_family();
    check(vkCreateCommandPool(device_, &pool, nullptr, &pool_), "vkCreateCommandPool");
    auto alloc =
        zeroed<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device_, &alloc, &cmd_), "vkAllocateCommandBuffers");
    auto fence = zeroed<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    check(vkCreateFence(device_, &fence, nullptr, &fence_), "vkCreateFence");
    if (timestamp_bits_ > 0) {
      auto q = zeroed<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
      q.queryType = VK_QUERY_TYPE_TIMESTAMP;
      q.queryCount = 2;
      check(vkCreateQueryPool(device_, &q, nullptr, &queries_), "vkCreateQueryPool");
    }
  } catch (...) {
    release();
    throw;
  }
}

CommandRunner::~CommandRunner() { release(); }

void CommandRunner::release() {
  // A command buffer still pending after a wait that fired may never finish: waiting for it
  // (vkDeviceWaitIdle) would hang, so its pool, fence and queries are leaked with the context.
  if (ctx_->abandoned()) return;
  // After a lost device nothing runs any more; vkDeviceWaitIdle returns at once.
  if (!broken_.empty()) vkDeviceWaitIdle(device_);
  if (queries_) vkDestroyQueryPool(device_, queries_, nullptr);
  if (fence_) vkDestroyFence(device_, fence_, nullptr);
  if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);  // frees cmd_ too
  queries_ = VK_NULL_HANDLE;
  fence_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
}

void CommandRunner::run(const std::function<void(VkCommandBuffer)>& body, const DeviceWork& work) {
  submit(body);
  wait(work);
  read_timestamps();
}

void CommandRunner::run_build(const std::function<void(VkCommandBuffer)>& body,
                              const std::string& what) {
  submit(body);
  wait_build(what);
  last_ns_.reset();  // a build's dispatch is no chunk's time
}

void CommandRunner::submit(const std::function<void(VkCommandBuffer)>& body) {
  ensure_usable();
  record(body);
  check(vkResetFences(device_, 1, &fence_), "vkResetFences");
  auto info = zeroed<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  info.commandBufferCount = 1;
  info.pCommandBuffers = &cmd_;
  const VkResult r = vkQueueSubmit(queue_, 1, &info, fence_);
  if (r == VK_ERROR_DEVICE_LOST) broken_ = "device lost at vkQueueSubmit";
  check(r, "vkQueueSubmit");
}

void CommandRunner::ensure_usable() const {
  if (!broken_.empty()) fail("device unusable after an earlier failure: " + broken_);
}

void CommandRunner::record(const std::function<void(VkCommandBuffer)>& body) {
  check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
  auto begin = zeroed<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer");
  if (queries_) {
    vkCmdResetQueryPool(cmd_, queries_, 0, 2);
    vkCmdWriteTimestamp(cmd_, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries_, 0);
  }
  body(cmd_);
  if (queries_) vkCmdWriteTimestamp(cmd_, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries_, 1);
  check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
}

void CommandRunner::wait(const DeviceWork& work) {
  const auto start = std::chrono::steady_clock::now();
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(wait_allowance(work));
  const VkResult r =
      vkWaitForFences(device_, 1, &fence_, VK_TRUE, static_cast<std::uint64_t>(ns.count()));
  if (r == VK_TIMEOUT) {
    const std::chrono::duration<double> waited = std::chrono::steady_clock::now() - start;
    give_up(wait_failure_line("vulkan", waited.count(), work));
  }
  if (r == VK_ERROR_DEVICE_LOST) broken_ = "device lost";
  check(r, "vkWaitForFences");
}

void CommandRunner::wait_build(const std::string& what) {
  constexpr std::uint64_t kSliceNs = 100'000'000;  // how soon a stop signal is noticed
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const VkResult r = vkWaitForFences(device_, 1, &fence_, VK_TRUE, kSliceNs);
    if (r != VK_TIMEOUT) {
      if (r == VK_ERROR_DEVICE_LOST) broken_ = "device lost";
      check(r, "vkWaitForFences");
      return;
    }
    if (interrupt_signal() != 0) {
      broken_ = "stopped while building " + what;
      ctx_->abandon();  // the compile may still run: nothing waits for it
      stop_if_interrupted_while("building " + what);
    }
    const std::chrono::duration<double> waited = std::chrono::steady_clock::now() - start;
    if (waited.count() >= kBuildSeconds)
      give_up("vulkan: building " + what +
              " (its first dispatch, which makes the driver compile it) " +
              "did not finish within " + setting_text(kBuildSeconds) + " s: the driver hangs");
  }
}

// The wait fired while the command buffer may still run: the runner refuses further work, and
// nothing made from the context is destroyed (Context::abandon).
void CommandRunner::give_up(const std::string& line) {
  broken_ = line;
  ctx_->abandon();
  throw BackendError(line);
}

void CommandRunner::read_timestamps() {
  last_ns_.reset();
  if (!queries_) return;
  std::uint64_t stamps[2] = {};
  check(
      vkGetQueryPoolResults(device_, queries_, 0, 2, sizeof(stamps), stamps, sizeof(std::uint64_t),
                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
      "vkGetQueryPoolResults");
  const std::uint64_t mask =
      timestamp_bits_ >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << timestamp_bits_) - 1;
  const std::uint64_t ticks = ((stamps[1] & mask) - (stamps[0] & mask)) & mask;
  last_ns_ = static_cast<double>(ticks) * static_cast<double>(timestamp_period_);
}

}  // namespace pxflow::vk
