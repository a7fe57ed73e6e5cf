// The machine's state around a bench (docs/harness.md, "Statistics"): load average and clock
// before and after, and the CPU time other processes and the hypervisor took meanwhile, read
// from /proc. Where /proc is not readable every figure says "unknown" (-1 or 0), never 0 load.
#pragma once
#include <cstdint>
#include <string>

#include "bench.hpp"

namespace pxflow {

// A run is disturbed when other processes (or the hypervisor's steal) took more than this share
// of every CPU's time while it ran: its figures may be slower than the machine is.
inline constexpr double kDisturbedShare = 0.10;

MachineState read_machine_state();

// Counts of CPU time at one moment: the machine's and this process's (threads included).
struct CpuTimes {
  std::uint64_t total = 0, idle = 0, steal = 0;  // every CPU, in clock ticks
  std::uint64_t own = 0;                         // this process, in clock ticks
  bool known = false;
};
CpuTimes read_cpu_times();

// From two snapshots and the states before and after: the shares and the verdict.
MachineLoad machine_load(const MachineState& before, const CpuTimes& t0, const MachineState& after,
                         const CpuTimes& t1);

// One line for the bench's output and the report's first screen: "machine: quiet (...)" or
// "machine: DISTURBED: ...; rerun on a quiet machine".
std::string machine_line(const MachineLoad& m);

// The JSON object of the bench file's "machine" (docs/report-schema.md), and back.
Json machine_json(const MachineLoad& m);
MachineLoad machine_from_json(const Json& j);

}  // namespace pxflow
