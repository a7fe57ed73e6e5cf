#include "vulkan_backend.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstring>
#include <span>
#include <string>

#include "batch_plan.hpp"
#include "command_runner.hpp"
#include "context.hpp"
#include "counted.hpp"
#include "flow_pipeline.hpp"
#include "grid.hpp"
#include "guard_zone.hpp"
#include "host_buffer.hpp"
#include "shader_builds.hpp"
#include "vk_error.hpp"

namespace pxflow {

// The shader writes each record as 8 little-endian words; copying them out as PoiRecord bytes
// is exact only on a little-endian host.
static_assert(std::endian::native == std::endian::little);

namespace {

vk::FlowPushConstants push_constants(const Params& p, const vk::BatchLayout& layout) {
  // The grid of SPEC §2 as the shader needs it: first coordinate, step and count per axis.
  const GridAxis gx = grid_axis_triple(p.width, p);
  const GridAxis gy = grid_axis_triple(p.height, p);
  vk::FlowPushConstants pc{};
  pc.width = static_cast<std::uint32_t>(p.width);
  pc.feature_threshold = static_cast<std::uint32_t>(p.feature_threshold);
  pc.sad_threshold = static_cast<std::uint32_t>(p.sad_threshold);
  pc.grid_x0 = static_cast<std::uint32_t>(gx.first);
  pc.grid_step_x = static_cast<std::uint32_t>(gx.step);
  pc.grid_nx = static_cast<std::uint32_t>(gx.count);
  pc.grid_y0 = static_cast<std::uint32_t>(gy.first);
  pc.grid_step_y = static_cast<std::uint32_t>(gy.step);
  pc.pois_per_pair = static_cast<std::uint32_t>(layout.pois_per_pair);
  pc.words_per_frame = layout.words_per_frame;
  return pc;
}

// `Faults` in kernels/vulkan/shader_checks.glsl, word for word.
struct ShaderFaults {
  std::uint32_t first_fault;  // the first faulting invocation's kind << 16 | line in flow.comp
  std::uint32_t invocations;
};

// What the shader's fault kinds (kFault... in kernels/vulkan/shader_checks.glsl) mean.
std::string describe_shader_fault(std::uint32_t kind) {
  switch (kind) {
    case 1:
      return "indexed past a private array";
    case 2:
      return "read outside its frame";
    default:
      return "reported an unknown fault kind " + std::to_string(kind);
  }
}

// Copies one frame into the buffer as packed rows (stride = width), zeroing the tail words.
void pack_frame(const FrameView& f, std::byte* dst, std::uint32_t words) {
  for (int y = 0; y < f.height; ++y)
    std::memcpy(dst + std::size_t(y) * f.width, f.row(y), std::size_t(f.width));
  const std::size_t used = std::size_t(f.width) * f.height;
  std::memset(dst + used, 0, std::size_t(words) * 4 - used);
}

// The frames buffer's size for `bytes` of frames: never a power of two. lavapipe compiles a
// variant of a pipeline for each kind of texel buffer it reads, and whether the buffer's size is a
// power of two is part of the kind (Mesa's gallivm, lp_bld_sample.h: the static texture state
// embedded in the generated code has `pot_width`, "is the width a power of two?"), so a pipeline
// warmed on one kind compiled again, inside a chunk's wait, on the other (8 s at S=17 with a cold
// shader cache).
std::uint64_t frames_buffer_bytes(std::uint64_t bytes) {
  bytes = std::max<std::uint64_t>(bytes, 12);
  return std::has_single_bit(bytes) ? bytes + 4 : bytes;
}

// Device writes become visible to the host's reads of the mapped records after the fence.
void barrier_to_host(VkCommandBuffer cmd) {
  auto barrier = vk::zeroed<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace

VulkanBackend::VulkanBackend(const VulkanConfig& config)
    : config_(config), shaders_(config.shaders) {
  ctx_ = std::make_unique<vk::Context>(vk::ContextOptions{config.device, config.validation});
  runner_ = std::make_unique<vk::CommandRunner>(*ctx_);
  // A broken pipeline fails create() early.
  for (const VulkanShaders build : {VulkanShaders::checked, VulkanShaders::production})
    ready_pipeline(build, profile(kDefaultProfile));
  fail_on_validation_messages();
}

VulkanBackend::~VulkanBackend() {
  // A chunk whose wait fired may still be running and writing into records_, forever: the context
  // was abandoned then, and the members below leak what they hold instead of waiting for it
  // (Context::abandon). Otherwise children go before the device they were made from.
  if (ctx_ && !ctx_->abandoned()) vkDeviceWaitIdle(ctx_->device());
  faults_.reset();
  records_.reset();
  frames_.reset();
  runner_.reset();
  pipelines_.clear();
  ctx_.reset();
}

std::optional<Backend::DeviceTime> VulkanBackend::last_device_time() const {
  if (!last_device_seconds_) return std::nullopt;
  return DeviceTime{"vulkan-timestamps", *last_device_seconds_ * 1e9, std::nullopt};
}

std::string VulkanBackend::device_name() const { return ctx_->properties().deviceName; }

Backend::Description VulkanBackend::describe() const {
  auto driver = vk::zeroed<VkPhysicalDeviceDriverProperties>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES);
  auto props =
      vk::zeroed<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
  props.pNext = &driver;
  vkGetPhysicalDeviceProperties2(ctx_->physical_device(), &props);
  const std::uint32_t api = props.properties.apiVersion;
  return {"kernels/vulkan/flow.comp (SPIR-V compute shader)",
          device_name() + " (Vulkan " + std::to_string(VK_API_VERSION_MAJOR(api)) + "." +
              std::to_string(VK_API_VERSION_MINOR(api)) + "." +
              std::to_string(VK_API_VERSION_PATCH(api)) + ")",
          std::string(driver.driverName) + ", " + driver.driverInfo};
}

std::string VulkanBackend::device_kind() const {
  switch (ctx_->properties().deviceType) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";  // lavapipe (llvmpipe)
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "gpu";
    default:
      return "other";
  }
}

std::vector<std::string> VulkanBackend::validation_messages() const { return ctx_->messages(); }

std::uint64_t VulkanBackend::buffer_limit() const {
  const auto& limits = ctx_->properties().limits;
  // Frames are read as 4-byte texels (flow_pipeline.cpp), records written as a storage buffer.
  return std::min({std::uint64_t{config_.max_buffer_bytes},
                   std::uint64_t{limits.maxStorageBufferRange},
                   4 * std::uint64_t{limits.maxTexelBufferElements}});
}

std::string VulkanBackend::unsupported(const Params& p) const {
  const vk::BatchLayout layout = vk::batch_layout(p);
  if (vk::pairs_per_chunk(layout, {buffer_limit(), config_.max_chunk_work}) > 0) return {};
  return "a " + std::to_string(p.width) + "x" + std::to_string(p.height) + " frame pair needs " +
         std::to_string(std::max(layout.pair_bytes, layout.record_bytes_per_pair)) +
         " bytes in one storage buffer; the Vulkan device allows " + std::to_string(buffer_limit());
}

std::string VulkanBackend::select_timed(bool timed) {
  shaders_ = timed ? VulkanShaders::production : config_.shaders;
  return vk::shader_name(VulkanShaders::production);
}

void VulkanBackend::prepare(const Params& p) {
  runner_->ensure_usable();
  if (shaders_ != VulkanShaders::production) ready_pipeline(VulkanShaders::checked, p);
  if (shaders_ != VulkanShaders::checked) ready_pipeline(VulkanShaders::production, p);
  fail_on_validation_messages();
}

void VulkanBackend::run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
                        OpCounts&) {
  last_device_seconds_.reset();
  runner_->ensure_usable();
  if (const std::string why = unsupported(p); !why.empty()) vk::fail(why);
  if (shaders_ != VulkanShaders::both) {
    const auto ns = run_shader(shaders_, pairs, p, out);
    if (ns) last_device_seconds_ = *ns * 1e-9;
    return;
  }
  const auto checked_ns = run_shader(VulkanShaders::checked, pairs, p, out);
  std::vector<PoiRecord> production(out.size());
  const auto production_ns = run_shader(VulkanShaders::production, pairs, p, production);
  if (std::memcmp(out.data(), production.data(), out.size_bytes()) != 0)
    vk::fail(vk::shaders_disagree(pairs, p, out, production));
  if (checked_ns && production_ns) last_device_seconds_ = (*checked_ns + *production_ns) * 1e-9;
}

