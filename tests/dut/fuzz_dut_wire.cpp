// libFuzzer target over everything the host does with a device's bytes (docs/dut-protocol.md):
// the frame receiver (COBS, delimiters, lengths, CRC) and every message parser on every packet
// it yields, plus the parsers on the raw input. A WireError is the expected answer to bad
// bytes; anything else (a crash, a sanitizer report, a leak, a hang) is a bug.
// Built and run by fuzz_dut_wire.sh (clang++ -fsanitize=fuzzer,address,undefined).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "dut_wire.hpp"
#include "pxdut.h"

namespace {

void parse_all(std::span<const std::uint8_t> body) {
  using namespace pxflow::dut;
  std::vector<pxflow::PoiRecord> out(4);
  try {
    parse_hello(body);
  } catch (const WireError&) {
  }
  try {
    parse_result(body);
  } catch (const WireError&) {
  }
  // The count the body's length suggests (clamped), so both the header and the length checks run.
  const std::uint32_t count = body.size() >= 40 ? 1 + (body.size() - 40) / 32 % 4 : 1;
  try {
    parse_records(body, 0, count, out);
  } catch (const WireError&) {
  }
  try {
    parse_error(body);
  } catch (const WireError&) {
  }
  nak_reason(body);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  pxflow::dut::FrameReceiver rx;
  for (std::size_t i = 0; i < size; ++i)
    if (rx.push(data[i]) == pxflow::dut::FrameReceiver::Event::kPacket) {
      pxflow::dut::message_name(rx.packet().type);
      parse_all(rx.packet().body);
    }
  parse_all(std::span<const std::uint8_t>(data, size));
  // The decoder alone, in place as the device runs it: never writes past the input.
  std::vector<std::uint8_t> copy(data, data + size);
  const std::int32_t n =
      pxdut_cobs_decode(copy.data(), static_cast<std::uint32_t>(copy.size()), copy.data());
  if (n > static_cast<std::int32_t>(size)) __builtin_trap();
  return 0;
}
