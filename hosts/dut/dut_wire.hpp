// The bytes of the device-under-test protocol on the host side (docs/dut-protocol.md sections 1
// and 3): frames in (COBS, delimiter, CRC) and out, and the messages' bodies. Everything here
// reads bytes from devices nobody here controls: every length is checked, a bad body is a
// WireError naming the field, never a read past the end (fuzzed: tests/dut/fuzz_dut_wire.cpp).
#pragma once
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "params.hpp"
#include "pxdut_wire.h"
#include "record.hpp"

namespace pxflow::dut {

// The protocol's numbers are dut/include/pxdut_wire.h's, the one table device and host share.
inline constexpr std::uint16_t kProtocolVersion = PXDUT_PROTOCOL_VERSION;
inline constexpr std::size_t kHostMaxPacket = PXDUT_MAX_PACKET_MAX;  // the largest it accepts

enum MessageType : std::uint8_t {
  kHello = PXDUT_MSG_HELLO,
  kParams = PXDUT_MSG_PARAMS,
  kFrame = PXDUT_MSG_FRAME,
  kRun = PXDUT_MSG_RUN,
  kRecords = PXDUT_MSG_RECORDS,
  kAck = PXDUT_MSG_ACK,
  kNak = PXDUT_MSG_NAK,
  kError = PXDUT_MSG_ERROR,
  kHelloReply = PXDUT_MSG_HELLO_REPLY,
  kResult = PXDUT_MSG_RESULT,
  kRecordsReply = PXDUT_MSG_RECORDS_REPLY,
};

// "HELLO", "RESULT", ... for messages; "0x42" for a type the protocol does not have.
std::string message_name(std::uint8_t type);

struct WireError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Packet {
  std::uint8_t type = 0;
  std::uint8_t seq = 0;
  std::vector<std::uint8_t> body;
};

// A packet as it goes on the link: COBS(type, seq, body, CRC-32) and the 0x00 delimiter.
std::vector<std::uint8_t> encode_frame(std::uint8_t type, std::uint8_t seq,
                                       std::span<const std::uint8_t> body);

// Collects link bytes and cuts them into frames at each 0x00.
class FrameReceiver {
 public:
  enum class Event { kNone, kPacket, kBad, kKeepalive };
  // Takes one byte; kPacket: packet() holds a frame with a good CRC; kBad: why_bad() says why
  // the frame was dropped (bad COBS, too long, too short, bad CRC); kKeepalive: an empty frame
  // (a 0x00 right after a 0x00), which a busy device may send to show it is alive.
  Event push(std::uint8_t byte);
  const Packet& packet() const { return packet_; }
  const std::string& why_bad() const { return why_bad_; }
  std::uint64_t bytes_seen() const { return bytes_seen_; }

 private:
  std::vector<std::uint8_t> buf_;
  bool overflow_ = false;
  Packet packet_;
  std::string why_bad_;
  std::uint64_t bytes_seen_ = 0;
};

// The HELLO reply (section 3).
struct Hello {
  std::uint16_t version = 0;
  bool computes_estimate = false;
  std::uint32_t counter_hz = 0;
  std::uint16_t max_packet = 0;
  std::uint32_t max_pixels = 0;
  std::uint32_t max_pois = 0;
  std::string name, build, clock;
};
// Throws WireError; only the version is read when it is not ours (the rest may differ).
Hello parse_hello(std::span<const std::uint8_t> body);

std::vector<std::uint8_t> hello_body();
std::vector<std::uint8_t> params_body(const Params& p);
std::vector<std::uint8_t> frame_body(int image, std::uint32_t offset,
                                     std::span<const std::uint8_t> pixels);
std::vector<std::uint8_t> run_body(std::uint32_t repetitions, std::uint32_t warmups);
std::vector<std::uint8_t> records_body(std::uint32_t first, std::uint32_t count);

struct RunResult {
  std::uint32_t pois = 0;
  std::uint32_t repetitions = 0;
  std::uint64_t cycles_total = 0;
  std::uint32_t cycles_min = 0;
  bool has_estimate = false;
  std::uint32_t flow_x_bits = 0, flow_y_bits = 0;
  std::int32_t quality = 0, meancount = 0;
};
RunResult parse_result(std::span<const std::uint8_t> body);

// A RECORDS reply: checks it holds exactly records first .. first+count-1 and decodes them.
void parse_records(std::span<const std::uint8_t> body, std::uint32_t first, std::uint32_t count,
                   std::span<PoiRecord> out);

struct DeviceErrorReply {
  std::uint16_t code = 0;
  std::string text;
};
DeviceErrorReply parse_error(std::span<const std::uint8_t> body);
std::string nak_reason(std::span<const std::uint8_t> body);

// SPEC §4's 32 bytes, little-endian, field by field.
PoiRecord decode_record(const std::uint8_t* bytes);
void encode_record(const PoiRecord& r, std::uint8_t* bytes);

}  // namespace pxflow::dut
