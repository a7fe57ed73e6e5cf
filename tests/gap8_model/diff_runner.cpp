#include "diff_runner.h"

#include <memory>
#include <sstream>
#include <vector>

#include "gap8/core.h"
#include "unicorn_cpu.h"

namespace {

std::string Hex(uint32_t v) { return gap8::Hex(v); }

// The first register or pc difference, or empty.
std::string CompareState(gap8::Core& core, UnicornCpu& uc, uint32_t uc_pc) {
  if (core.pc() != uc_pc) return "pc: model " + Hex(core.pc()) + ", unicorn " + Hex(uc_pc);
  for (int r = 1; r < 32; ++r) {
    if (core.reg(r) == uc.reg(r)) continue;
    std::ostringstream out;
    out << 'x' << r << ": model " << Hex(core.reg(r)) << ", unicorn " << Hex(uc.reg(r));
    return out.str();
  }
  return "";
}

std::string CompareRegion(gap8::Memory& memory, UnicornCpu& uc, uint32_t base, uint32_t size) {
  std::vector<uint8_t> mine(size);
  memory.Read(base, mine.data(), size);
  const std::vector<uint8_t> theirs = uc.Read(base, size);
  for (uint32_t i = 0; i < size; ++i) {
    if (mine[i] == theirs[i]) continue;
    std::ostringstream out;
    out << "memory at " << Hex(base + i) << ": model " << int{mine[i]} << ", unicorn "
        << int{theirs[i]};
    return out.str();
  }
  return "";
}

void CopyRegion(gap8::Memory& memory, UnicornCpu& uc, uint32_t base, uint32_t size) {
  std::vector<uint8_t> bytes(size);
  memory.Read(base, bytes.data(), size);
  uc.Write(base, bytes.data(), size);
}

}  // namespace

Regions WholeMemory() { return {{GAP8_L1_BASE, GAP8_L1_SIZE}, {GAP8_L2_BASE, GAP8_L2_SIZE}}; }

DiffOutcome RunDifferential(UnicornCpu& uc, gap8::Memory& memory, uint32_t start, uint32_t end,
                            const uint32_t (&regs)[32], uint64_t max_steps,
                            const Regions& regions) {
  for (const auto& [base, size] : regions) CopyRegion(memory, uc, base, size);
  gap8::Core core(0, memory, nullptr);
  core.set_pc(start);
  uc.set_pc(start);
  for (int r = 1; r < 32; ++r) {
    core.set_reg(r, regs[r]);
    uc.set_reg(r, regs[r]);
  }
  DiffOutcome out;
  uint32_t last_pc = start;
  bool first = true;  // the first callback comes before any instruction ran
  auto step_model = [&]() -> std::string {
    try {
      core.Step();
    } catch (const gap8::Fault& f) {
      return "model faulted: " + f.Message();
    }
    ++out.steps;
    return "";
  };
  std::function<bool(uint32_t)> before_each = [&](uint32_t pc) {
    if (!first) {
      std::string d = step_model();
      if (d.empty()) d = CompareState(core, uc, pc);
      if (!d.empty()) out.difference = d + " after the instruction at " + Hex(last_pc);
    }
    first = false;
    last_pc = pc;
    if (out.difference.empty() && out.steps >= max_steps)
      out.difference = "still running after " + std::to_string(max_steps) + " instructions";
    return out.difference.empty();
  };
  const std::string error = uc.Run(end, before_each);
  if (out.difference.empty() && !error.empty())
    out.difference = "unicorn stopped at " + Hex(uc.pc()) + ": " + error;
  if (out.difference.empty()) {  // Unicorn reached `end`: the model runs its last instruction
    std::string d = step_model();
    if (d.empty()) d = CompareState(core, uc, uc.pc());
    if (!d.empty()) out.difference = d + " after the instruction at " + Hex(last_pc);
  }
  for (const auto& [base, size] : regions) {
    if (out.difference.empty()) out.difference = CompareRegion(memory, uc, base, size);
  }
  out.same = out.difference.empty();
  return out;
}
