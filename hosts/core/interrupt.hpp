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
//     handler, with async-signal-safe calls only: every stream in the in-flight table below that
//     holds records is cut to its last complete record, gets the incomplete marker and is renamed
//     into place; every other temporary is removed; one line on stderr; _exit(128 + the signal).
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

// The outputs being written, for the handler's last resort above: a fixed table the signal
// handler reads without locks. io/output_plan keeps it up to date; nothing else needs it.
namespace in_flight {

enum class Kind : int {
  whole_file,  // removed: the previous file stays
  stream,      // kept when it holds records: cut to its last record, marked, renamed into place
  complete,    // written and synced: renamed into place
  discarded    // being removed
};
enum class Marker : int { json_lines, csv };

// A slot for the temporary `tmp` (open as `fd`) of `target`; -1 when the table is full or a
// path too long (that temporary is then left to the next run's clean-up of dead temporaries).
int begin(const std::string& tmp, const std::string& target, int fd, Kind kind, Marker marker);
void set_kind(int slot, Kind kind);
// A stream's state after a complete record: its size in bytes and its records.
void record(int slot, std::size_t offset, std::size_t records);
void end(int slot);

// The last line of a stream that stopped before its end (written into `buf`, at most `cap`
// bytes; its length), the one definition of the marker, async-signal-safe:
//   JSON lines: {"incomplete": {"records": 243, "stopped_by": "SIGINT"}}
//   CSV:        # incomplete: 243 records, stopped by SIGINT
std::size_t format_marker(char* buf, std::size_t cap, Marker marker, std::size_t records,
                          const char* stopped_by);

}  // namespace in_flight
}  // namespace pxflow
