#include "guarded_run.hpp"

#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <new>

#include "worker_wire.hpp"

namespace pxflow::worker {
namespace {

std::size_t page_size() {
  static const std::size_t p = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return p;
}
std::size_t round_up(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }

// What the handler compares the faulting address with: the readable areas of the run in
// flight, in address order. Only plain data and atomics: the handler reads it.
struct Area {
  std::uintptr_t begin, end;  // [begin, end): a frame, or the output (without its guards)
  std::uint32_t pair, next;   // for a frame
  bool output;
};
std::atomic<const Area*> g_areas{nullptr};
std::atomic<std::size_t> g_area_count{0};
std::atomic<std::uintptr_t> g_map_begin{0}, g_map_end{0};
std::atomic<std::uint64_t> g_records{0};
int g_report_fd = -1;
std::vector<Area> g_area_store;  // owned here; g_areas points into it while armed

// The area nearest to `addr` (which lies outside every area, in the mapping), as a kFault.
Fault locate(std::uintptr_t addr) {
  Fault f;
  const Area* areas = g_areas.load();
  const std::size_t n = g_area_count.load();
  std::uint64_t best = ~std::uint64_t{0};
  for (std::size_t i = 0; i < n; ++i) {
    const Area& a = areas[i];
    const bool past = addr >= a.end;
    const std::uint64_t d = past ? addr - a.end + 1 : a.begin - addr;
    if (addr >= a.begin && addr < a.end) return Fault{};  // inside: not ours to explain
    if (d >= best) continue;
    best = d;
    f.where = a.output ? (past ? Fault::kPastOutput : Fault::kBeforeOutput)
                       : (past ? Fault::kPastInput : Fault::kBeforeInput);
    f.pair = a.pair;
    f.next = a.next;
    f.bytes = d;
    f.records = g_records.load();
  }
  return f;
}

extern "C" void on_fault(int sig, siginfo_t* info, void*) {
  const auto addr = reinterpret_cast<std::uintptr_t>(info->si_addr);
  if (info->si_code > 0 && addr >= g_map_begin.load() && addr < g_map_end.load()) {
    const Fault f = locate(addr);
    if (f.where != Fault::kElsewhere) {
      // One write of a few dozen bytes to a pipe is atomic; write() is async-signal-safe.
      std::uint8_t msg[kHeaderBytes + sizeof f];
      msg[0] = static_cast<std::uint8_t>(Type::kFault);
      const auto len = static_cast<std::uint32_t>(sizeof f);
      std::memcpy(msg + 1, &len, sizeof len);
      std::memcpy(msg + kHeaderBytes, &f, sizeof f);
      (void)!::write(g_report_fd, msg, sizeof msg);
    }
  }
  // SA_RESETHAND restored the default action: a fault re-faults on return, a raised signal
  // (raise(SIGSEGV), si_code <= 0) is raised again; either way the worker dies of `sig`.
  raise(sig);
}

}  // namespace

GuardedRun::GuardedRun(const std::vector<Frame>& frames, const std::vector<PoiRecord>& fill) {
  const std::size_t page = page_size();
  records_ = fill.size();
  const std::size_t out_bytes = records_ * sizeof(PoiRecord);
  const std::size_t guard = GuardedRun::kGuardRecords * sizeof(PoiRecord);
  const std::size_t out_slot = round_up(out_bytes + 2 * guard, page);
  // Inaccessible page, output slot, then per frame: inaccessible page, frame slot; last, an
  // inaccessible page.
  std::size_t total = page + out_slot;
  for (const Frame& f : frames) total += page + round_up(f.pixels.size(), page);
  total += page;
  void* m = mmap(nullptr, total, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (m == MAP_FAILED) throw std::bad_alloc();
  map_ = static_cast<std::uint8_t*>(m);
  map_bytes_ = total;
  std::vector<Area> areas;
  auto open_slot = [&](std::uint8_t* at, std::size_t bytes) {
    if (bytes > 0 && mprotect(at, bytes, PROT_READ | PROT_WRITE) != 0) {
      munmap(map_, map_bytes_);
      throw std::bad_alloc();
    }
  };
  // The output: its guards fill the slot around it; it ends a guard before the slot's end.
  slot_begin_ = map_ + page;
  slot_end_ = slot_begin_ + out_slot;
  open_slot(slot_begin_, out_slot);
  std::memset(slot_begin_, kGuardByte, out_slot);
  out_ = reinterpret_cast<PoiRecord*>(slot_end_ - guard - out_bytes);
  std::copy(fill.begin(), fill.end(), out_);
  const auto out_at = reinterpret_cast<std::uintptr_t>(out_);
  areas.push_back({out_at, out_at + out_bytes, 0, 0, true});
  // The frames: each one's last byte is the last before an inaccessible page.
  std::uint8_t* at = slot_end_;
  std::vector<FrameView> views;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    const std::size_t slot = round_up(f.pixels.size(), page);
    at += page;
    open_slot(at, slot);
    std::uint8_t* data = at + slot - f.pixels.size();
    std::copy(f.pixels.begin(), f.pixels.end(), data);
    if (slot > 0) mprotect(at, slot, PROT_READ);  // input: a write to it crashes as well
    const auto d = reinterpret_cast<std::uintptr_t>(data);
    areas.push_back({d, d + f.pixels.size(), static_cast<std::uint32_t>(i / 2),
                     static_cast<std::uint32_t>(i % 2), false});
    views.push_back({f.width, f.height, f.width, data});
    at += slot;
  }
  for (std::size_t i = 0; i + 1 < views.size(); i += 2) pairs_.push_back({views[i], views[i + 1]});
  g_area_store = std::move(areas);
  g_records.store(records_);
  g_areas.store(g_area_store.data());
  g_area_count.store(g_area_store.size());
  g_map_begin.store(reinterpret_cast<std::uintptr_t>(map_));
  g_map_end.store(reinterpret_cast<std::uintptr_t>(map_) + map_bytes_);
}

GuardedRun::~GuardedRun() {
  g_map_end.store(0);
  g_map_begin.store(0);
  g_area_count.store(0);
  munmap(map_, map_bytes_);
}

std::string GuardedRun::check_guards() const {
  const auto* out = reinterpret_cast<const std::uint8_t*>(out_);
  const std::uint8_t* out_end = out + records_ * sizeof(PoiRecord);
  const std::uint8_t* begin = slot_begin_;
  const std::uint8_t* first_changed =
      std::find_if(begin, out, [](std::uint8_t b) { return b != kGuardByte; });
  std::string note;
  if (first_changed != out)
    note = "wrote before its output (" + std::to_string(out - first_changed) +
           " bytes before record 0)";
  std::size_t past = 0;  // how far the furthest changed byte after the output lies
  for (const std::uint8_t* b = out_end; b < slot_end_; ++b)
    if (*b != kGuardByte) past = static_cast<std::size_t>(b - out_end) + 1;
  if (past > 0)
    note += (note.empty() ? "" : "; ") + std::string("wrote past its output (") +
            std::to_string(past) + " bytes after record " +
            (records_ > 0 ? std::to_string(records_ - 1) : std::string("-")) + ")";
  return note;
}

void install_fault_reporter(int report_fd) {
  g_report_fd = report_fd;
  // Its own stack on this thread: a fault from a stack overflow still gets its note.
  static std::vector<std::uint8_t> stack(std::max<std::size_t>(SIGSTKSZ, 64 * 1024));
  stack_t ss{};
  ss.ss_sp = stack.data();
  ss.ss_size = stack.size();
  sigaltstack(&ss, nullptr);
  struct sigaction a {};
  a.sa_sigaction = on_fault;
  a.sa_flags = SA_SIGINFO | SA_RESETHAND | SA_ONSTACK;
  sigemptyset(&a.sa_mask);
  sigaction(SIGSEGV, &a, nullptr);
  sigaction(SIGBUS, &a, nullptr);
}

}  // namespace pxflow::worker
