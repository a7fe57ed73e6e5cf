// One conversation with a device (docs/dut-protocol.md section 2): numbered requests, replies
// matched by sequence number, resends on a timeout, a NAK or a corrupted reply (at most
// kResends), and every failure turned into one line naming the device, the message and what
// to try. A wait lasts --device-timeout x the work units of the request (RUN: its pair's
// candidates; hosts/core/device_wait.hpp) and starts again whenever the device sends a valid
// frame or a keepalive (an empty frame, a lone 0x00): a device that keeps talking is not hung.
#pragma once
#include <chrono>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "device_wait.hpp"
#include "dut_link.hpp"
#include "dut_wire.hpp"
#include "errors.hpp"

namespace pxflow::dut {

inline constexpr int kResends = 3;

// A device failure: the what() is the whole line. `fatal`: the link is gone or the device stopped
// answering, so the row is dead for the rest of the run.
struct DutError : BackendError {
  DutError(const std::string& line, bool fatal_) : BackendError(line), fatal(fatal_) {}
  bool fatal;
};

class Session {
 public:
  // `label` starts every line ("dut ref (exec:build/pxflow-dut-ref)").
  Session(std::string label, std::unique_ptr<Link> link, std::chrono::duration<double> timeout);

  // HELLO. Returns the reply, or throws DutError with the probe's reason as its message (no
  // answer, not a pxflow device, another protocol version).
  Hello hello();

  // Sends a request and returns the reply of type `expect`; an ERROR reply, a reply of another
  // type or a malformed one is a DutError (not fatal); no valid reply after kResends resends or
  // a closed link is a fatal DutError.
  // `work`: the kernel work the request starts (RUN), which scales the wait; nullptr for none.
  Packet exchange(std::uint8_t type, std::span<const std::uint8_t> body, std::uint8_t expect,
                  const DeviceWork* work = nullptr);

  const std::string& label() const { return label_; }

  // A failure line: "<label>: <message>: <what>; <hint>".
  [[noreturn]] void fail(const std::string& message, const std::string& what,
                         const std::string& hint, bool fatal);

 private:
  std::string label_;
  std::unique_ptr<Link> link_;
  std::chrono::duration<double> timeout_;
  std::uint8_t next_seq_ = 0;
  FrameReceiver rx_;
  std::vector<std::uint8_t> pending_;  // bytes read but not yet fed to rx_
  std::size_t pending_at_ = 0;
  bool valid_frame_seen_ = false;
  std::uint64_t bytes_at_last_packet_ = 0;  // rx_.bytes_seen() when the last valid frame ended
};

}  // namespace pxflow::dut
