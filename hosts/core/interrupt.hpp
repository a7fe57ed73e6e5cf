// Every signal has one policy (install_interrupt_handlers):
//   - SIGINT, SIGTERM, SIGHUP: the first one asks the run to stop at the next point where nothing
//     is half done (between check cases, bench points, report steps, a sequence's pairs, and
//     within a second while a read waits on a FIFO, a pipe or a terminal: the handlers are
//     installed without SA_RESTART, so a blocked read returns EINTR). Whole files are written only
//     when complete and streams keep their completed records (io/output_plan); the CLI says
//     whether any file changed and exits 128 + the signal: 130, 143, 129.
//   - Another one within kStopGraceMs of the first is the same stop delivered twice (`timeout -s
//     INT` sends two; so does an impatient double Ctrl-C): the wind-down goes on and keeps what
//     one signal keeps, exit 128 + the first signal.
//   - One later than that, during a wind-down that is taking long, ends the process at once, in the
//     handler, with async-signal-safe calls only (the last resort io/in_flight.hpp sets): every
//     stream that holds records is cut to its last complete record, gets the incomplete marker and
//     is renamed into place; every other temporary is removed; one line on stderr; _exit(128 + the
//     signal).
//   - SIGPIPE (a reader that went away, `| head -3`): a stop like the first SIGINT, exit 141
//     (128 + SIGPIPE), the streams kept; the write that caused it returns EPIPE, which
//     io/output_plan turns into the same stop at once (stop_now). It is never the last resort.
//   - SIGXFSZ (beyond `ulimit -f`): nothing; the write returns EFBIG, a failed write like a full
//     disk (exit 1).
//   Both are caught by handlers, not SIG_IGN, so that a program pxflow starts gets the default
//   back at exec.
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace pxflow {

// How long after the first stop signal another one is taken as the same stop (see above); the
// environment variable PXFLOW_STOP_GRACE_MS sets another (0: a second signal ends at once).
inline constexpr long long kStopGraceMs = 1000;

struct Interrupted : std::runtime_error {
  int signal;
  Interrupted(int sig, const std::string& what) : std::runtime_error(what), signal(sig) {}
};

void install_interrupt_handlers();

// The signal that asked the run to stop (the first one), or 0.
int interrupt_signal();

// "SIGINT", "SIGTERM", "SIGHUP", "SIGPIPE", ...; "a signal" for any other. Async-signal-safe.
const char* signal_name(int sig);

// Throws Interrupted saying what had finished (`done`, e.g. "12 of 33 cases") when a signal came.
void stop_if_interrupted(const std::string& done);

// The same, for a wait that a signal cut short: "SIGINT while `doing`" (e.g. "reading f.fifo").
void stop_if_interrupted_while(const std::string& doing);

// Records `sig` as the stop (unless a signal came first) and throws Interrupted "SIG...: why":
// EPIPE on standard output is SIGPIPE's stop.
[[noreturn]] void stop_now(int sig, const std::string& why);

// The handler's last resort on a late second signal (above): a function that keeps or removes the
// temporaries being written, with async-signal-safe calls only, given the first signal's name.
// io/in_flight.hpp sets it when it holds a temporary; interrupt itself touches no file.
using LastResort = void (*)(const char* stopped_by);
void set_last_resort(LastResort flush);

}  // namespace pxflow
