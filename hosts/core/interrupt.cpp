#include "interrupt.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>

namespace pxflow {
namespace {

std::atomic<int> g_signal{0};

// One temporary being written. The handler may run at any point of the main thread's updates:
// `state` publishes a filled slot (0 free, 1 being filled, 2 live) and a stream's last mark is
// double-buffered, `current` naming the complete one.
struct Slot {
  std::atomic<int> state{0};
  std::atomic<int> kind{0};
  int fd = -1;
  in_flight::Marker marker = in_flight::Marker::json_lines;
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

// write() of a C string, errors ignored (the process is about to end).
void say(const char* text) {
  for (std::size_t n = std::strlen(text); n > 0;) {
    const ssize_t w = ::write(2, text, n);
    if (w <= 0) return;
    text += w, n -= static_cast<std::size_t>(w);
  }
}

bool write_all(int fd, const char* bytes, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, bytes, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    bytes += w, n -= static_cast<std::size_t>(w);
  }
  return true;
}

// The last resort of a second signal: every live slot as the top of interrupt.hpp says.
void flush_in_flight(const char* stopped_by) {
  for (Slot& s : g_slots) {
    if (s.state.load(std::memory_order_acquire) != 2) continue;
    switch (static_cast<in_flight::Kind>(s.kind.load())) {
      case in_flight::Kind::stream: {
        const Slot::Mark m = s.marks[s.current.load(std::memory_order_acquire)];
        if (m.records == 0) {
          ::unlink(s.tmp);
          break;
        }
        char marker[160];
        const std::size_t n =
            in_flight::format_marker(marker, sizeof marker, s.marker, m.records, stopped_by);
        const off_t at = static_cast<off_t>(m.offset);
        if (::ftruncate(s.fd, at) == 0 && ::lseek(s.fd, at, SEEK_SET) == at &&
            write_all(s.fd, marker, n) && ::rename(s.tmp, s.target) == 0)
          break;
        ::unlink(s.tmp);  // could not be kept whole: the previous file stays
        break;
      }
      case in_flight::Kind::complete:
        if (::rename(s.tmp, s.target) != 0) ::unlink(s.tmp);
        break;
      case in_flight::Kind::whole_file:
      case in_flight::Kind::discarded:
        ::unlink(s.tmp);
        break;
    }
  }
}

// CLOCK_MONOTONIC in milliseconds (clock_gettime is async-signal-safe).
long long now_ms() {
  timespec t{};
  ::clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<long long>(t.tv_sec) * 1000 + t.tv_nsec / 1000000;
}

std::atomic<long long> g_first_ms{0};
long long g_grace_ms = kStopGraceMs;  // PXFLOW_STOP_GRACE_MS, read once at install

extern "C" void on_stop_signal(int sig) {
  const int saved_errno = errno;
  int first = 0;
  if (g_signal.compare_exchange_strong(first, sig)) {  // the first: a request to stop
    g_first_ms.store(now_ms());
    errno = saved_errno;
    return;
  }
  // Within the grace after the first, the same stop delivered twice (`timeout -s INT`, a double
  // Ctrl-C): the wind-down goes on and keeps what one signal keeps.
  if (now_ms() - g_first_ms.load() < g_grace_ms) {
    errno = saved_errno;
    return;
  }
  flush_in_flight(signal_name(first));
  say("pxflow: ");
  say(signal_name(sig));
  say(" during the stop: ended at once; streams kept up to their last complete record\n");
  ::_exit(128 + sig);
}

// SIGPIPE: a reader went away; the write that caused it returns EPIPE. A stop like the first
// SIGINT (a command that writes to standard output now and then sees it at its next stop
// point), never the last resort.
extern "C" void on_broken_pipe(int sig) {
  int none = 0;
  g_signal.compare_exchange_strong(none, sig);
}

// SIGXFSZ: the write that caused it returns EFBIG, a failed write like a full disk.
extern "C" void on_ignored_signal(int) {}

void install(int sig, void (*handler)(int)) {
  struct sigaction a {};
  a.sa_handler = handler;
  ::sigemptyset(&a.sa_mask);
  // The stop signals do not interrupt one another's handler.
  for (int s : {SIGINT, SIGTERM, SIGHUP}) ::sigaddset(&a.sa_mask, s);
  a.sa_flags = 0;  // no SA_RESTART: a read blocked on a FIFO returns EINTR
  ::sigaction(sig, &a, nullptr);
}

// Decimal digits of `v` into `out`; their count.
std::size_t put_number(char* out, std::size_t v) {
  char digits[24];
  std::size_t n = 0;
  do digits[n++] = static_cast<char>('0' + v % 10), v /= 10;
  while (v > 0);
  for (std::size_t i = 0; i < n; ++i) out[i] = digits[n - 1 - i];
  return n;
}

}  // namespace

void install_interrupt_handlers() {
  if (const char* grace = std::getenv("PXFLOW_STOP_GRACE_MS"); grace && *grace)
    g_grace_ms = std::max(0LL, std::atoll(grace));
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) install(sig, on_stop_signal);
  install(SIGPIPE, on_broken_pipe);
  install(SIGXFSZ, on_ignored_signal);
}

int interrupt_signal() { return g_signal.load(); }

const char* signal_name(int sig) {
  switch (sig) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    case SIGPIPE:
      return "SIGPIPE";
    default:
      return "a signal";
  }
}

void stop_if_interrupted(const std::string& done) {
  if (const int sig = interrupt_signal())
    throw Interrupted(sig, std::string(signal_name(sig)) + " after " + done);
}

void stop_if_interrupted_while(const std::string& doing) {
  if (const int sig = interrupt_signal())
    throw Interrupted(sig, std::string(signal_name(sig)) + " while " + doing);
}

void stop_now(int sig, const std::string& why) {
  int first = 0;
  g_signal.compare_exchange_strong(first, sig);
  throw Interrupted(sig, std::string(signal_name(sig)) + ": " + why);
}

namespace in_flight {

int begin(const std::string& tmp, const std::string& target, int fd, Kind kind, Marker marker) {
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

}  // namespace in_flight
}  // namespace pxflow
