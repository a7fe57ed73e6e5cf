#include "input_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "errors.hpp"
#include "file_inputs.hpp"
#include "interrupt.hpp"

namespace pxflow {
namespace fs = std::filesystem;
namespace {

// A JSON or list file far beyond this is a mistake (an endless stream), not an input.
constexpr std::uint64_t kMaxTextBytes = std::uint64_t{1} << 30;

// Closes the descriptor on every path out, exceptions included.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

std::string count_text(std::uint64_t n) {
  return std::to_string(n) + (n == 1 ? " byte" : " bytes");
}

void require_existing(const std::string& label, const std::string& path) {
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (!ec && fs::exists(st)) return;
  if (ec == std::errc::too_many_symbolic_link_levels)
    throw InputError(label + ": a loop of symbolic links");
  if (ec == std::errc::permission_denied)
    throw InputError(label + ": cannot be reached (a folder on the way may not be searched)");
  if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
    throw InputError(label + ": cannot be opened (" + ec.message() + ")");
  throw InputError(label + ": no such file");
}

}  // namespace

bool is_stream(const std::string& path) {
  std::error_code ec;
  return fs::is_fifo(fs::status(path, ec));
}

namespace {

void require_readable(const std::string& label, const std::string& path) {
  require_existing(label, path);
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (fs::is_regular_file(st) || fs::is_fifo(st)) return;
  if (fs::is_directory(st)) throw InputError(label + ": is a directory, not a file");
  if (fs::is_character_file(st))
    throw InputError(label + ": is a character device (it may never end), not a file or a pipe");
  throw InputError(label + ": not a regular file or a pipe");
}

}  // namespace

int open_or_stop(const std::string& path, const std::string& label) {
  for (;;) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0 || errno != EINTR) return fd;
    stop_if_interrupted_while("opening " + label);
  }
}

long read_or_stop(int fd, void* buf, std::size_t n, const std::string& label) {
  // Only a wait looks at the flag: a regular file's read never waits, and a run stopped then
  // says what it had done at its own stop point. A signal that came just before poll() would
  // not cut it short: the wait goes in slices of a second.
  const auto waited = [&] { stop_if_interrupted_while("reading " + label); };
  for (;;) {
    struct pollfd p {
      fd, POLLIN, 0
    };
    const int ready = ::poll(&p, 1, 1000);
    if (ready == 0 || (ready < 0 && errno == EINTR)) {
      waited();
      continue;
    }
    const ssize_t got = ::read(fd, buf, n);
    if (got < 0 && errno == EINTR) {
      waited();
      continue;
    }
    return static_cast<long>(got);
  }
}

namespace {

std::vector<std::uint8_t> read_bytes(const std::string& label, const std::string& path,
                                     std::uint64_t max_bytes, const std::string& why) {
  require_readable(label, path);
  const Fd in{open_or_stop(path, label)};
  if (in.fd < 0)
    throw InputError(label + ": cannot open for reading (" + std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(in.fd, &st) == 0 && S_ISREG(st.st_mode) &&
      static_cast<std::uint64_t>(st.st_size) > max_bytes)
    throw InputError(label + ": holds " + count_text(st.st_size) + ", " + why);
  std::vector<std::uint8_t> bytes;
  std::uint8_t chunk[1 << 16];
  for (;;) {
    const long n = read_or_stop(in.fd, chunk, sizeof chunk, label);
    if (n < 0) throw InputError(label + ": read failed (" + std::strerror(errno) + ")");
    if (n == 0) break;
    if (bytes.size() + static_cast<std::uint64_t>(n) > max_bytes)
      throw InputError(label + ": holds more than " + count_text(max_bytes) + ", " + why);
    bytes.insert(bytes.end(), chunk, chunk + n);
  }
  if (bytes.empty()) throw InputError(label + ": file is empty");
  return bytes;
}

}  // namespace

void require_readable_input(const std::string& label, const std::string& path) {
  note_input(path);  // before any refusal: a path named as an input is never written
  require_readable(label, path);
}

std::vector<std::uint8_t> read_input(const std::string& label, const std::string& path,
                                     std::uint64_t max_bytes, const std::string& why) {
  note_input(path);
  return read_bytes(label, path, max_bytes, why);
}

std::string read_input_text(const std::string& label, const std::string& path) {
  const std::vector<std::uint8_t> bytes =
      read_input(label, path, kMaxTextBytes, "too large for a JSON or list file");
  return std::string(bytes.begin(), bytes.end());
}

std::string read_updated_text(const std::string& label, const std::string& path) {
  const std::vector<std::uint8_t> bytes =
      read_bytes(label, path, kMaxTextBytes, "too large for a JSON or list file");
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace pxflow
