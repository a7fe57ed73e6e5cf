// The ceiling of the SAD work: back-to-back independent SAD instructions on L1-resident data, in
// bytes compared (absolute differences summed) per TSC cycle: psadbw at each width, and the
// multi-SAD instructions the kernels search with (vmpsadbw ymm, vdbpsadbw zmm), which compare
// twice psadbw's bytes per instruction. Each width is in its own file, compiled with the flags of
// the ISA table row whose `ceiling` column names it (hosts/cpu/CMakeLists.txt).
#pragma once
#include <cstdint>
#include <string>

namespace pxflow::cpu {

// Runs `rounds` x 12 independent instructions of the given kind and width, each on 64 L1-resident
// bytes (a 768-byte buffer); returns a value that depends on every result so none is optimised
// away. The rows are reloaded every round (an empty asm makes the pointer opaque), and only they:
// the twelve chains stay in registers. A "memory" clobber per chain kept them on the stack, a
// store and a reload per instruction, which measured the store path (2.4x below vdbpsadbw on
// Zen 4; docs/measurements/bench.md, 2026-12-08).
std::uint64_t psadbw_xmm(const std::uint8_t* data, std::int64_t rounds);
std::uint64_t psadbw_ymm(const std::uint8_t* data, std::int64_t rounds);
std::uint64_t vmpsadbw_ymm(const std::uint8_t* data, std::int64_t rounds);
std::uint64_t psadbw_zmm(const std::uint8_t* data, std::int64_t rounds);
std::uint64_t vdbpsadbw_zmm(const std::uint8_t* data, std::int64_t rounds);

// The SAD instructions this CPU has and may use (the ISA mask applies), e.g. "psadbw xmm,
// psadbw ymm, vmpsadbw ymm, psadbw zmm, vdbpsadbw zmm"; "none" when no x86 SIMD path is available.
std::string ceiling_instructions();

// The one of ceiling_instructions() that compares the most bytes per TSC cycle on one thread,
// measured now, with that rate; {"none", 0} when there is none.
struct Ceiling {
  std::string instruction;
  double bytes_per_cycle;
};
Ceiling fastest_instruction();

// Bytes compared per TSC cycle by `threads` threads each running back-to-back `instruction` (a
// name of ceiling_instructions()) at once, summed (two threads on the two hyperthreads of one core
// share its ports); each thread's fastest of many trials, counted only while every thread still
// runs, since others may share the machine. 0 for an instruction this CPU may not use.
double measure_ceiling(const std::string& instruction, int threads);

}  // namespace pxflow::cpu
