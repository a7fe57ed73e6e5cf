// The m4-qemu firmware's two links measured side by side, in one run, with the same ELF
// (docs/cortex-m4.md, "The link"): for each link of hosts/m4qemu (semihosting, the UART) it
// starts QEMU with the row's own command line, says HELLO and PARAMS (64x64, px4flow-64), then
// times FRAME messages of the largest chunk the device takes (host to device) and RECORDS
// replies of all 64 records (device to host). A rate is payload bytes (pixels, records) per
// second of wall clock over whole exchanges: what the row gets, framing and acknowledgements
// included. A measurement, not a test: it asserts no rate (docs/cortex-m4.md has the figures and
// this command). Exits 1 when a link fails to carry the bytes, 2 on a bad command line.
//
//   m4_link_rate FIRMWARE [--kib N]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "dut_link.hpp"
#include "dut_session.hpp"
#include "dut_wire.hpp"
#include "m4qemu_row.hpp"
#include "params.hpp"

namespace {

using namespace pxflow;
using Seconds = std::chrono::duration<double>;

struct Rates {
  double to_device = 0, from_device = 0;  // payload bytes per second
};

Rates measure(const std::string& firmware, m4qemu::M4Link link, std::size_t bytes) {
  const std::vector<std::string> argv = m4qemu::qemu_command(firmware, link);
  dut::Session s(std::string("m4-qemu (") + m4qemu::link_name(link) + " link)",
                 dut::open_exec_link(argv), Seconds(10));
  const dut::Hello hello = s.hello();
  const Params p = profile("px4flow-64");
  s.exchange(dut::kParams, dut::params_body(p), dut::kAck);
  const std::size_t pixels = static_cast<std::size_t>(p.width) * p.height;
  const std::size_t chunk = std::min<std::size_t>(hello.max_packet - 18u, pixels);
  std::vector<std::uint8_t> data(chunk);
  for (std::size_t i = 0; i < chunk; ++i) data[i] = static_cast<std::uint8_t>(i * 37u + 11u);

  Rates r;
  std::size_t sent = 0;
  auto t0 = std::chrono::steady_clock::now();
  while (sent < bytes) {
    s.exchange(dut::kFrame, dut::frame_body(0, 0, data), dut::kAck);
    sent += chunk;
  }
  r.to_device = sent / Seconds(std::chrono::steady_clock::now() - t0).count();

  s.exchange(dut::kRun, dut::run_body(1, 0), dut::kResult);
  const std::uint32_t pois = 64u;  // px4flow-64's grid on 64x64
  std::size_t received = 0;
  t0 = std::chrono::steady_clock::now();
  while (received < bytes) {
    const dut::Packet reply =
        s.exchange(dut::kRecords, dut::records_body(0, pois), dut::kRecordsReply);
    received += reply.body.size() - 8u;  // the records, not `first` and `count`
  }
  r.from_device = received / Seconds(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: m4_link_rate FIRMWARE [--kib N]\n");
    return 2;
  }
  const std::string firmware = argv[1];
  std::size_t kib = 128;
  for (int i = 2; i < argc; i += 2) {
    char* end = nullptr;
    if (std::strcmp(argv[i], "--kib") != 0 || i + 1 >= argc ||
        (kib = std::strtoul(argv[i + 1], &end, 10)) == 0 || *end != '\0' || kib > 65536) {
      std::fprintf(stderr, "m4_link_rate: bad option '%s' (usage: FIRMWARE [--kib 1..65536])\n",
                   argv[i]);
      return 2;
    }
  }
  std::printf("m4_link_rate: %zu KiB each way per link, firmware %s\n", kib, firmware.c_str());
  std::printf("%-12s %18s %18s\n", "link", "host->device KB/s", "device->host KB/s");
  std::vector<Rates> rates;
  try {
    for (const m4qemu::M4LinkName& l : m4qemu::kM4Links) {
      rates.push_back(measure(firmware, l.link, kib * 1024u));
      std::printf("%-12s %18.1f %18.1f\n", l.name, rates.back().to_device / 1000,
                  rates.back().from_device / 1000);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::printf("FAIL %s\n", e.what());
    return 1;
  }
  const double to = rates[0].to_device / rates[1].to_device;
  const double from = rates[0].from_device / rates[1].from_device;
  std::printf("semihosting / uart: %.1fx host->device, %.1fx device->host\n", to, from);
  return 0;
}
