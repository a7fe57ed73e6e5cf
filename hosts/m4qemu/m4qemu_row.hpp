// The m4-qemu row: the Cortex-M4 kernel (kernels/cortex-m4) in its firmware
// (boards/mps2-an386/dut_main.c) on QEMU's mps2-an386, reached over the device-under-test
// protocol through the dut family's exec link (hosts/dut): QEMU is the child process, its
// emulated UART0 on the child's stdin/stdout.
#pragma once
#include <string>
#include <vector>

namespace pxflow::m4qemu {

// -icount shift=N: one instruction per 2^N ns of virtual time. The firmware converts SysTick
// ticks (25 MHz) to instructions for exactly this N (5 per tick), and says so in HELLO's clock,
// "qemu-icount-instructions".
inline constexpr int kIcountShift = 3;

// The firmware ELF the row runs: --m4-firmware FILE, else the one this build made.
std::string& firmware_path();

// The QEMU command line of the row (argv[0] is looked up in PATH by the exec link).
std::vector<std::string> qemu_command(const std::string& firmware);

// Empty when the row can start QEMU here, else why not (no qemu-system-arm in PATH, no firmware).
std::string prerequisites_missing(const std::string& firmware);

}  // namespace pxflow::m4qemu
