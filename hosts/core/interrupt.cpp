#include "interrupt.hpp"

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

// write() of a C string, errors ignored (the process is about to end).
void say(const char* text) {
  for (std::size_t n = std::strlen(text); n > 0;) {
    const ssize_t w = ::write(2, text, n);
    if (w <= 0) return;
    text += w, n -= static_cast<std::size_t>(w);
  }
}

std::atomic<LastResort> g_last_resort{nullptr};

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
  if (const LastResort flush = g_last_resort.load()) flush(signal_name(first));
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

void set_last_resort(LastResort flush) { g_last_resort.store(flush); }
}  // namespace pxflow
