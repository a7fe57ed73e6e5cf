#include "dut_wire.hpp"

#include <cstring>

#include "pxdut.h"
#include "spec_params.hpp"

namespace pxflow::dut {
namespace {

// Bounds-checked little-endian reads from a body; `what` names the message in the error.
class Reader {
 public:
  Reader(std::span<const std::uint8_t> b, const char* what) : b_(b), what_(what) {}
  std::uint8_t u8(const char* field) {
    need(1, field);
    return b_[at_++];
  }
  std::uint16_t u16(const char* field) {
    need(2, field);
    const std::uint16_t v = static_cast<std::uint16_t>(b_[at_] | b_[at_ + 1] << 8);
    at_ += 2;
    return v;
  }
  std::uint32_t u32(const char* field) {
    const std::uint32_t lo = u16(field);
    return lo | static_cast<std::uint32_t>(u16(field)) << 16;
  }
  std::string str(const char* field) {
    const std::size_t n = u8(field);
    need(n, field);
    std::string s(reinterpret_cast<const char*>(b_.data() + at_), n);
    at_ += n;
    return s;
  }
  void end() const {
    if (at_ != b_.size())
      throw WireError(std::string(what_) + " has " + std::to_string(b_.size() - at_) +
                      " bytes more than its fields");
  }

 private:
  void need(std::size_t n, const char* field) const {
    if (b_.size() - at_ < n)
      throw WireError(std::string(what_) + " ends before its field " + field + " (" +
                      std::to_string(b_.size()) + " bytes)");
  }
  std::span<const std::uint8_t> b_;
  const char* what_;
  std::size_t at_ = 0;
};

void put16(std::vector<std::uint8_t>& v, std::uint32_t x) {
  v.push_back(static_cast<std::uint8_t>(x));
  v.push_back(static_cast<std::uint8_t>(x >> 8));
}
void put32(std::vector<std::uint8_t>& v, std::uint32_t x) {
  put16(v, x);
  put16(v, x >> 16);
}
std::uint16_t get16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | p[1] << 8); }

// "bad CRC", ...: why a frame was discarded (a PXDUT_NAK_* reason), the words of the host's own
// receiver and of a device's NAK; nullptr for a reason the protocol lacks.
const char* discard_reason(unsigned reason) {
  switch (reason) {
    case PXDUT_NAK_BAD_CRC:
      return "bad CRC";
    case PXDUT_NAK_BAD_COBS:
      return "bad COBS";
    case PXDUT_NAK_TOO_LONG:
      return "too long";
    case PXDUT_NAK_TOO_SHORT:
      return "too short";
  }
  return nullptr;
}

}  // namespace

std::string message_name(std::uint8_t type) {
  switch (type) {
    case kHello:
      return "HELLO";
    case kParams:
      return "PARAMS";
    case kFrame:
      return "FRAME";
    case kRun:
      return "RUN";
    case kRecords:
      return "RECORDS";
    case kAck:
      return "ACK";
    case kNak:
      return "NAK";
    case kError:
      return "ERROR";
    case kHelloReply:
      return "HELLO reply";
    case kResult:
      return "RESULT";
    case kRecordsReply:
      return "RECORDS reply";
  }
  static const char* hex = "0123456789abcdef";
  return std::string("message 0x") + hex[type >> 4] + hex[type & 15];
}

std::vector<std::uint8_t> encode_frame(std::uint8_t type, std::uint8_t seq,
                                       std::span<const std::uint8_t> body) {
  std::vector<std::uint8_t> packet{type, seq};
  packet.insert(packet.end(), body.begin(), body.end());
  put32(packet, pxdut_crc32(packet.data(), static_cast<std::uint32_t>(packet.size())));
  std::vector<std::uint8_t> out(packet.size() + packet.size() / 254 + 2);
  const std::uint32_t n =
      pxdut_cobs_encode(packet.data(), static_cast<std::uint32_t>(packet.size()), out.data());
  out.resize(n);
  out.push_back(0);
  return out;
}

