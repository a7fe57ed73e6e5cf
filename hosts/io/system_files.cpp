#include "system_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

namespace pxflow {
namespace {

std::string read_all(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  std::string text;
  char chunk[1 << 14];
  for (;;) {
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    text.append(chunk, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

}  // namespace

std::string read_system_file(const std::string& path) { return read_all(path); }

int open_null_device(bool for_writing) {
  return ::open("/dev/null", (for_writing ? O_WRONLY : O_RDONLY) | O_CLOEXEC);
}

std::string read_own_output(const std::string& path) { return read_all(path); }

}  // namespace pxflow
