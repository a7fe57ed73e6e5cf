#include "output_plan.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "errors.hpp"
#include "file_inputs.hpp"
#include "owned_folder.hpp"

namespace pxflow {
namespace {

namespace fs = std::filesystem;

std::string errno_text() { return std::strerror(errno); }

std::size_t g_files_changed = 0;

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

// The path with every existing part's links resolved: two spellings of one file compare equal
// even before the file exists.
fs::path resolved(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::path(path).lexically_normal() : p;
}

bool inside(const fs::path& file, const fs::path& folder) {
  const auto [f, d] = std::mismatch(file.begin(), file.end(), folder.begin(), folder.end());
  return d == folder.end() && f != file.end();
}

// Does `name` have the shape of `pattern` ("pair-NNNNNN.png": a digit for each N)?
bool matches(const std::string& name, const std::string& pattern) {
  if (name.size() != pattern.size()) return false;
  for (std::size_t i = 0; i < name.size(); ++i)
    if (pattern[i] == 'N' ? !std::isdigit(static_cast<unsigned char>(name[i]))
                          : name[i] != pattern[i])
      return false;
  return true;
}

bool regular_or_absent(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode);
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

// The temporary file beside `path` that its bytes go to first (one per process and path), and
// creating it.
std::string temporary_for(const std::string& path) {
  return path + ".tmp." + std::to_string(::getpid());
}
int create_temporary(const std::string& tmp) {
  return ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
}

// Writes `bytes` to `path` through a temporary beside it, renamed into place when complete.
void write_whole(const std::string& label, const std::string& path, std::string_view bytes) {
  const std::string tmp = temporary_for(path);
  const int fd = create_temporary(tmp);
  if (fd < 0) throw OutputError(label + ": cannot create " + tmp + ": " + errno_text());
  bool ok = write_all(fd, bytes) && ::fsync(fd) == 0;
  std::string why = errno_text();
  if (::close(fd) != 0 && ok) ok = false, why = errno_text();
  if (ok && ::rename(tmp.c_str(), path.c_str()) != 0) ok = false, why = errno_text();
  if (!ok) {
    ::unlink(tmp.c_str());
    throw OutputError(label + ": cannot write: " + why + " (the previous file is unchanged)");
  }
  ++g_files_changed;
}

}  // namespace

PlannedPath::~PlannedPath() { discard(); }

void PlannedPath::open() {
  prepared_ = true;
  if (to_stdout()) {
    direct_ = true;
    return;
  }
  if (!regular_or_absent(path_)) {  // a device or FIFO: written straight through, opened late
    direct_ = true;
    if (::access(path_.c_str(), W_OK) != 0)
      throw InputError(label() + ": cannot be written: " + errno_text());
    return;
  }
  tmp_ = temporary_for(path_);
  fd_ = create_temporary(tmp_);
  if (fd_ < 0) {
    const std::string why = errno_text();
    tmp_.clear();
    throw InputError(label() + ": cannot be created: " + why + " (checked before any work)");
  }
}

void PlannedPath::append(std::string_view bytes) {
  if (!prepared_) throw std::logic_error(label() + ": written before its plan was prepared");
  if (done_) throw std::logic_error(label() + ": written after it was finished");
  if (to_stdout()) {
    std::fwrite(bytes.data(), 1, bytes.size(), stdout);
    std::fflush(stdout);
    return;
  }
  if (fd_ < 0 && direct_) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) throw OutputError(label() + ": cannot open: " + errno_text());
  }
  if (!write_all(fd_, bytes)) throw OutputError(label() + ": cannot write: " + errno_text());
}

void PlannedPath::commit() {
  if (done_) return;
  done_ = true;
  if (to_stdout()) {
    check_stdout();
    return;
  }
  bool ok = direct_ || ::fsync(fd_) == 0;
  std::string why = errno_text();
  if (fd_ >= 0 && ::close(fd_) != 0 && ok) ok = false, why = errno_text();
  fd_ = -1;
  if (ok && !direct_ && ::rename(tmp_.c_str(), path_.c_str()) != 0) ok = false, why = errno_text();
  if (!ok) {
    discard();
    throw OutputError(label() + ": cannot write: " + why +
                      (direct_ ? "" : " (the previous file is unchanged)"));
  }
  tmp_.clear();
  ++g_files_changed;
}

