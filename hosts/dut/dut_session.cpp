#include "dut_session.hpp"

#include <algorithm>
#include <optional>

namespace pxflow::dut {
namespace {

constexpr auto kSettle = std::chrono::milliseconds(100);  // after a corrupted frame, see whether
                                                          // a good one follows before resending
// More bytes than this with no valid frame among them is not a device talking: four of the
// largest frames the host accepts, far above any stray print a device may send between frames.
constexpr std::uint64_t kGarbageLimit = 4 * (kHostMaxPacket + kHostMaxPacket / 254 + 2);

}  // namespace

Session::Session(std::string label, std::unique_ptr<Link> link,
                 std::chrono::duration<double> timeout)
    : label_(std::move(label)), link_(std::move(link)), timeout_(timeout) {}

void Session::fail(const std::string& message, const std::string& what, const std::string& hint,
                   bool fatal) {
  throw DutError(label_ + ": " + message + ": " + what + (hint.empty() ? "" : "; " + hint), fatal);
}

Packet Session::exchange(std::uint8_t type, std::span<const std::uint8_t> body, std::uint8_t expect,
                         const DeviceWork* work) {
  Request r;
  r.name = message_name(type);
  r.seq = next_seq_++;
  r.expect = expect;
  const std::vector<std::uint8_t> frame = encode_frame(type, r.seq, body);
  // The allowance of one wait (hosts/core/device_wait.hpp): the timeout once per work unit.
  const double allowed = timeout_.count() * (work ? work_units(*work) : 1.0);
  r.wait = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(allowed));
  r.allowed_text = setting_text(allowed) + " s";
  r.for_work = work ? " for " + work_text(*work) : "";
  std::string problem;
  for (int attempt = 0; attempt <= kResends; ++attempt) {
    const Clock::time_point deadline = Clock::now() + r.wait;
    // A leading delimiter ends whatever partial frame the device holds (section 1).
    send(r.name, frame, attempt > 0 || type == kHello, deadline);
    if (std::optional<Packet> reply = await_reply(r, deadline, problem)) return *reply;
  }
  fail(r.name,
       (problem.empty() ? std::string("no valid answer") : problem) + " after " +
           std::to_string(kResends) + " resends (each waited up to " + r.allowed_text + ")",
       "is the device running and on this link (baud rate)? " + raise_timeout_hint(work), true);
}

void Session::send(const std::string& name, std::span<const std::uint8_t> frame, bool delimit,
                   Clock::time_point deadline) {
  try {
    if (delimit) link_->write(std::vector<std::uint8_t>{0}, deadline);
    link_->write(frame, deadline);
  } catch (const LinkError& e) {
    fail(name, std::string("the link broke: ") + e.what(),
         "is the device still running? (its output above may say why)", true);
  }
}

std::optional<Packet> Session::await_reply(const Request& r, Clock::time_point deadline,
                                           std::string& problem) {
  Clock::time_point resend_at = deadline;
  std::string wrong_seq;  // a reply of this attempt that did not copy the request's seq
  for (;;) {
    if (pending_at_ == pending_.size()) {
      if (Clock::now() >= resend_at) return std::nullopt;
      if (read_more(r.name, resend_at) == 0) {
        if (resend_at == deadline)
          problem =
              wrong_seq.empty() ? "no answer within " + r.allowed_text + r.for_work : wrong_seq;
        return std::nullopt;
      }
    }
    const FrameReceiver::Event ev = next_event(r.name);
    if (ev == FrameReceiver::Event::kKeepalive || ev == FrameReceiver::Event::kPacket) {
      // The device is alive: the wait starts again (unless a corrupted reply is settling).
      if (resend_at == deadline) resend_at = deadline = Clock::now() + r.wait;
    }
    if (ev == FrameReceiver::Event::kBad) {
      problem = "a corrupted reply (" + rx_.why_bad() + ")";
      resend_at = std::min(resend_at, Clock::now() + kSettle);
      continue;
    }
    if (ev != FrameReceiver::Event::kPacket) continue;
    const Packet& p = rx_.packet();
    valid_frame_seen_ = true;
    if (p.type == kNak) {
      problem = "the device NAKed it (" + nak_reason(p.body) + ")";
      return std::nullopt;
    }
    if (p.seq != r.seq) {  // a late copy of an earlier reply, or a device that does not copy seq
      wrong_seq = "only a reply with seq " + std::to_string(p.seq) + " within " + r.allowed_text +
                  r.for_work + ", not the request's " + std::to_string(r.seq) +
                  " (a reply copies its request's seq)";
      continue;
    }
    return accept_reply(r, p);
  }
}

