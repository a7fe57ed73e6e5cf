#include "output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "errors.hpp"

namespace pxflow {
namespace {

std::string errno_text() { return std::strerror(errno); }

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

// Writes all of `bytes` to `fd`; false (errno set) on any failure.
bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace

void check_output_path(const std::string& option, const std::string& path,
                       std::span<const std::string> inputs) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError(option + " needs a file name (got an empty one)");
  if (path == kStdoutPath) return;
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw InputError(option + " " + path + ": is a directory");
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec))
    throw InputError(option + " " + path + ": no such directory " + dir.string());
  check_not_an_input(option, path, inputs);
}

void check_not_an_input(const std::string& option, const std::string& path,
                        std::span<const std::string> inputs) {
  for (const std::string& in : inputs)
    if (same_file(path, in))
      throw InputError(option + " " + path + ": is an input (" + in +
                       "); pxflow never overwrites an input, choose another name");
}

void write_output_file(const std::string& path, std::string_view bytes) {
  if (path == kStdoutPath) {
    std::cout << bytes;
    check_stdout();
    return;
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    // A device or FIFO: nothing to keep intact, write straight through.
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw OutputError("cannot open " + path + ": " + errno_text());
    const bool ok = write_all(fd, bytes);
    const std::string why = errno_text();
    if (::close(fd) != 0 || !ok) throw OutputError("cannot write " + path + ": " + why);
    return;
  }
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError("cannot create " + tmp + ": " + errno_text());
  bool ok = write_all(fd, bytes) && ::fsync(fd) == 0;
  std::string why = errno_text();
  if (::close(fd) != 0 && ok) ok = false, why = errno_text();
  if (ok && ::rename(tmp.c_str(), path.c_str()) != 0) ok = false, why = errno_text();
  if (!ok) {
    ::unlink(tmp.c_str());
    throw OutputError("cannot write " + path + ": " + why + " (the previous file is unchanged)");
  }
}

void check_stdout() {
  std::cout.flush();
  const bool lost = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (lost) {
    std::cout.clear();
    throw OutputError("cannot write to standard output: " + errno_text());
  }
}

}  // namespace pxflow
