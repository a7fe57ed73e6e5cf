#include "dut_backend.hpp"

#include <bit>
#include <cstring>

#include "counted.hpp"
#include "estimate.hpp"
#include "grid.hpp"

namespace pxflow::dut {

std::string Device::probe() {
  if (probed_) return why_not_;
  probed_ = true;
  // --device-timeout (hosts/core/device_wait.hpp), read when the device is opened.
  const std::chrono::duration<double> timeout(device_timeout_seconds());
  try {
    session_ = std::make_unique<Session>("dut " + spec_.name + " (" + spec_.text + ")",
                                         open_link(spec_, timeout), timeout);
    hello_ = session_->hello();
  } catch (const LinkError& e) {
    why_not_ = e.what();
  } catch (const DutError& e) {
    why_not_ = e.what();
  }
  if (!why_not_.empty()) session_.reset();  // stops an exec device that did not answer
  return why_not_;
}

Session& Device::session() {
  if (!dead_.empty()) throw DutError(dead_ + " (failed earlier in this run)", true);
  if (!session_) throw DutError("dut " + spec_.name + ": " + probe(), true);
  return *session_;
}

void Device::kill(const std::string& line) {
  if (dead_.empty()) dead_ = line;  // the first failure is the one every later use repeats
  session_.reset();                 // an exec device is stopped and reaped now
}

std::string DutBackend::unsupported(const Params& p) const {
  const Hello& h = dev_->hello();
  if (p.gyro_comp) return "gyro compensation is not part of protocol version 1";
  const std::uint64_t pixels = std::uint64_t(p.width) * p.height;
  if (pixels > h.max_pixels)
    return "a " + std::to_string(p.width) + "x" + std::to_string(p.height) +
           " frame is larger than the device's " + std::to_string(h.max_pixels) +
           " pixels (HELLO max_pixels)";
  if (poi_count(p) > h.max_pois)
    return counted(poi_count(p), "POI") + " are more than the device's " +
           std::to_string(h.max_pois) + " (HELLO max_pois)";
  return {};
}

namespace {

void send_image(Session& s, const FrameView& f, int image, std::size_t chunk) {
  std::vector<std::uint8_t> packed(static_cast<std::size_t>(f.width) * f.height);
  for (int y = 0; y < f.height; ++y)
    std::memcpy(&packed[std::size_t(y) * f.width], f.row(y), f.width);
  for (std::size_t at = 0; at < packed.size(); at += chunk) {
    const std::size_t n = std::min(chunk, packed.size() - at);
    s.exchange(kFrame,
               frame_body(image, static_cast<std::uint32_t>(at),
                          std::span<const std::uint8_t>(packed).subspan(at, n)),
               kAck);
  }
}

std::string float_text(std::uint32_t bits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.9g (0x%08x)", std::bit_cast<float>(bits), bits);
  return buf;
}

}  // namespace

void DutBackend::run_pair(const FramePair& pair, const Params& p, std::span<PoiRecord> out,
                          std::size_t index, RunResult& result) {
  Session& s = dev_->session();
  const Hello& h = dev_->hello();
  if (dev_->params_sent != p) {
    dev_->params_sent.reset();
    s.exchange(kParams, params_body(p), kAck);
    dev_->params_sent = p;
  }
  const std::size_t max_packet = std::min<std::size_t>(h.max_packet, kHostMaxPacket);
  send_image(s, pair.prev, PXDUT_IMAGE_PREV, max_packet - PXDUT_FRAME_CHUNK_MARGIN);
  send_image(s, pair.next, PXDUT_IMAGE_NEXT, max_packet - PXDUT_FRAME_CHUNK_MARGIN);
  const DeviceWork work{1, out.size(), p.search_radius};  // scales the wait for RESULT
  const Packet reply = s.exchange(kRun, run_body(1, 0), kResult, &work);
  const std::string pair_text = "pair " + std::to_string(index);
  try {
    result = parse_result(reply.body);
  } catch (const WireError& e) {
    s.fail("RUN", std::string("malformed RESULT: ") + e.what(), "", false);
  }
  if (result.pois != out.size())
    s.fail("RUN",
           "RESULT of " + pair_text + " says " + std::to_string(result.pois) +
               " records, the grid has " + std::to_string(out.size()),
           "the kernel must write one record per grid POI (SPEC §2)", false);
  const std::uint32_t per_reply =
      static_cast<std::uint32_t>((max_packet - PXDUT_RECORDS_REPLY_OVERHEAD) / PXDUT_RECORD_BYTES);
  for (std::uint32_t first = 0; first < out.size(); first += per_reply) {
    const std::uint32_t count =
        std::min<std::uint32_t>(per_reply, static_cast<std::uint32_t>(out.size()) - first);
    const Packet r = s.exchange(kRecords, records_body(first, count), kRecordsReply);
    try {
      parse_records(r.body, first, count, out.subspan(first, count));
    } catch (const WireError& e) {
      s.fail("RECORDS", e.what(), "the device must answer exactly the records asked for", false);
    }
  }
  if (!result.has_estimate) return;
  // The device's own estimate must be the host's of its records, bit for bit (SPEC §5).
  const FrameResult host = estimate_flow(out, p);
  const std::uint32_t hx = std::bit_cast<std::uint32_t>(host.flow_x),
                      hy = std::bit_cast<std::uint32_t>(host.flow_y);
  if (hx != result.flow_x_bits || hy != result.flow_y_bits || host.quality != result.quality ||
      host.meancount != result.meancount)
    s.fail("RUN",
           "the device's estimate of " + pair_text + " (" + float_text(result.flow_x_bits) + ", " +
               float_text(result.flow_y_bits) + ", quality " + std::to_string(result.quality) +
               ", " + std::to_string(result.meancount) +
               " accepted) differs from estimate_flow of " + "its records (" + float_text(hx) +
               ", " + float_text(hy) + ", quality " + std::to_string(host.quality) + ", " +
               std::to_string(host.meancount) + " accepted)",
           "build the estimate with -ffp-contract=off and SPEC §5's operation order", false);
}

void DutBackend::run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
                     OpCounts&) {
  last_time_.reset();
  const std::size_t pois = poi_count(p);
  if (out.size() != pairs.size() * pois) throw BackendError("dut: output size mismatch");
  std::uint64_t ticks = 0;
  try {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      RunResult r;
      run_pair(pairs[i], p, out.subspan(i * pois, pois), i, r);
      ticks += r.cycles_total;
    }
  } catch (const DutError& e) {
    dev_->params_sent.reset();  // after a failure the device's state is unknown
    std::fill(out.begin(), out.end(), PoiRecord{});  // nothing partial may look valid
    if (e.fatal) dev_->kill(e.what());
    throw;
  }
  const Hello& h = dev_->hello();
  DeviceTime t;
  t.source = h.clock;  // "dut-cycles" for a cycle counter; the device names any other clock
  t.ns = static_cast<double>(ticks) / h.counter_hz * 1e9;
  if (h.clock == "dut-cycles") t.cycles = static_cast<double>(ticks);
  last_time_ = t;
}

BackendRow dut_row(const DutSpec& spec) {
  auto device = std::make_shared<Device>(spec);
  BackendRow row;
  row.name = spec.name;
  row.needs = "the device at " + spec.text + " (docs/dut-protocol.md)";
  row.probe = [device] { return device->probe(); };
  row.create = [device](const BackendOptions&) -> std::unique_ptr<Backend> {
    if (const std::string why = device->probe(); !why.empty()) throw BackendError(why);
    return std::make_unique<DutBackend>(device);
  };
  row.family = "dut";
  return row;
}

}  // namespace pxflow::dut