std::optional<double> VulkanBackend::run_shader(VulkanShaders build,
                                                std::span<const FramePair> pairs, const Params& p,
                                                std::span<PoiRecord> out) {
  last_chunks_ = 0;
  last_dispatches_ = 0;
  const vk::BatchLayout layout = vk::batch_layout(p);
  const std::size_t per_chunk =
      vk::pairs_per_chunk(layout, {buffer_limit(), config_.max_chunk_work});
  vk::FlowPipeline& pipeline = ready_pipeline(build, p);
  double device_ns = 0;
  bool timed = true;
  for (std::size_t start = 0; start < pairs.size(); start += per_chunk) {
    const std::size_t n = std::min(per_chunk, pairs.size() - start);
    run_chunk(pipeline, pairs.subspan(start, n), p,
              out.subspan(start * layout.pois_per_pair, n * layout.pois_per_pair));
    const auto ns = runner_->last_device_ns();
    timed = timed && ns.has_value();
    if (ns) device_ns += *ns;
    ++last_chunks_;
  }
  fail_on_validation_messages();
  if (!timed || last_chunks_ == 0) return std::nullopt;
  return device_ns;
}

vk::FlowPipeline& VulkanBackend::ready_pipeline(VulkanShaders build, const Params& p) {
  auto& slot = pipelines_[{build, p.search_radius}];
  if (slot && slot->warmed()) return *slot;
  const auto start = std::chrono::steady_clock::now();
  try {
    if (!slot) {
      const auto& custom =
          build == VulkanShaders::checked ? config_.checked_spirv : config_.production_spirv;
      slot = std::make_unique<vk::FlowPipeline>(
          *ctx_, p.search_radius,
          custom.empty() ? vk::built_in_spirv(build) : std::span<const std::uint32_t>(custom));
    }
    warm(*slot, build, p);
  } catch (...) {
    build_seconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    throw;
  }
  build_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return *slot;
}

