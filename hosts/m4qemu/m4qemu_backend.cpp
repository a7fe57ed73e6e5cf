#include "m4qemu_backend.hpp"

#include <cmath>

#include "grid.hpp"

namespace pxflow::m4qemu {

// The Cortex-M4's widest SAD instruction, USADA8, compares 4 bytes: no code does the SAD work in
// fewer instructions than one per 4 bytes (loads and the search's bookkeeping not counted).
std::optional<Backend::DeviceBound> M4QemuBackend::device_bound(const Params& p) const {
  return DeviceBound{"the SAD work at one USADA8 (4 bytes) per instruction, no load",
                     "instructions",
                     sad_bytes_per_frame(static_cast<long>(poi_count(p)), p.search_radius) / 4.0};
}

M4QemuBackend::M4QemuBackend(std::shared_ptr<dut::Device> device)
    : device_(device), inner_(std::move(device)) {}

void M4QemuBackend::run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
                        OpCounts& counts) {
  last_time_.reset();
  OpCounts ignored;
  inner_.run(pairs, p, out, ignored);
  counts += m4_counts(out, p);
  std::optional<DeviceTime> t = inner_.last_device_time();
  if (!t) return;
  // The firmware's counter ticks are instructions at counter_hz = 1e9 / 2^shift per virtual
  // second (boards/mps2-an386/dut_main.c); DutBackend gave ns = ticks / counter_hz * 1e9.
  const double hz = device_->hello().counter_hz;
  t->instructions = std::round(t->ns * hz / 1e9);
  t->cycles.reset();
  t->exact = true;
  last_time_ = t;
}

OpCounts m4_counts(std::span<const PoiRecord> records, const Params& p) {
  OpCounts c;
  c.counted = true;
  const std::uint64_t candidates = (2 * p.search_radius + 1) * (2 * p.search_radius + 1);
  for (const PoiRecord& r : records) {
    c.sad_ops += 6;
    if (r.status != kDropped) c.sad_ops += 16 * candidates;
    if (r.status == kAccepted) c.sad_ops += 128, c.interpolations += 768;
  }
  return c;
}

}  // namespace pxflow::m4qemu
