// The m4qemu family: one row, m4-qemu, and the --m4-firmware option (the fault tests of
// tests/m4qemu run other firmware through the same row).
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
#include "own_files.hpp"

namespace pxflow {
namespace m4qemu {

std::string& firmware_option() {
  static std::string path;
  return path;
}

const char* link_name(M4Link link) {
  for (const M4LinkName& l : kM4Links)
    if (l.link == link) return l.name;
  return "?";
}

M4Link& link_choice() {
  static M4Link link = M4Link::kSemihosting;
  return link;
}

std::vector<std::string> qemu_command(const std::string& firmware, M4Link link) {
  // -nographic with -monitor none: no monitor multiplexed onto stdin/stdout, so no byte of the
  // binary protocol is taken for a Ctrl-A escape. Semihosting is always on (the firmware exits
  // through it on a fault).
  std::vector<std::string> argv = {
      "qemu-system-arm", "-M",   "mps2-an386", "-nographic",
      "-monitor",        "none", "-icount",    "shift=" + std::to_string(kIcountShift)};
  if (link == M4Link::kSemihosting) {
    // UART0 on nothing, so that stdin is read by the firmware's SYS_READ alone; the word
    // link=semihosting on the semihosting command line (SYS_GET_CMDLINE) makes the firmware open
    // ":tt", which QEMU maps to its own stdin and stdout (boards/mps2-an386/semihost.c).
    argv.insert(argv.end(), {"-serial", "null", "-semihosting-config",
                             "enable=on,target=native,arg=pxflow_m4_dut,arg=link=semihosting"});
  } else {
    argv.insert(argv.end(), {"-serial", "stdio", "-semihosting-config", "enable=on,target=native"});
  }
  argv.insert(argv.end(), {"-kernel", firmware});
  return argv;
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

std::string prerequisites_missing(std::string& firmware) {
  if (!executable_in_path("qemu-system-arm"))
    return "qemu-system-arm not found in PATH (install qemu-system-arm: bash ci/install-deps.sh)";
  firmware = firmware_option();
  if (!firmware.empty()) {
    struct stat st {};
    if (stat(firmware.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
      return "firmware not found: " + firmware + " (--m4-firmware) is missing";
    return "";
  }
  const OwnFile own = find_own_file(PXFLOW_M4_FIRMWARE_FILE, {PXFLOW_M4_FIRMWARE_BUILD_RELDIR,
                                                              PXFLOW_M4_FIRMWARE_INSTALL_RELDIR});
  firmware = own.found.string();
  if (!firmware.empty()) return "";
  return std::string("firmware not built or not installed: no ") + PXFLOW_M4_FIRMWARE_FILE +
         (own.tried.empty() ? "" : " at " + describe_tried(own.tried)) +
         " (build the pxflow target with gcc-arm-none-eabi installed and install it again, or "
         "give --m4-firmware FILE; docs/cortex-m4.md)";
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
      std::string fw;
      why_not = prerequisites_missing(fw);
      if (why_not.empty()) {
        dut::DutSpec spec;
        spec.name = "m4-qemu";
        spec.kind = dut::DutSpec::Kind::kExec;
        spec.argv = qemu_command(fw, link_choice());
        spec.text = "exec:qemu-system-arm -M mps2-an386 ... (" +
                    std::string(link_name(link_choice())) + " link) -kernel " + fw;
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
  row.counts_like = RefVariant::kOriginal;  // m4_counts(): the firmware interpolates per pixel
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
  firmware.value_name = "ELF";
  firmware.reads_file = true;
  firmware.help =
      "The firmware ELF the m4-qemu row runs under QEMU (default: the one built or installed with "
      "this pxflow)";
  firmware.apply = [](const std::string& file) {
    if (file.empty())
      throw InputError("--m4-firmware: empty path: give the firmware ELF (see pxflow --help)");
    m4qemu::firmware_option() = file;
  };
  FamilyOption link;
  link.flag = "--m4-link";
  link.value_name = "semihosting|uart";
  link.help =
      "The link to the m4-qemu firmware: semihosting (default; QEMU's stdin/stdout, fast) or uart "
      "(the board's UART as QEMU models it, about 20 KB/s); docs/cortex-m4.md";
  link.apply = [](const std::string& name) {
    for (const m4qemu::M4LinkName& l : m4qemu::kM4Links)
      if (name == l.name) {
        m4qemu::link_choice() = l.link;
        return;
      }
    throw InputError("--m4-link: unknown link '" + name + "': allowed semihosting, uart");
  };
  f.options = {firmware, link};
  f.environment.push_back({"PATH", "Where the m4-qemu row looks for qemu-system-arm"});
  return f;
}

}  // namespace pxflow
