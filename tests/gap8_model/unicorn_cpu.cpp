#include "unicorn_cpu.h"

#include <stdexcept>

#include "../../gap8_model/runtime/gap8_regs.h"

namespace {

void Check(uc_err err, const char* what) {
  if (err != UC_ERR_OK) throw std::runtime_error(std::string(what) + ": " + uc_strerror(err));
}

int RegId(int r) { return UC_RISCV_REG_X0 + r; }

}  // namespace

UnicornCpu::UnicornCpu() {
  Check(uc_open(UC_ARCH_RISCV, UC_MODE_RISCV32, &uc_), "uc_open");
  Check(uc_mem_map(uc_, GAP8_L1_BASE, GAP8_L1_SIZE, UC_PROT_ALL), "map L1");
  Check(uc_mem_map(uc_, GAP8_L2_BASE, GAP8_L2_SIZE, UC_PROT_ALL), "map L2");
}

UnicornCpu::~UnicornCpu() { uc_close(uc_); }

void UnicornCpu::Write(uint32_t addr, const void* data, size_t size) {
  Check(uc_mem_write(uc_, addr, data, size), "uc_mem_write");
}

std::vector<uint8_t> UnicornCpu::Read(uint32_t addr, size_t size) {
  std::vector<uint8_t> bytes(size);
  Check(uc_mem_read(uc_, addr, bytes.data(), size), "uc_mem_read");
  return bytes;
}

uint32_t UnicornCpu::pc() {
  uint32_t v = 0;
  Check(uc_reg_read(uc_, UC_RISCV_REG_PC, &v), "read pc");
  return v;
}

void UnicornCpu::set_pc(uint32_t pc) { Check(uc_reg_write(uc_, UC_RISCV_REG_PC, &pc), "write pc"); }

uint32_t UnicornCpu::reg(int r) {
  uint32_t v = 0;
  Check(uc_reg_read(uc_, RegId(r), &v), "read register");
  return v;
}

void UnicornCpu::set_reg(int r, uint32_t v) {
  Check(uc_reg_write(uc_, RegId(r), &v), "write register");
}

void UnicornCpu::OnCode(uc_engine* uc, uint64_t address, uint32_t, void* self) {
  auto* cpu = static_cast<UnicornCpu*>(self);
  if (!(*cpu->before_each_)(static_cast<uint32_t>(address))) uc_emu_stop(uc);
}

std::string UnicornCpu::Run(uint32_t end, const std::function<bool(uint32_t)>& before_each) {
  before_each_ = &before_each;
  uc_hook hook;
  Check(uc_hook_add(uc_, &hook, UC_HOOK_CODE, reinterpret_cast<void*>(&OnCode), this, 1, 0),
        "uc_hook_add");
  const uc_err err = uc_emu_start(uc_, pc(), end, 0, 0);
  uc_hook_del(uc_, hook);
  return err == UC_ERR_OK ? "" : uc_strerror(err);
}
