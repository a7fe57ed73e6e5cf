// The m4-qemu backend: the dut family's DutBackend over QEMU, with what only this row knows.
// Under -icount the device's counter counts instructions and, with nothing but the kernel between
// its two reads, the same count every run to within its tick (5 instructions: the tick's phase
// depends on how long the core slept before): the row's device time is exact (one checked run is
// the measurement, like the GAP8 model's cycles) and is reported as instructions, never cycles.
#pragma once
#include <memory>
#include <optional>

#include "backend.hpp"
#include "dut_backend.hpp"

namespace pxflow::m4qemu {

class M4QemuBackend : public Backend {
 public:
  explicit M4QemuBackend(std::shared_ptr<dut::Device> device);
  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override;
  std::string unsupported(const Params& p) const override { return inner_.unsupported(p); }
  std::optional<DeviceTime> last_device_time() const override { return last_time_; }
  // The firmware's HELLO name and build, on QEMU's emulated board.
  Description describe() const override {
    Description d = inner_.describe();
    d.device = "Cortex-M4 on qemu-system-arm -M mps2-an386 (" + d.device + ")";
    return d;
  }
  // The SAD work at one USADA8 (4 bytes) per instruction, in instructions as the row's clock
  // counts them (docs/harness.md, "The bound of every row").
  std::optional<DeviceBound> device_bound(const Params& p) const override;

 private:
  std::shared_ptr<dut::Device> device_;
  dut::DutBackend inner_;
  std::optional<DeviceTime> last_time_;
};

// The firmware's work as docs/counting.md charges it, from the records (the kernel of
// kernels/cortex-m4 does exactly this): USAD8/USADA8 instructions (6 per POI for the feature,
// 16 per candidate of a searched POI, 128 for an accepted POI's half-pixel step) and the original
// variant's 768 interpolations per accepted POI (12 UHADD8 per 4 pixels).
OpCounts m4_counts(std::span<const PoiRecord> records, const Params& p);

}  // namespace pxflow::m4qemu
