// The outputs being written, for the signal handler's last resort (core/interrupt.hpp): a fixed
// table the handler reads without locks, which io/output_plan keeps up to date. On a late second
// signal every stream that holds records is cut to its last complete record, gets the incomplete
// marker and is renamed into place; every other temporary is removed.
#pragma once
#include <cstddef>
#include <string>

namespace pxflow::in_flight {

enum class Kind : int {
  whole_file,  // removed: the previous file stays
  stream,      // kept when it holds records: cut to its last record, marked, renamed into place
  complete,    // written and synced: renamed into place
  discarded    // being removed
};
enum class Marker : int { json_lines, csv };

// Writes all of `bytes` to `fd` (EINTR retried); false, errno set, on any failure.
// Async-signal-safe: the handler's last resort and io/output_plan write through it.
bool write_all(int fd, const char* bytes, std::size_t n);

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

}  // namespace pxflow::in_flight
