// The m4qemu family: one row, m4-qemu, and the --m4-firmware option (the fault tests of tests/m4
// run other firmware through the same row).
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <memory>

#include "backend.hpp"
#include "dut_backend.hpp"
#include "dut_spec.hpp"
#include "errors.hpp"
#include "m4qemu_backend.hpp"
#include "m4qemu_row.hpp"

namespace pxflow {
namespace m4qemu {

std::string& firmware_path() {
  static std::string path = PXFLOW_M4_FIRMWARE;
  return path;
}

std::vector<std::string> qemu_command(const std::string& firmware) {
  // -nographic with -monitor none and -serial stdio: UART0 alone on stdin/stdout (no monitor
  // multiplexed in, so no byte of the binary protocol is taken for a Ctrl-A escape);
  // semihosting for the firmware's exit on a fault (it never prints).
  return {"qemu-system-arm",
          "-M",
          "mps2-an386",
          "-nographic",
          "-monitor",
          "none",
          "-serial",
          "stdio",
          "-icount",
          "shift=" + std::to_string(kIcountShift),
          "-semihosting-config",
          "enable=on,target=native",
          "-kernel",
          firmware};
}

namespace {

bool executable_in_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = dirs.find(':', start);
    const std::string dir = dirs.substr(start, end == std::string::npos ? end : end - start);
    const std::string file = (dir.empty() ? "." : dir) + "/" + name;
    if (access(file.c_str(), X_OK) == 0) return true;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return false;
}

}  // namespace

std::string prerequisites_missing(const std::string& firmware) {
  if (!executable_in_path("qemu-system-arm"))
    return "qemu-system-arm not found in PATH (install qemu-system-arm: bash ci/install-deps.sh)";
  struct stat st {};
  if (stat(firmware.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    return "firmware not built: " + firmware +
           " is missing (build the pxflow target with gcc-arm-none-eabi installed, or give "
           "--m4-firmware FILE)";
  return "";
}

namespace {

// The device is opened on first use (the probe), with the firmware path known by then: the
// option is applied after the registry made its rows.
struct LazyDevice {
  std::shared_ptr<dut::Device> device;
  std::string why_not;
  bool opened = false;

  std::string probe() {
    if (!opened) {
      opened = true;
      const std::string fw = firmware_path();
      why_not = prerequisites_missing(fw);
      if (why_not.empty()) {
        dut::DutSpec spec;
        spec.name = "m4-qemu";
        spec.kind = dut::DutSpec::Kind::kExec;
        spec.argv = qemu_command(fw);
        spec.text = "exec:qemu-system-arm -M mps2-an386 ... -kernel " + fw;
        device = std::make_shared<dut::Device>(spec);
      }
    }
    if (!why_not.empty() || !device) return why_not;
    return device->probe();
  }
};

BackendRow m4_qemu_row() {
  auto lazy = std::make_shared<LazyDevice>();
  BackendRow row;
  row.name = "m4-qemu";
  row.needs = "qemu-system-arm and the Cortex-M4 firmware (gcc-arm-none-eabi); docs/cortex-m4.md";
  row.probe = [lazy] { return lazy->probe(); };
  row.create = [lazy](const BackendOptions&) -> std::unique_ptr<Backend> {
    if (const std::string why = lazy->probe(); !why.empty()) throw BackendError(why);
    return std::make_unique<M4QemuBackend>(lazy->device);
  };
  return row;
}

}  // namespace
}  // namespace m4qemu

BackendFamily m4qemu_family() {
  BackendFamily f;
  f.name = "m4qemu";
  f.rows.push_back(m4qemu::m4_qemu_row());
  FamilyOption firmware;
  firmware.flag = "--m4-firmware";
  firmware.help =
      "The firmware ELF the m4-qemu row runs under QEMU (default: the one this build made)";
  firmware.apply = [](const std::string& file) {
    if (file.empty())
      throw InputError("--m4-firmware: empty path: give the firmware ELF (see pxflow --help)");
    m4qemu::firmware_path() = file;
  };
  f.options = {firmware};
  return f;
}

}  // namespace pxflow