std::size_t Session::read_more(const std::string& name, Clock::time_point until) {
  pending_.resize(4096);
  pending_at_ = 0;
  std::size_t n = 0;
  try {
    n = link_->read(pending_.data(), pending_.size(), until);
  } catch (const LinkError& e) {
    pending_.clear();
    fail(name, std::string("the device went away: ") + e.what(),
         "is it still running? (its output above may say why)", true);
  }
  pending_.resize(n);
  return n;
}

FrameReceiver::Event Session::next_event(const std::string& name) {
  const FrameReceiver::Event ev = rx_.push(pending_[pending_at_++]);
  if (ev == FrameReceiver::Event::kPacket) bytes_at_last_packet_ = rx_.bytes_seen();
  if (rx_.bytes_seen() - bytes_at_last_packet_ > kGarbageLimit) {
    pending_.clear();
    pending_at_ = 0;
    fail(name,
         std::to_string(rx_.bytes_seen() - bytes_at_last_packet_) +
             " bytes arrived with no valid frame among them",
         link_->garbage_hint(), true);
  }
  return ev;
}

Packet Session::accept_reply(const Request& r, const Packet& p) {
  if (p.type == kError) {
    DeviceErrorReply e;
    try {
      e = parse_error(p.body);
    } catch (const WireError& w) {
      fail(r.name, std::string("a malformed ERROR: ") + w.what(), "", false);
    }
    fail(r.name, "the device answered ERROR " + std::to_string(e.code) + " (" + e.text + ")",
         e.code == PXDUT_ERR_NOT_READY ? "did it reset? it lost the parameters or frames" : "",
         false);
  }
  if (p.type != r.expect)
    fail(r.name, "answered with " + message_name(p.type) + ", expected " + message_name(r.expect),
         "is this a pxflow device of protocol version 1?", false);
  return p;
}

Hello Session::hello() {
  Packet p;
  try {
    p = exchange(kHello, hello_body(), kHelloReply);
  } catch (const DutError& e) {
    const std::string line = e.what();
    if (!valid_frame_seen_ && rx_.bytes_seen() > 0)
      throw DutError("not a pxflow device: " + std::to_string(rx_.bytes_seen()) +
                         " bytes arrived but no valid frame (" + link_->garbage_hint() + ")",
                     true);
    throw DutError(line.substr(std::min(line.size(), label_.size() + 2)), true);
  }
  Hello h;
  try {
    h = parse_hello(p.body);
  } catch (const WireError& w) {
    throw DutError(std::string("not a pxflow device: ") + w.what(), true);
  }
  if (h.version != kProtocolVersion)
    throw DutError("protocol version " + std::to_string(h.version) + ", this pxflow speaks " +
                       std::to_string(kProtocolVersion),
                   true);
  // The device's own size rule (section 1): no packet of its may exceed what it declares.
  const std::size_t packet = p.body.size() + PXDUT_PACKET_OVERHEAD;
  if (packet > h.max_packet)
    throw DutError("its HELLO reply is a " + std::to_string(packet) +
                       "-byte packet, more than the max_packet of " + std::to_string(h.max_packet) +
                       " it declares (a reply overran its buffer)",
                   true);
  return h;
}

}  // namespace pxflow::dut