// Where the driver compiles a pipeline varies: some at vkCreateComputePipelines, lavapipe at its
// first dispatch, inside the fence wait, where a compile of seconds (a large S, a cold shader
// cache, a busy machine) would count against the allowance of the first chunk's work. So each new
// pipeline runs one dispatch of no work first (item_count 0: every invocation returns at once),
// bound to the backend's own buffers as a chunk binds them, and that wait is build time.
void VulkanBackend::warm(vk::FlowPipeline& pipeline, VulkanShaders build, const Params& p) {
  // No submission is pending: the buffers may be regrown. At least one pair's worth, as a chunk of
  // p binds them: lavapipe compiled again for a chunk after a warm-up on buffers of 12 bytes.
  const vk::BatchLayout layout = vk::batch_layout(p);
  ensure_buffers(layout.pair_bytes, layout.record_bytes_per_pair);
  pipeline.bind_buffers(frames_->buffer(), records_->buffer(), records_front_, faults_->buffer());
  // The problem's own push constants (a driver may specialize on their values), no items.
  vk::FlowPushConstants pc = push_constants(p, layout);
  pc.first_item = 0;
  pc.item_count = 0;
  runner_->run_build(
      [&](VkCommandBuffer cmd) {
        pipeline.bind(cmd);
        pipeline.push(cmd, pc);
        vkCmdDispatch(cmd, 1, 1, 1);
      },
      "the " + vk::shader_name(build) + " at S=" + std::to_string(p.search_radius));
  pipeline.set_warmed();
}

