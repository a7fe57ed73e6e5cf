// Unicorn's RV32 CPU (QEMU's RISC-V, RV32IMAFDC) set up with the GAP8 model's memory map: the
// reference the model is compared with, instruction by instruction.
#pragma once

#include <unicorn/unicorn.h>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class UnicornCpu {
 public:
  UnicornCpu();
  ~UnicornCpu();
  UnicornCpu(const UnicornCpu&) = delete;
  UnicornCpu& operator=(const UnicornCpu&) = delete;

  void Write(uint32_t addr, const void* data, size_t size);
  std::vector<uint8_t> Read(uint32_t addr, size_t size);

  uint32_t pc();
  void set_pc(uint32_t pc);
  uint32_t reg(int r);
  void set_reg(int r, uint32_t v);

  // Runs from pc until `end`, calling before_each(pc) before every instruction (registers then
  // hold the state after the previous one); before_each returns false to stop early. Returns
  // empty, or Unicorn's error (an exception such as an illegal instruction).
  std::string Run(uint32_t end, const std::function<bool(uint32_t)>& before_each);

 private:
  static void OnCode(uc_engine* uc, uint64_t address, uint32_t size, void* self);

  uc_engine* uc_ = nullptr;
  const std::function<bool(uint32_t)>* before_each_ = nullptr;
};
