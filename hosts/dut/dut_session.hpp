// One conversation with a device (docs/dut-protocol.md section 2): numbered requests, replies
// matched by sequence number, resends on a timeout, a NAK or a corrupted reply (at most
// kResends), and every failure turned into one line naming the device, the message and what
// to try. A wait lasts --device-timeout x the work units of the request (RUN: its pair's
// candidates; hosts/core/device_wait.hpp) and starts again whenever the device sends a valid
// frame or a keepalive (an empty frame, a lone 0x00): a device that keeps talking is not hung.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
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
  // One request as exchange() waits for its reply.
  struct Request {
    std::string name;  // the message's name, for failure lines
    std::uint8_t seq = 0;
    std::uint8_t expect = 0;             // the reply's type
    Clock::duration wait{};              // the allowance of one wait
    std::string allowed_text, for_work;  // "2.5 s", " for ..." (the work), for failure lines
  };

  // Writes the frame, after a lone delimiter when `delimit`; a broken link is a fatal DutError.
  void send(const std::string& name, std::span<const std::uint8_t> frame, bool delimit,
            Clock::time_point deadline);
  // One attempt's wait: the reply to `r`, or nullopt when it is to be sent again (no answer in
  // time, a NAK, a corrupted reply that nothing valid followed); `problem` then says why.
  std::optional<Packet> await_reply(const Request& r, Clock::time_point deadline,
                                    std::string& problem);
  // Reads what the link has into pending_, waiting up to `until`; 0: nothing came.
  std::size_t read_more(const std::string& name, Clock::time_point until);
  // Feeds the next pending byte to rx_; too many bytes with no valid frame is a fatal DutError.
  FrameReceiver::Event next_event(const std::string& name);
  // A reply that copies the request's seq: the packet when of the type expected, else a DutError.
  Packet accept_reply(const Request& r, const Packet& p);

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
