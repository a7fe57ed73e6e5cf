#include "dut_spec.hpp"

#include <sstream>

#include "errors.hpp"
#include "params.hpp"

namespace pxflow::dut {
namespace {

const char* kAllowed =
    "exec:COMMAND [ARG...], tcp:HOST:PORT or serial:/dev/ttyXXX[,BAUD] (see docs/dut-protocol.md)";

[[noreturn]] void bad(const std::string& arg, const std::string& what) {
  throw InputError("--dut " + arg + ": " + what + ": allowed NAME=" + kAllowed);
}

bool good_name(const std::string& n) {
  if (n.empty() || !std::isalnum(static_cast<unsigned char>(n[0]))) return false;
  for (char c : n)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
      return false;
  return true;
}

}  // namespace

DutSpec parse_dut_spec(const std::string& arg) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos) bad(arg, "no NAME= before the device");
  DutSpec s;
  s.name = arg.substr(0, eq);
  s.text = arg.substr(eq + 1);
  if (!good_name(s.name))
    bad(arg, "the name '" + s.name + "' is not letters, digits, '-', '_' or '.'");
  const auto colon = s.text.find(':');
  const std::string kind = s.text.substr(0, colon),
                    rest = colon == std::string::npos ? "" : s.text.substr(colon + 1);
  if (kind == "exec") {
    s.kind = DutSpec::Kind::kExec;
    std::istringstream words(rest);
    for (std::string w; words >> w;) s.argv.push_back(w);
    if (s.argv.empty()) bad(arg, "exec: needs a command");
  } else if (kind == "tcp") {
    s.kind = DutSpec::Kind::kTcp;
    const auto last = rest.rfind(':');
    if (last == std::string::npos || last == 0) bad(arg, "tcp: needs HOST:PORT");
    s.host = rest.substr(0, last);
    s.port = rest.substr(last + 1);
    if (s.host.size() > 2 && s.host.front() == '[' && s.host.back() == ']')
      s.host = s.host.substr(1, s.host.size() - 2);  // [::1]:5000
    try {
      parse_int(s.port, "port", 1, 65535);
    } catch (const InputError&) {
      bad(arg, "tcp: the port '" + s.port + "' is not a number in 1..65535");
    }
  } else if (kind == "serial") {
    s.kind = DutSpec::Kind::kSerial;
    const auto comma = rest.find(',');
    s.path = rest.substr(0, comma);
    if (s.path.empty()) bad(arg, "serial: needs a device path");
    if (comma != std::string::npos) {
      const std::string b = rest.substr(comma + 1);
      try {
        s.baud = parse_int(b, "baud", 1, 100000000);
      } catch (const InputError&) {
        s.baud = 0;
      }
      if (!serial_baud_supported(s.baud))
        throw InputError("--dut " + arg + ": baud rate '" + b + "': allowed " +
                         serial_bauds_text());
    }
  } else {
    bad(arg, "unknown transport '" + kind + "'");
  }
  return s;
}

std::unique_ptr<Link> open_link(const DutSpec& spec, std::chrono::duration<double> timeout) {
  switch (spec.kind) {
    case DutSpec::Kind::kExec:
      return open_exec_link(spec.argv);
    case DutSpec::Kind::kTcp:
      return open_tcp_link(spec.host, spec.port,
                           Clock::now() + std::chrono::duration_cast<Clock::duration>(timeout));
    case DutSpec::Kind::kSerial:
      return open_serial_link(spec.path, spec.baud);
  }
  throw LinkError("unknown transport");
}

}  // namespace pxflow::dut