FrameReceiver::Event FrameReceiver::push(std::uint8_t byte) {
  ++bytes_seen_;
  if (byte != 0) {
    if (buf_.size() < kHostMaxPacket + kHostMaxPacket / 254 + 1) {
      buf_.push_back(byte);
      return Event::kNone;
    }
    // Reported once, at the first byte too many, not at a delimiter that may never come (a
    // link that carries anything but frames): whoever reads it need not wait for the end.
    if (overflow_) return Event::kNone;
    overflow_ = true;
    return why_bad_ = std::string(discard_reason(PXDUT_NAK_TOO_LONG)) + ", with no delimiter",
           Event::kBad;
  }
  std::vector<std::uint8_t> frame;
  frame.swap(buf_);
  const bool overflow = overflow_;
  overflow_ = false;
  if (overflow) return Event::kNone;  // reported when it began
  if (frame.empty()) return Event::kKeepalive;
  const std::int32_t n =
      pxdut_cobs_decode(frame.data(), static_cast<std::uint32_t>(frame.size()), frame.data());
  if (n < 0) return why_bad_ = discard_reason(PXDUT_NAK_BAD_COBS), Event::kBad;
  if (n < std::int32_t{PXDUT_PACKET_OVERHEAD})
    return why_bad_ = discard_reason(PXDUT_NAK_TOO_SHORT), Event::kBad;
  const std::uint32_t len = static_cast<std::uint32_t>(n) - 4;
  const std::uint32_t crc = get16(frame.data() + len) | std::uint32_t{get16(frame.data() + len + 2)}
                                                            << 16;
  if (pxdut_crc32(frame.data(), len) != crc)
    return why_bad_ = discard_reason(PXDUT_NAK_BAD_CRC), Event::kBad;
  packet_.type = frame[0];
  packet_.seq = frame[1];
  packet_.body.assign(frame.begin() + 2, frame.begin() + len);
  return Event::kPacket;
}

Hello parse_hello(std::span<const std::uint8_t> body) {
  Reader r(body, "HELLO reply");
  Hello h;
  h.version = r.u16("version");
  if (h.version != kProtocolVersion) return h;
  h.computes_estimate = (r.u16("flags") & PXDUT_HELLO_FLAG_ESTIMATE) != 0;
  h.counter_hz = r.u32("counter_hz");
  h.max_packet = r.u16("max_packet");
  r.u16("reserved");
  h.max_pixels = r.u32("max_pixels");
  h.max_pois = r.u32("max_pois");
  h.name = r.str("name");
  h.build = r.str("build");
  h.clock = r.str("clock");
  r.end();
  if (h.max_packet < PXDUT_MAX_PACKET_MIN)
    throw WireError("HELLO reply: max_packet " + std::to_string(h.max_packet) + " is below " +
                    std::to_string(PXDUT_MAX_PACKET_MIN));
  if (h.counter_hz == 0) throw WireError("HELLO reply: counter_hz is 0");
  return h;
}

std::vector<std::uint8_t> hello_body() {
  std::vector<std::uint8_t> b;
  put16(b, kProtocolVersion);
  return b;
}

std::vector<std::uint8_t> params_body(const Params& p) {
  const pxflow_param_block q = spec_params(p);  // the PARAMS body is the block, field by field
  std::vector<std::uint8_t> b;
  for (std::uint32_t v : {q.width, q.height, q.search_radius, q.tile, q.blocks, q.feature_threshold,
                          q.sad_threshold, q.hist_filter, q.min_count, q.gyro_comp})
    put32(b, v);
  return b;
}

std::vector<std::uint8_t> frame_body(int image, std::uint32_t offset,
                                     std::span<const std::uint8_t> pixels) {
  std::vector<std::uint8_t> b{static_cast<std::uint8_t>(image), 0, 0, 0};
  put32(b, offset);
  b.insert(b.end(), pixels.begin(), pixels.end());
  return b;
}

std::vector<std::uint8_t> run_body(std::uint32_t repetitions, std::uint32_t warmups) {
  std::vector<std::uint8_t> b;
  put32(b, repetitions);
  put32(b, warmups);
  return b;
}