void PlannedPath::discard() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!tmp_.empty()) ::unlink(tmp_.c_str());
  tmp_.clear();
}

void OutputFile::write(std::string_view bytes) {
  append(bytes);
  commit();
}

OutputStream::~OutputStream() {
  if (!prepared_ || done_) return;
  if (records_ == 0) {
    discard();
    return;
  }
  try {
    commit();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pxflow: error: %s\n", e.what());
  }
}

void OutputStream::header(std::string_view bytes) { append(bytes); }

void OutputStream::add(std::string_view bytes) {
  append(bytes);
  ++records_;
}

void OutputStream::finish() { commit(); }

void OutputFolder::write(const std::string& name, std::string_view bytes) {
  const std::string path = (fs::path(dir_) / name).string();
  if (plan_ == nullptr) throw std::logic_error(option_ + " " + path + ": folder not prepared");
  plan_->check_not_an_input(option_, path);
  write_whole(option_ + " " + path, path, bytes);
  written_.push_back(name);
}

bool OutputFolder::make_subfolder(const std::string& name) {
  const fs::path path = fs::path(dir_) / name;
  if (plan_ == nullptr) throw std::logic_error(option_ + " " + path.string() + ": not prepared");
  plan_->check_not_an_input(option_, path.string());
  std::error_code ec;
  if (fs::create_directory(path, ec)) return true;
  if (ec) throw OutputError(option_ + ": cannot create " + path.string() + ": " + ec.message());
  return false;
}

void OutputFolder::remove_earlier() {
  if (plan_ == nullptr) return;
  std::vector<std::string> earlier;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir_, ec))
    if (matches(entry.path().filename().string(), pattern_))
      earlier.push_back(entry.path().filename().string());
  remove_unwritten(dir_, earlier, earlier, written_);
}

void OutputPlan::read(const std::string& path) { note_input(path); }

void OutputPlan::read_all(const std::vector<std::string>& paths) {
  for (const std::string& p : paths) read(p);
}

void OutputPlan::read_folder(const std::string& option, const std::string& dir) {
  note_input_folder(option, dir);
}

OutputFile& OutputPlan::file(const std::string& option, const std::string& path) {
  if (prepared_) throw std::logic_error(option + ": output added after the plan was prepared");
  return files_.emplace_back(option, path);
}

OutputStream& OutputPlan::stream(const std::string& option, const std::string& path) {
  if (prepared_) throw std::logic_error(option + ": output added after the plan was prepared");
  return streams_.emplace_back(option, path);
}

OutputFolder& OutputPlan::folder(const std::string& option, const std::string& dir,
                                 const std::string& pattern) {
  if (prepared_) throw std::logic_error(option + ": output added after the plan was prepared");
  return folders_.emplace_back(option, dir, pattern);
}

void OutputPlan::make_folder(const std::string& option, const std::string& dir,
                             const std::string& manifest) {
  if (prepared_) throw std::logic_error(option + ": output added after the plan was prepared");
  made_folders_.push_back({option, dir, manifest});
}

void OutputPlan::check_not_an_input(const std::string& option, const std::string& path) const {
  for (const std::string& in : inputs_noted())
    if (same_file(path, in))
      throw InputError(option + " " + path + ": is an input (" + in +
                       "); pxflow never overwrites an input, choose another name");
}

void OutputPlan::check_output(const std::string& option, const std::string& path,
                              bool is_folder) const {
  if (path.empty()) throw InputError(option + " needs a file name (got an empty one)");
  if (path == kStdoutPath) return;
  std::error_code ec;
  const fs::path p(path);
  if (is_folder) {
    if (!fs::is_directory(p, ec))
      throw InputError(option + " " + path + ": names no existing folder (create it first)");
  } else {
    if (fs::is_directory(p, ec)) throw InputError(option + " " + path + ": is a directory");
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec))
      throw InputError(option + " " + path + ": no such directory " + dir.string());
    check_not_an_input(option, path);
  }
  check_not_in_input_folder(option, path);
}

