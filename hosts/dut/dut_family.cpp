// The dut family: no rows of its own; `--dut NAME=SPEC` (repeatable) appends one row per device
// before the command runs, and `--dut-timeout` bounds every wait for a device.
#include <set>

#include "backend.hpp"
#include "dut_backend.hpp"
#include "errors.hpp"
#include "registry.hpp"

namespace pxflow {

BackendFamily dut_family() {
  BackendFamily f;
  f.name = "dut";
  FamilyOption dut;
  dut.flag = "--dut";
  dut.help =
      "A device under test as a backend row NAME, repeatable: NAME=exec:COMMAND [ARG...], "
      "NAME=tcp:HOST:PORT or NAME=serial:/dev/ttyXXX[,BAUD] (docs/dut-protocol.md)";
  dut.repeatable = true;
  dut.apply = [](const std::string& arg) {
    const dut::DutSpec spec = dut::parse_dut_spec(arg);
    for (const BackendRow& row : backend_rows())
      if (row.name == spec.name)
        throw InputError("--dut " + arg + ": the name '" + spec.name + "' is taken (by the " +
                         row.family + " row): choose another NAME (see pxflow backends)");
    add_backend_row(dut::dut_row(spec));
  };
  FamilyOption timeout;
  timeout.flag = "--dut-timeout";
  timeout.help =
      "Seconds to wait for any one answer of a --dut device (default 10); a message is resent "
      "at most 3 times, so a silent device fails within 4 x this";
  timeout.apply = [](const std::string& text) {
    char* end = nullptr;
    const double s = std::strtod(text.c_str(), &end);
    if (text.empty() || *end || !(s >= 0.01 && s <= 3600))
      throw InputError("--dut-timeout: '" + text +
                       "': allowed seconds from 0.01 to 3600 (see pxflow --help)");
    dut::dut_timeout() = std::chrono::duration<double>(s);
  };
  f.options = {dut, timeout};
  return f;
}

}  // namespace pxflow