std::vector<std::uint8_t> records_body(std::uint32_t first, std::uint32_t count) {
  return run_body(first, count);  // the same two u32
}

RunResult parse_result(std::span<const std::uint8_t> body) {
  Reader r(body, "RESULT");
  RunResult x;
  x.pois = r.u32("pois");
  x.repetitions = r.u32("repetitions");
  const std::uint64_t lo = r.u32("cycles_total");
  x.cycles_total = lo | std::uint64_t{r.u32("cycles_total")} << 32;
  x.cycles_min = r.u32("cycles_min");
  x.has_estimate = (r.u32("flags") & PXDUT_RESULT_FLAG_ESTIMATE) != 0;
  x.flow_x_bits = r.u32("flow_x");
  x.flow_y_bits = r.u32("flow_y");
  x.quality = static_cast<std::int32_t>(r.u32("quality"));
  x.meancount = static_cast<std::int32_t>(r.u32("meancount"));
  r.end();
  return x;
}

void parse_records(std::span<const std::uint8_t> body, std::uint32_t first, std::uint32_t count,
                   std::span<PoiRecord> out) {
  Reader r(body, "RECORDS reply");
  const std::uint32_t got_first = r.u32("first"), got_count = r.u32("count");
  // Bytes past the records asked for are the stream's guard zone (guard_zone.hpp's message).
  const std::size_t asked = std::size_t{PXDUT_RECORD_BYTES} * count;
  if (got_first == first && count > 0 && body.size() > 8 + asked)
    throw WireError("wrote past its output (" + std::to_string(body.size() - 8 - asked) +
                    " bytes after record " + std::to_string(first + count - 1) + ")");
  if (got_first != first || got_count != count)
    throw WireError("RECORDS reply holds records " + std::to_string(got_first) + " + " +
                    std::to_string(got_count) + ", asked for " + std::to_string(first) + " + " +
                    std::to_string(count));
  if (body.size() != 8 + std::size_t{PXDUT_RECORD_BYTES} * count)
    throw WireError("RECORDS reply has " + std::to_string(body.size() - 8) + " record bytes for " +
                    std::to_string(count) + " records of " + std::to_string(PXDUT_RECORD_BYTES));
  if (out.size() < count) throw WireError("RECORDS reply: more records than asked for");
  for (std::uint32_t i = 0; i < count; ++i)
    out[i] = decode_record(body.data() + 8 + PXDUT_RECORD_BYTES * i);
}

DeviceErrorReply parse_error(std::span<const std::uint8_t> body) {
  Reader r(body, "ERROR");
  DeviceErrorReply e;
  e.code = r.u16("code");
  e.text = r.str("text");
  r.end();
  for (char& c : e.text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = '?';  // one line, printable
  return e;
}

std::string nak_reason(std::span<const std::uint8_t> body) {
  if (body.size() != 1) return "a NAK of " + std::to_string(body.size()) + " bytes";
  const char* why = discard_reason(body[0]);
  return why ? why : "reason " + std::to_string(body[0]);
}

// The record's bytes are the spec core's (pxflow_record_to_bytes / _from_bytes); PoiRecord has
// its layout (reference/spec_core.cpp static_asserts it), so the two convert by memcpy.
PoiRecord decode_record(const std::uint8_t* b) {
  pxflow_poi_record spec;
  pxflow_record_from_bytes(b, &spec);
  PoiRecord r;
  std::memcpy(&r, &spec, sizeof r);
  return r;
}

void encode_record(const PoiRecord& r, std::uint8_t* b) {
  pxflow_poi_record spec;
  std::memcpy(&spec, &r, sizeof spec);
  pxflow_record_to_bytes(&spec, b);
  b[PXFLOW_RECORD_AT_STATUS + 1] = r.pad0;  // a host's codec keeps what it was given
  b[PXFLOW_RECORD_AT_DIR + 1] = r.pad1;
}

}  // namespace pxflow::dut
