// The row of one --dut device: the device (its link and session, opened by the probe's HELLO and
// shared with every backend the row creates) and the Backend that runs pairs on it.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "backend.hpp"
#include "dut_session.hpp"
#include "dut_spec.hpp"

namespace pxflow::dut {

class Device {
 public:
  explicit Device(DutSpec spec) : spec_(std::move(spec)) {}
  // Opens the link and says HELLO once; empty when the device answered as a version-1 device,
  // else the one-line reason it cannot run (the row's probe).
  std::string probe();
  // The open session; throws the fatal line again once the device has failed.
  Session& session();
  const Hello& hello() const { return hello_; }
  const DutSpec& spec() const { return spec_; }
  // Marks the device dead after a fatal failure: every later use fails at once with `line`.
  void kill(const std::string& line);
  std::optional<Params> params_sent;  // what the device holds, to skip a repeated PARAMS

 private:
  DutSpec spec_;
  std::unique_ptr<Session> session_;
  bool probed_ = false;
  std::string why_not_, dead_;
  Hello hello_;
};

class DutBackend : public Backend {
 public:
  explicit DutBackend(std::shared_ptr<Device> device) : dev_(std::move(device)) {}
  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override;
  std::string unsupported(const Params& p) const override;
  std::optional<DeviceTime> last_device_time() const override { return last_time_; }
  // The device's own name and build (its HELLO) and the link it is reached through.
  Description describe() const override {
    const Hello& h = dev_->hello();
    return {h.name + (h.build.empty() ? "" : " (build " + h.build + ")"),
            "device under test at " + dev_->spec().text,
            "pxflow device protocol v" + std::to_string(h.version)};
  }

 private:
  void run_pair(const FramePair& pair, const Params& p, std::span<PoiRecord> out, std::size_t index,
                RunResult& result);
  std::shared_ptr<Device> dev_;
  std::optional<DeviceTime> last_time_;
};

// The registry row for `spec` (family "dut").
BackendRow dut_row(const DutSpec& spec);

}  // namespace pxflow::dut
