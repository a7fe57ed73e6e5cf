// The byte links to a device (docs/dut-protocol.md section 5): a child process's stdin/stdout,
// a TCP connection, a serial port in raw mode. Every wait has a deadline and notices Ctrl-C
// (hosts/core/interrupt.hpp); nothing blocks forever.
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace pxflow::dut {

using Clock = std::chrono::steady_clock;

// A link that cannot be opened or broke: the message says why (BackendError-like, caught by the
// session and turned into its one line).
struct LinkError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Link {
 public:
  virtual ~Link() = default;
  // Writes every byte before `deadline`; throws LinkError when the link is closed or full.
  virtual void write(std::span<const std::uint8_t> bytes, Clock::time_point deadline) = 0;
  // Waits for bytes until `deadline`: returns how many were read, 0 at the deadline; throws
  // LinkError when the link is closed (the message says how: "exited with status 3").
  virtual std::size_t read(std::uint8_t* buf, std::size_t max, Clock::time_point deadline) = 0;
  // What to look at when bytes arrive but never a valid frame: this kind of link's usual
  // misconnection ("wrong port or baud rate?" on a serial port, not over exec:).
  virtual std::string garbage_hint() const = 0;
};

// exec: COMMAND split at blanks, no shell, started as a GuardedChild (hosts/core/guarded_child.hpp:
// its whole process group ends with pxflow, however pxflow ends); stopped and reaped by the
// destructor (stdin closed, a second to exit by itself, then SIGKILL to the group).
std::unique_ptr<Link> open_exec_link(const std::vector<std::string>& argv);
std::unique_ptr<Link> open_tcp_link(const std::string& host, const std::string& port,
                                    Clock::time_point deadline);
std::unique_ptr<Link> open_serial_link(const std::string& path, int baud);

// The baud rates serial: accepts (termios Bxxx constants), for the spec parser's message.
bool serial_baud_supported(int baud);
std::string serial_bauds_text();

}  // namespace pxflow::dut
