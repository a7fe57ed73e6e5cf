// The m4-qemu row: the Cortex-M4 kernel (kernels/cortex-m4) in its firmware
// (boards/mps2-an386/dut_main.c) on QEMU's mps2-an386, reached over the device-under-test
// protocol through the dut family's exec link (hosts/dut): QEMU is the child process, and the
// firmware's link (semihosting, or the emulated UART0) is on the child's stdin/stdout.
#pragma once
#include <string>
#include <vector>

namespace pxflow::m4qemu {

// -icount shift=N: one instruction per 2^N ns of virtual time. The firmware converts SysTick
// ticks (25 MHz) to instructions for exactly this N (5 per tick), and says so in HELLO's clock,
// "qemu-icount-instructions".
inline constexpr int kIcountShift = 3;

// --m4-firmware FILE, or empty: the row runs the firmware built or installed with this pxflow.
std::string& firmware_option();

// The firmware's two links to the host (boards/mps2-an386/link.c), chosen by the QEMU command
// line: semihosting, the row's (one read(2) or write(2) of QEMU's stdin/stdout per call), or the
// board's UART (QEMU's CMSDK UART model: one byte per main-loop turn, about 20 KB/s). The row's
// QEMU command line (qemu_command) is the only place that spells either.
enum class M4Link { kSemihosting, kUart };
struct M4LinkName {
  M4Link link;
  const char* name;
};
inline constexpr M4LinkName kM4Links[] = {{M4Link::kSemihosting, "semihosting"},
                                          {M4Link::kUart, "uart"}};
const char* link_name(M4Link link);

// The link the row uses: --m4-link NAME, else semihosting.
M4Link& link_choice();

// The QEMU command line of the row (argv[0] is looked up in PATH by the exec link).
std::vector<std::string> qemu_command(const std::string& firmware, M4Link link);

// Empty when the row can start QEMU here, with `firmware` set to the ELF it runs (--m4-firmware
// FILE, else the build tree's or the installed one, found relative to the running pxflow:
// hosts/core/own_files.hpp), else why not (no qemu-system-arm in PATH, no firmware).
std::string prerequisites_missing(std::string& firmware);

}  // namespace pxflow::m4qemu
