#include "worker_wire.hpp"

#include <algorithm>

#include "counted.hpp"

namespace pxflow::worker {

std::vector<std::uint8_t> frame_message(Type type, std::span<const std::uint8_t> payload) {
  Writer w;
  w.pod(type).pod(static_cast<std::uint32_t>(payload.size()));
  std::vector<std::uint8_t> message = w.take();
  // resize and copy, not insert: GCC 12 sees a false out-of-bounds memcpy in the inlined insert
  // of this 5-byte vector when the unity batch gives it more context (-Warray-bounds).
  const std::size_t head = message.size();
  message.resize(head + payload.size());
  std::copy(payload.begin(), payload.end(), message.begin() + static_cast<std::ptrdiff_t>(head));
  return message;
}

Writer& Writer::bytes(std::span<const std::uint8_t> b) {
  pod(static_cast<std::uint32_t>(b.size()));
  bytes_.insert(bytes_.end(), b.begin(), b.end());
  return *this;
}

Writer& Writer::text(const std::string& s) {
  return bytes({reinterpret_cast<const std::uint8_t*>(s.data()), s.size()});
}

std::span<const std::uint8_t> Reader::take(std::size_t n) {
  if (n > rest_.size()) throw WireError("a worker message ends early");
  const auto b = rest_.first(n);
  rest_ = rest_.subspan(n);
  return b;
}

std::span<const std::uint8_t> Reader::bytes() { return take(pod<std::uint32_t>()); }

std::string Reader::text() {
  const auto b = bytes();
  return {reinterpret_cast<const char*>(b.data()), b.size()};
}

std::vector<std::uint8_t> encode(const Hello& h) {
  Writer w;
  w.pod(h.state).text(h.why).text(h.implementation).text(h.device);
  return w.take();
}

Hello decode_hello(std::span<const std::uint8_t> payload) {
  Reader r(payload);
  Hello h;
  h.state = r.pod<Hello::State>();
  h.why = r.text();
  h.implementation = r.text();
  h.device = r.text();
  return h;
}

std::vector<std::uint8_t> encode_case(const Params& p, std::span<const FramePair> pairs) {
  Writer w;
  w.pod(p).pod(static_cast<std::uint32_t>(pairs.size()));
  std::vector<std::uint8_t> packed(static_cast<std::size_t>(p.width) * p.height);
  for (const FramePair& pair : pairs)
    for (const FrameView& f : {pair.prev, pair.next}) {
      for (int y = 0; y < p.height; ++y)
        std::memcpy(packed.data() + static_cast<std::size_t>(y) * p.width, f.row(y), p.width);
      w.bytes(packed);
    }
  return w.take();
}

DecodedCase decode_case(std::span<const std::uint8_t> payload) {
  Reader r(payload);
  DecodedCase c{r.pod<Params>(), {}};
  const std::size_t frames = 2 * std::size_t{r.pod<std::uint32_t>()};
  const std::size_t size = static_cast<std::size_t>(c.params.width) * c.params.height;
  for (std::size_t i = 0; i < frames; ++i) {
    const auto b = r.bytes();
    if (b.size() != size) throw WireError("a worker's frame has the wrong size");
    c.frames.push_back({c.params.width, c.params.height, {b.begin(), b.end()}});
  }
  return c;
}

std::vector<std::uint8_t> encode(const Done& d) {
  Writer w;
  w.pod(d.seconds).pod(d.counts).text(d.guard_note);
  w.bytes({reinterpret_cast<const std::uint8_t*>(d.records.data()),
           d.records.size() * sizeof(PoiRecord)});
  return w.take();
}

Done decode_done(std::span<const std::uint8_t> payload) {
  Reader r(payload);
  Done d;
  d.seconds = r.pod<double>();
  d.counts = r.pod<OpCounts>();
  d.guard_note = r.text();
  const auto b = r.bytes();
  if (b.size() % sizeof(PoiRecord) != 0) throw WireError("a worker's records are cut");
  d.records.resize(b.size() / sizeof(PoiRecord));
  std::memcpy(d.records.data(), b.data(), b.size());
  return d;
}

std::string fault_text(const Fault& f, const std::string& pair_name) {
  const std::string bytes = counted(static_cast<long>(f.bytes), "byte");
  const std::string frame = std::string(f.next ? "next" : "prev") + " frame of " + pair_name;
  switch (f.where) {
    case Fault::kPastInput:
      return "it read " + bytes + " past the end of the " + frame + " (strict input)";
    case Fault::kBeforeInput:
      return "it read " + bytes + " before the start of the " + frame + " (strict input)";
    case Fault::kPastOutput:
      return "it went " + bytes + " past its output (after record " +
             std::to_string(f.records - 1) + ")";
    case Fault::kBeforeOutput:
      return "it went " + bytes + " before its output (before record 0)";
    default:
      return {};
  }
}

}  // namespace pxflow::worker
