// The messages between `pxflow check` and its workers (check_worker.hpp): one request, one
// reply, over a pipe each way. Both ends are the same binary, so plain structs (Params, OpCounts,
// PoiRecord) travel as their bytes. A message is a type byte, a 32-bit length and the payload.
#pragma once
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow::worker {

// A message that does not parse: the other end is not a pxflow worker of this binary.
struct WireError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Type : std::uint8_t {
  kHello = 'H',          // worker -> pxflow, once: the backend opened, or why not
  kCase = 'C',           // pxflow -> worker: params and pairs to run
  kPrepare = 'P',        // pxflow -> worker: params (no pairs) whose kernels to build first
  kPrepared = 'R',       // built (Backend::prepare): the seconds it took
  kNotApplicable = 'N',  // the backend does not support the case's params: why
  kDone = 'D',           // records, counts, seconds, and what the guards saw
  kError = 'E',          // run() threw: the message
  kFault = 'F',          // written by the worker's SIGSEGV/SIGBUS handler just before it dies
};

struct Message {
  Type type{};
  std::vector<std::uint8_t> payload;
};

// The header of every message: type, then the payload's length (little-endian, as the host's).
inline constexpr std::size_t kHeaderBytes = 5;
// Bytes of a message with this payload: what a reader waits for.
std::vector<std::uint8_t> frame_message(Type type, std::span<const std::uint8_t> payload);

// Appends values to a payload.
class Writer {
 public:
  template <class T>
  Writer& pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* b = reinterpret_cast<const std::uint8_t*>(&v);
    bytes_.insert(bytes_.end(), b, b + sizeof v);
    return *this;
  }
  Writer& bytes(std::span<const std::uint8_t> b);  // its length, then the bytes
  Writer& text(const std::string& s);              // the same
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

// Reads them back in the same order; throws WireError past the end.
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> payload) : rest_(payload) {}
  template <class T>
  T pod() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    std::memcpy(&v, take(sizeof v).data(), sizeof v);
    return v;
  }
  std::span<const std::uint8_t> bytes();
  std::string text();
  bool done() const { return rest_.empty(); }

 private:
  std::span<const std::uint8_t> take(std::size_t n);
  std::span<const std::uint8_t> rest_;
};

// kHello.
struct Hello {
  enum class State : std::uint8_t { kOpened, kCannotRun, kInputError } state = State::kOpened;
  std::string why;                     // kCannotRun: the reason; kInputError: the error
  std::string implementation, device;  // Backend::describe() when opened
};
std::vector<std::uint8_t> encode(const Hello& h);
Hello decode_hello(std::span<const std::uint8_t> payload);

// kCase: the frames of each pair, packed (stride = width).
std::vector<std::uint8_t> encode_case(const Params& p, std::span<const FramePair> pairs);
struct DecodedCase {
  Params params;
  std::vector<Frame> frames;  // prev, next, prev, next ...
};
DecodedCase decode_case(std::span<const std::uint8_t> payload);

// kDone.
struct Done {
  double seconds = 0;  // inside run()
  OpCounts counts;
  std::vector<PoiRecord> records;
  std::string guard_note;  // empty: the guards around the output are intact
};
std::vector<std::uint8_t> encode(const Done& d);
Done decode_done(std::span<const std::uint8_t> payload);

// kFault: where the faulting address was, as the signal handler saw it (async-signal-safe: a
// fixed-size struct written with one write()).
struct Fault {
  enum Where : std::uint32_t { kElsewhere, kBeforeInput, kPastInput, kBeforeOutput, kPastOutput };
  std::uint32_t where = kElsewhere;
  std::uint32_t pair = 0;     // the input's pair within the request
  std::uint32_t next = 0;     // 1: the pair's next frame, 0: its prev frame
  std::uint64_t bytes = 0;    // how far before the start or past the end
  std::uint64_t records = 0;  // kPastOutput/kBeforeOutput: the output's record count
};
// "it read 1 byte past the end of the pair's next frame" (pair_name: the pair's, in words).
std::string fault_text(const Fault& f, const std::string& pair_name);

}  // namespace pxflow::worker
