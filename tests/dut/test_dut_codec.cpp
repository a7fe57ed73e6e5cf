// The framing against vectors from independent sources, and the host's parsers on bad bodies.
#include <catch2/catch.hpp>
#include <cstring>
#include <string>
#include <vector>

#include "dut_wire.hpp"
#include "pxdut.h"

using pxflow::dut::FrameReceiver;
using Bytes = std::vector<std::uint8_t>;

namespace {

std::uint32_t crc_of(const std::string& s) {
  return pxdut_crc32(reinterpret_cast<const std::uint8_t*>(s.data()),
                     static_cast<std::uint32_t>(s.size()));
}

Bytes cobs(const Bytes& in) {
  Bytes out(in.size() + in.size() / 254 + 2);
  out.resize(pxdut_cobs_encode(in.data(), static_cast<std::uint32_t>(in.size()), out.data()));
  return out;
}

Bytes range(int first, int last) {  // first .. last inclusive
  Bytes b;
  for (int v = first; v <= last; ++v) b.push_back(static_cast<std::uint8_t>(v));
  return b;
}

Bytes cat(Bytes a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST_CASE("CRC-32/ISO-HDLC matches its published check values", "[dut][codec]") {
  // The check value of the CRC catalogue (reveng, "CRC-32/ISO-HDLC": check=0xcbf43926).
  CHECK(crc_of("123456789") == 0xCBF43926u);
  CHECK(crc_of("") == 0x00000000u);
  // zlib's crc32() of the pangram, as quoted by many independent sources.
  CHECK(crc_of("The quick brown fox jumps over the lazy dog") == 0x414FA339u);
}

TEST_CASE("COBS encodes Wikipedia's example table (without the delimiter)", "[dut][codec]") {
  // Wikipedia, "Consistent Overhead Byte Stuffing", Encoding examples 1-11.
  const std::vector<std::pair<Bytes, Bytes>> table = {
      {{0x00}, {0x01, 0x01}},
      {{0x00, 0x00}, {0x01, 0x01, 0x01}},
      {{0x00, 0x11, 0x00}, {0x01, 0x02, 0x11, 0x01}},
      {{0x11, 0x22, 0x00, 0x33}, {0x03, 0x11, 0x22, 0x02, 0x33}},
      {{0x11, 0x22, 0x33, 0x44}, {0x05, 0x11, 0x22, 0x33, 0x44}},
      {{0x11, 0x00, 0x00, 0x00}, {0x02, 0x11, 0x01, 0x01, 0x01}},
      {range(0x01, 0xFE), cat({0xFF}, range(0x01, 0xFE))},
      {range(0x00, 0xFE), cat({0x01, 0xFF}, range(0x01, 0xFE))},
      {range(0x01, 0xFF), cat(cat({0xFF}, range(0x01, 0xFE)), {0x02, 0xFF})},
      {cat(range(0x02, 0xFF), {0x00}), cat(cat({0xFF}, range(0x02, 0xFF)), {0x01, 0x01})},
      {cat(range(0x03, 0xFF), {0x00, 0x01}), cat(cat({0xFE}, range(0x03, 0xFF)), {0x02, 0x01})},
  };
  int example = 1;
  for (const auto& [in, want] : table) {
    INFO("example " << example++);
    const Bytes got = cobs(in);
    CHECK(got == want);
    Bytes back(got.size());
    const std::int32_t n =
        pxdut_cobs_decode(got.data(), static_cast<std::uint32_t>(got.size()), back.data());
    REQUIRE(n == static_cast<std::int32_t>(in.size()));
    back.resize(n);
    CHECK(back == in);
  }
  // The empty packet (Cheshire and Baker: a lone code byte 0x01).
  CHECK(cobs({}) == Bytes{0x01});
}

TEST_CASE("COBS decoding rejects codes that point past the end", "[dut][codec]") {
  Bytes out(16);
  const Bytes past = {0x05, 0x11, 0x22};
  CHECK(pxdut_cobs_decode(past.data(), 3, out.data()) == -1);
  const Bytes zero_code = {0x02, 0x11, 0x00};
  CHECK(pxdut_cobs_decode(zero_code.data(), 3, out.data()) == -1);
}

TEST_CASE("the frame receiver resynchronises after garbage and drops bad frames", "[dut][codec]") {
  const Bytes good = pxflow::dut::encode_frame(pxflow::dut::kAck, 7, {});
  Bytes stream = {0x13, 0x37, 0x00, 0x02, 0x37, 0x00};  // garbage up to delimiters
  stream.insert(stream.end(), good.begin(), good.end());
  Bytes flipped = good;
  flipped[2] ^= 0x01;
  stream.insert(stream.end(), flipped.begin(), flipped.end());
  FrameReceiver rx;
  std::vector<std::string> events;
  for (std::uint8_t b : stream) {
    const auto ev = rx.push(b);
    if (ev == FrameReceiver::Event::kBad) events.push_back("bad " + rx.why_bad());
    if (ev == FrameReceiver::Event::kPacket)
      events.push_back("packet " + std::to_string(rx.packet().type) + " seq " +
                       std::to_string(rx.packet().seq));
  }
  CHECK(events ==
        std::vector<std::string>{"bad bad COBS", "bad too short", "packet 6 seq 7", "bad bad CRC"});
}

TEST_CASE("the host's parsers reject short, long and malformed bodies", "[dut][codec]") {
  using namespace pxflow::dut;
  CHECK_THROWS_AS(parse_result(Bytes(39)), WireError);
  CHECK_THROWS_AS(parse_result(Bytes(41)), WireError);
  CHECK_NOTHROW(parse_result(Bytes(40)));
  CHECK_THROWS_AS(parse_hello(Bytes{0x01}), WireError);
  // A HELLO of another version is read for its version only.
  CHECK(parse_hello(Bytes{0x02, 0x00}).version == 2);
  CHECK_THROWS_WITH(parse_error(Bytes{0x04, 0x00, 0x05, 'a'}), Catch::Contains("text"));
  std::vector<pxflow::PoiRecord> out(2);
  Bytes rec = {0, 0, 0, 0, 2, 0, 0, 0};  // first 0, count 2, but no record bytes
  CHECK_THROWS_WITH(parse_records(rec, 0, 2, out), Catch::Contains("record bytes"));
  CHECK_THROWS_WITH(parse_records(rec, 1, 2, out), Catch::Contains("asked for"));
}

TEST_CASE("a record goes over the wire field by field and back", "[dut][codec]") {
  pxflow::PoiRecord r{};
  r.x = 0x1234, r.y = 7, r.status = 2, r.feature = 999, r.dx = -3, r.dy = 4, r.sad = 4321,
  r.dir = 5, r.hx = -7, r.hy = 9;
  for (int k = 0; k < 8; ++k) r.sub[k] = static_cast<std::uint16_t>(1000 + k);
  std::uint8_t bytes[32];
  pxflow::dut::encode_record(r, bytes);
  CHECK(bytes[0] == 0x34);
  CHECK(bytes[1] == 0x12);
  CHECK(bytes[8] == 0xFD);  // dx = -3
  const pxflow::PoiRecord back = pxflow::dut::decode_record(bytes);
  CHECK(std::memcmp(&back, &r, sizeof r) == 0);
}
