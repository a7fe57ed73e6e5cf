// The memory a check worker hands to run() (docs/harness.md, "Isolation"): every input frame ends
// at an inaccessible page (and starts after one), the output records sit between guard bytes
// filled with a pattern, and the whole layout is fenced by inaccessible pages. A read past a
// frame then crashes the worker, and its SIGSEGV handler says where, before it dies; a write past
// the output either changes a guard byte (found after the run) or crashes the same way.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "frame.hpp"
#include "record.hpp"

namespace pxflow::worker {

class GuardedRun {
 public:
  // `frames`: prev, next, prev, next ... (packed); `records`: the output's size. The output
  // starts filled with `fill` (the checker's sentinel records). Throws std::bad_alloc when the
  // mapping fails.
  GuardedRun(const std::vector<Frame>& frames, const std::vector<PoiRecord>& fill);
  ~GuardedRun();
  GuardedRun(const GuardedRun&) = delete;
  GuardedRun& operator=(const GuardedRun&) = delete;

  std::span<const FramePair> pairs() const { return pairs_; }
  std::span<PoiRecord> output() const { return {out_, records_}; }
  // Empty when every guard byte is intact; else "wrote past its output (N bytes after record K)"
  // or "wrote before its output (N bytes before record 0)".
  std::string check_guards() const;

  // Guard bytes on each side of the output, at least (a multiple of a record).
  static constexpr std::size_t kGuardRecords = 4;
  static constexpr std::uint8_t kGuardByte = 0x5A;  // not the sentinel records' 0xA5

 private:
  std::uint8_t* map_ = nullptr;
  std::size_t map_bytes_ = 0;
  std::uint8_t *slot_begin_ = nullptr, *slot_end_ = nullptr;  // the output with its guards
  PoiRecord* out_ = nullptr;
  std::size_t records_ = 0;
  std::vector<FramePair> pairs_;
};

// Installs the worker's SIGSEGV/SIGBUS handler: when the faulting address is in a GuardedRun's
// inaccessible pages, it writes a kFault message (worker_wire.hpp) to `report_fd`, then the
// signal kills the worker as it would have.
void install_fault_reporter(int report_fd);

}  // namespace pxflow::worker
