#include "in_flight.hpp"

#include <limits.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "interrupt.hpp"

namespace pxflow::in_flight {
namespace {

// One temporary being written. The handler may run at any point of the main thread's updates:
// `state` publishes a filled slot (0 free, 1 being filled, 2 live) and a stream's last mark is
// double-buffered, `current` naming the complete one.
struct Slot {
  std::atomic<int> state{0};
  std::atomic<int> kind{0};
  int fd = -1;
  Marker marker = Marker::json_lines;
  struct Mark {
    std::size_t offset = 0, records = 0;
  } marks[2];
  std::atomic<int> current{0};
  char tmp[PATH_MAX] = {};
  char target[PATH_MAX] = {};
};

// pxflow writes a few files at a time (a report's: a dozen or so, with its pictures).
constexpr int kSlots = 64;
Slot g_slots[kSlots];

static_assert(std::atomic<int>::is_always_lock_free);

// Decimal digits of `v` into `out`; their count.
std::size_t put_number(char* out, std::size_t v) {
  char digits[24];
  std::size_t n = 0;
  do digits[n++] = static_cast<char>('0' + v % 10), v /= 10;
  while (v > 0);
  for (std::size_t i = 0; i < n; ++i) out[i] = digits[n - 1 - i];
  return n;
}

// The last resort of a second signal: every live slot as the top of interrupt.hpp says.
void flush_in_flight(const char* stopped_by) {
  for (Slot& s : g_slots) {
    if (s.state.load(std::memory_order_acquire) != 2) continue;
    switch (static_cast<Kind>(s.kind.load())) {
      case Kind::stream: {
        const Slot::Mark m = s.marks[s.current.load(std::memory_order_acquire)];
        if (m.records == 0) {
          ::unlink(s.tmp);
          break;
        }
        char marker[160];
        const std::size_t n = format_marker(marker, sizeof marker, s.marker, m.records, stopped_by);
        const off_t at = static_cast<off_t>(m.offset);
        if (::ftruncate(s.fd, at) == 0 && ::lseek(s.fd, at, SEEK_SET) == at &&
            write_all(s.fd, marker, n) && ::rename(s.tmp, s.target) == 0)
          break;
        ::unlink(s.tmp);  // could not be kept whole: the previous file stays
        break;
      }
      case Kind::complete:
        if (::rename(s.tmp, s.target) != 0) ::unlink(s.tmp);
        break;
      case Kind::whole_file:
      case Kind::discarded:
        ::unlink(s.tmp);
        break;
    }
  }
}

}  // namespace

bool write_all(int fd, const char* bytes, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, bytes, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    bytes += w, n -= static_cast<std::size_t>(w);
  }
  return true;
}

int begin(const std::string& tmp, const std::string& target, int fd, Kind kind, Marker marker) {
  // The second signal's handler keeps or removes these (interrupt.hpp).
  set_last_resort(flush_in_flight);
  if (tmp.size() >= PATH_MAX || target.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kSlots; ++i) {
    Slot& s = g_slots[i];
    int free = 0;
    if (!s.state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(s.tmp, tmp.c_str(), tmp.size() + 1);
    std::memcpy(s.target, target.c_str(), target.size() + 1);
    s.fd = fd;
    s.marker = marker;
    s.marks[0] = s.marks[1] = {};
    s.current.store(0);
    s.kind.store(static_cast<int>(kind));
    s.state.store(2, std::memory_order_release);
    return i;
  }
  return -1;
}

void set_kind(int slot, Kind kind) {
  if (slot >= 0) g_slots[slot].kind.store(static_cast<int>(kind));
}

void record(int slot, std::size_t offset, std::size_t records) {
  if (slot < 0) return;
  Slot& s = g_slots[slot];
  const int next = 1 - s.current.load(std::memory_order_relaxed);
  s.marks[next] = {offset, records};
  s.current.store(next, std::memory_order_release);
}

void end(int slot) {
  if (slot >= 0) g_slots[slot].state.store(0, std::memory_order_release);
}

std::size_t format_marker(char* buf, std::size_t cap, Marker marker, std::size_t records,
                          const char* stopped_by) {
  const bool csv = marker == Marker::csv;
  const char* parts[] = {csv ? "# incomplete: " : "{\"incomplete\": {\"records\": ", nullptr,
                         csv ? " records, stopped by " : ", \"stopped_by\": \"", stopped_by,
                         csv ? "\n" : "\"}}\n"};
  char number[24];
  number[put_number(number, records)] = '\0';
  parts[1] = number;
  std::size_t n = 0;
  for (const char* p : parts)
    for (; *p != '\0' && n + 1 < cap; ++p) buf[n++] = *p;
  return n;
}

}  // namespace pxflow::in_flight
