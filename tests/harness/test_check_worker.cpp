// The check worker's protocol and guarded memory (hosts/harness/check/worker_wire.hpp,
// guarded_run.hpp), in-process: what crosses the pipe comes back equal, a cut message is refused,
// the guards see a write outside the output, and every frame ends at a page boundary.
#include <unistd.h>

#include <catch2/catch.hpp>

#include "exactness.hpp"
#include "guarded_run.hpp"
#include "worker_wire.hpp"

using namespace pxflow;
using namespace pxflow::worker;

TEST_CASE("a case crosses the wire with its params and packed frames", "[worker]") {
  Params p;
  p.width = 5, p.height = 3, p.search_radius = 2;
  std::vector<std::uint8_t> wide(7 * 3);  // a stride of 7: the wire packs it to 5
  for (std::size_t i = 0; i < wide.size(); ++i) wide[i] = static_cast<std::uint8_t>(i);
  const FrameView v{5, 3, 7, wide.data()};
  const FramePair pairs[] = {{v, v}};
  const DecodedCase c = decode_case(encode_case(p, pairs));
  CHECK(c.params == p);
  REQUIRE(c.frames.size() == 2);
  CHECK(c.frames[1].pixels ==
        std::vector<std::uint8_t>{0, 1, 2, 3, 4, 7, 8, 9, 10, 11, 14, 15, 16, 17, 18});
}

TEST_CASE("hello and done come back equal, a cut message is refused", "[worker]") {
  const Hello h{Hello::State::kCannotRun, "no device", "impl", "dev"};
  const Hello back = decode_hello(encode(h));
  CHECK((back.state == h.state && back.why == h.why && back.implementation == h.implementation &&
         back.device == h.device));
  Done d;
  d.seconds = 0.25;
  d.counts = {true, 91520, 7};
  d.records = sentinel_records(3);
  d.guard_note = "wrote past its output (16 bytes after record 2)";
  const std::vector<std::uint8_t> bytes = encode(d);
  const Done e = decode_done(bytes);
  CHECK(e.seconds == d.seconds);
  CHECK((e.counts.counted && e.counts.sad_ops == 91520 && e.counts.interpolations == 7));
  CHECK(e.guard_note == d.guard_note);
  CHECK(std::memcmp(e.records.data(), d.records.data(), 3 * sizeof(PoiRecord)) == 0);
  const std::vector<std::uint8_t> cut(bytes.begin(), bytes.end() - 1);
  CHECK_THROWS_AS(decode_done(cut), WireError);
  const auto message = frame_message(Type::kDone, bytes);
  CHECK(message.size() == kHeaderBytes + bytes.size());
  CHECK(message[0] == 'D');
}

TEST_CASE("the guards around the output see a write past it or before it", "[worker]") {
  const std::vector<Frame> frames = {{5, 3, std::vector<std::uint8_t>(15, 1)},
                                     {5, 3, std::vector<std::uint8_t>(15, 2)}};
  const long page = sysconf(_SC_PAGESIZE);
  {
    GuardedRun g(frames, sentinel_records(4));
    CHECK(g.check_guards().empty());
    // Each frame's last byte is the last of its page: the next byte is inaccessible.
    for (const FramePair& p : g.pairs())
      for (const FrameView& f : {p.prev, p.next})
        CHECK(reinterpret_cast<std::uintptr_t>(f.data + 15) % page == 0);
    CHECK(g.pairs()[0].next.data[14] == 2);
    PoiRecord* out = g.output().data();
    out[4] = out[0];  // one record past the end
    CHECK(g.check_guards() ==
          "wrote past its output (" + std::to_string(sizeof(PoiRecord)) + " bytes after record 3)");
  }
  GuardedRun g(frames, sentinel_records(4));
  reinterpret_cast<std::uint8_t*>(g.output().data())[-3] = 0;
  CHECK(g.check_guards() == "wrote before its output (3 bytes before record 0)");
}

TEST_CASE("a fault in the guard pages is said in words", "[worker]") {
  Fault f;
  f.where = Fault::kPastInput;
  f.next = 1;
  f.bytes = 1;
  CHECK(fault_text(f, "the pair") ==
        "it read 1 byte past the end of the next frame of the pair (strict input)");
  f.where = Fault::kPastOutput;
  f.bytes = 40;
  f.records = 64;
  CHECK(fault_text(f, "the pair") == "it went 40 bytes past its output (after record 63)");
}
