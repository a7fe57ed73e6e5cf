// The dut family: no rows of its own; `--dut NAME=SPEC` (repeatable) appends one row per device
// before the command runs. Its waits follow --device-timeout (alias --dut-timeout), declared once
// for every family by the CLI (hosts/core/device_wait.hpp).
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
  dut.value_name = "NAME=SPEC";
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
  f.options = {dut};
  f.environment.push_back({"PATH", "Where --dut NAME=exec:COMMAND looks for COMMAND"});
  return f;
}

}  // namespace pxflow