void OutputPlan::check_not_in_input_folder(const std::string& option,
                                           const std::string& path) const {
  const fs::path where = resolved(path);
  for (const auto& [in_option, folder] : input_folders_noted()) {
    const fs::path f = resolved(folder);
    if (where == f || inside(where, f))
      throw InputError(option + " " + path + ": is inside " + folder + ", the folder " + in_option +
                       " reads; pxflow never writes where it reads, choose another");
  }
}

void OutputPlan::prepare() {
  if (prepared_) throw std::logic_error("output plan prepared twice");
  std::vector<fs::path> created;  // removed again (when still empty) if the plan is refused
  try {
    for (const auto& [option, dir, manifest] : made_folders_) {
      if (dir.empty()) throw InputError(option + " needs a folder name (got an empty one)");
      check_owned_folder(option, dir, manifest);
      std::error_code ec;
      if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw InputError(option + " " + dir + ": is a file, not a folder");
      check_not_in_input_folder(option, dir);
      fs::path first_missing;
      for (fs::path p = fs::absolute(dir, ec); !p.empty() && !fs::exists(p, ec);
           p = p.parent_path())
        first_missing = p;
      if (!fs::create_directories(dir, ec) && ec)
        throw InputError(option + " " + dir + ": cannot create the folder: " + ec.message());
      // Deepest first, so that removing them one by one removes each made folder.
      for (fs::path p = fs::absolute(dir, ec); !first_missing.empty(); p = p.parent_path()) {
        created.push_back(p);
        if (p == first_missing) break;
      }
    }
    check_and_open();
  } catch (...) {
    std::error_code ec;
    for (const fs::path& p : created) fs::remove(p, ec);  // only an empty folder goes
    throw;
  }
}

void OutputPlan::check_and_open() {
  struct Claim {
    std::string option, path;
  };
  std::vector<Claim> claims;
  for (const OutputFile& f : files_) claims.push_back({f.option(), f.path()});
  for (const OutputStream& s : streams_) claims.push_back({s.option(), s.path()});
  for (const Claim& c : claims) check_output(c.option, c.path, false);
  for (const OutputFolder& f : folders_) {
    check_output(f.option_, f.dir_, true);
    for (const std::string& in : inputs_noted())
      if (resolved(in).parent_path() == resolved(f.dir_) &&
          matches(fs::path(in).filename().string(), f.pattern_))
        throw InputError(f.option_ + " " + f.dir_ + ": holds the input " + in + ", which a " +
                         f.pattern_ + " picture would replace; choose another folder");
  }
  // Two outputs that are one file: one of them would be lost.
  for (std::size_t i = 0; i < claims.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const Claim &a = claims[j], &b = claims[i];
      const bool both_stdout = a.path == kStdoutPath && b.path == kStdoutPath;
      const bool one_file = a.path != kStdoutPath && b.path != kStdoutPath &&
                            (resolved(a.path) == resolved(b.path) || same_file(a.path, b.path));
      if (both_stdout)
        throw InputError(a.option + " and " + b.option +
                         ": only one of them can write to standard output (-)");
      if (one_file)
        throw InputError(a.option + " " + a.path + " and " + b.option + " " + b.path +
                         ": the same file; give each output its own name");
    }
  prepared_ = true;
  // Create every temporary now: an output that cannot be written fails before any work.
  for (OutputFile& f : files_) f.open();
  for (OutputStream& s : streams_) s.open();
  for (OutputFolder& f : folders_) {
    const std::string probe =
        (fs::path(f.dir_) / (".pxflow-probe." + std::to_string(::getpid()))).string();
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0)
      throw InputError(f.option_ + " " + f.dir_ + ": cannot create files in it: " + errno_text() +
                       " (checked before any work)");
    ::close(fd);
    ::unlink(probe.c_str());
    f.plan_ = this;
  }
}

std::size_t files_changed() { return g_files_changed; }

void check_stdout() {
  std::cout.flush();
  const bool lost = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (lost) {
    std::cout.clear();
    throw OutputError("cannot write to standard output: " + errno_text());
  }
}

}  // namespace pxflow