void VulkanBackend::ensure_buffers(std::uint64_t frame_bytes, std::uint64_t record_bytes) {
  const std::uint64_t align =
      std::max<std::uint64_t>(1, ctx_->properties().limits.minStorageBufferOffsetAlignment);
  records_front_ = (kGuardBytes + align - 1) / align * align;
  const std::uint64_t guarded = records_front_ + record_bytes + kGuardBytes;
  if (!faults_) faults_ = std::make_unique<vk::HostBuffer>(*ctx_, sizeof(ShaderFaults));
  if (frames_ && records_ && frames_->size() >= frame_bytes && records_->size() >= guarded) return;
  records_.reset();
  frames_.reset();
  frames_ = std::make_unique<vk::HostBuffer>(*ctx_, frames_buffer_bytes(frame_bytes));
  records_ = std::make_unique<vk::HostBuffer>(*ctx_, guarded);
}

void VulkanBackend::run_chunk(vk::FlowPipeline& pipeline, std::span<const FramePair> pairs,
                              const Params& p, std::span<PoiRecord> out) {
  const vk::BatchLayout layout = vk::batch_layout(p);
  const std::size_t overrun_pairs =
      (config_.overrun_items + layout.pois_per_pair - 1) / layout.pois_per_pair;
  ensure_buffers((pairs.size() + overrun_pairs) * layout.pair_bytes, out.size_bytes());
  for (std::size_t n = 0; n < pairs.size(); ++n) {
    std::byte* prev = frames_->data() + n * layout.pair_bytes;
    pack_frame(pairs[n].prev, prev, layout.words_per_frame);
    pack_frame(pairs[n].next, prev + layout.pair_bytes / 2, layout.words_per_frame);
  }
  // No submission is pending here.
  pipeline.bind_buffers(frames_->buffer(), records_->buffer(), records_front_, faults_->buffer());
  ShaderFaults faults{};
  std::memcpy(faults_->data(), &faults, sizeof(faults));
  auto* const guarded = reinterpret_cast<std::uint8_t*>(records_->data());
  const std::span<std::uint8_t> before(guarded, records_front_);
  const std::span<std::uint8_t> after(guarded + records_front_ + out.size_bytes(),
                                      records_->size() - records_front_ - out.size_bytes());
  fill_guard(before);
  fill_guard(after);
  const std::uint32_t local = pipeline.local_size();
  const std::uint32_t max_groups = config_.max_groups_per_dispatch
                                       ? config_.max_groups_per_dispatch
                                       : ctx_->properties().limits.maxComputeWorkGroupCount[0];
  const std::uint64_t items = out.size() + config_.overrun_items;
  const std::uint64_t per_dispatch = std::uint64_t(max_groups) * local;
  vk::FlowPushConstants pc = push_constants(p, layout);
  runner_->run(
      [&](VkCommandBuffer cmd) {
        pipeline.bind(cmd);
        for (std::uint64_t first = 0; first < items; first += per_dispatch) {
          pc.first_item = static_cast<std::uint32_t>(first);
          pc.item_count = static_cast<std::uint32_t>(std::min(per_dispatch, items - first));
          pipeline.push(cmd, pc);
          vkCmdDispatch(cmd, (pc.item_count + local - 1) / local, 1, 1);
          ++last_dispatches_;
        }
        barrier_to_host(cmd);
      },
      DeviceWork{pairs.size(), layout.pois_per_pair, p.search_radius});
  std::memcpy(out.data(), guarded + records_front_, out.size_bytes());
  std::memcpy(&faults, faults_->data(), sizeof(faults));
  if (faults.invocations != 0)
    vk::fail("kernels/vulkan/flow.comp:" + std::to_string(faults.first_fault & 0xFFFFu) + ": " +
             describe_shader_fault(faults.first_fault >> 16) + " (" +
             counted(faults.invocations, "invocation") +
             " of this chunk; kernels/vulkan/shader_checks.glsl)");
  check_guard_before(before, "vulkan");
  check_guard_after(after, out.size(), "vulkan");
}

void VulkanBackend::fail_on_validation_messages() const {
  const auto messages = ctx_->messages();
  if (!messages.empty())
    vk::fail("validation layer reported " + counted(messages.size(), "message") +
             ", first: " + messages.front());
}

}  // namespace pxflow
