// `--dut NAME=SPEC` (docs/dut-protocol.md section 5): the row's name and how to reach the device.
#pragma once
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "dut_link.hpp"

namespace pxflow::dut {

struct DutSpec {
  std::string name;  // the registry row
  std::string text;  // SPEC as given, for messages
  enum class Kind { kExec, kTcp, kSerial } kind = Kind::kExec;
  std::vector<std::string> argv;  // exec
  std::string host, port;         // tcp
  std::string path;               // serial
  int baud = 115200;
};

// Parses NAME=SPEC; throws InputError (exit 2) naming what is wrong and what is allowed.
DutSpec parse_dut_spec(const std::string& arg);

// Opens the link the spec names; throws LinkError when it cannot.
std::unique_ptr<Link> open_link(const DutSpec& spec, std::chrono::duration<double> timeout);

}  // namespace pxflow::dut
