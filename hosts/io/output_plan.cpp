#include "output_plan.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "errors.hpp"
#include "file_inputs.hpp"
#include "in_flight.hpp"
#include "interrupt.hpp"
#include "owned_folder.hpp"

namespace pxflow {
namespace {

namespace fs = std::filesystem;

std::string errno_text() { return std::strerror(errno); }

std::size_t g_files_changed = 0;

// The file an OutputFolder's probe creates (as a temporary) to see that files can be made.
const char* const kProbeName = "pxflow-probe";

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

bool write_all(int fd, std::string_view bytes) {
  return in_flight::write_all(fd, bytes.data(), bytes.size());
}

// The path a write to `path` reaches: its chain of symbolic links followed (a dangling link:
// where it points, created there), every relative target taken from its link's folder.
std::string follow_links(const std::string& path) {
  fs::path p(path);
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) break;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) break;
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  return p.lexically_normal().string();
}

std::string folder_of(const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  return dir.empty() ? "." : dir.string();
}

// ".NAME.pxflow-PID.tmp": NAME and PID, or false.
bool parse_temporary(const std::string& name, std::string* original, long* pid) {
  static const std::string kMark = ".pxflow-", kEnd = ".tmp";
  if (name.size() < 1 + kMark.size() + 1 + kEnd.size() || name[0] != '.' || !name.ends_with(kEnd))
    return false;
  const std::size_t mark = name.rfind(kMark, name.size() - kEnd.size());
  if (mark == std::string::npos || mark < 2) return false;
  const std::string digits =
      name.substr(mark + kMark.size(), name.size() - kEnd.size() - mark - kMark.size());
  if (digits.empty() || digits.size() > 9 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(c) != 0; }))
    return false;
  if (original) *original = name.substr(1, mark - 1);
  if (pid) *pid = std::stol(digits);
  return true;
}

// Removes the temporaries in `dir` of processes that are gone (kill(pid, 0): ESRCH) whose NAME
// `wanted` accepts.
template <class Wanted>
void remove_dead_temporaries(const std::string& dir, Wanted wanted) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    std::string original;
    long pid = 0;
    if (!parse_temporary(name, &original, &pid) || pid == ::getpid() || !wanted(original)) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    std::error_code gone;
    if (fs::is_regular_file(fs::symlink_status(entry.path(), gone))) fs::remove(entry.path(), gone);
  }
}

// "" when the file system holding `dir` has room to start, else why not.
std::string space_problem(const std::string& dir) {
  struct statvfs v {};
  if (::statvfs(dir.c_str(), &v) != 0 || v.f_blocks == 0) return "";  // procfs and the like
  const std::uint64_t blocks = ::geteuid() == 0 ? v.f_bfree : v.f_bavail;
  const std::uint64_t free_bytes = blocks * v.f_frsize;
  if (free_bytes < kMinFreeBytes)
    return "the file system of " + dir + " has " + std::to_string(free_bytes) +
           " bytes free, less than the 1 MiB pxflow needs to start; free some space or choose "
           "another place";
  if (v.f_files > 0 && (::geteuid() == 0 ? v.f_ffree : v.f_favail) == 0)
    return "the file system of " + dir + " has no free inode; free some or choose another place";
  return "";
}

std::string mode_text(mode_t mode) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04o", static_cast<unsigned>(mode & 07777));
  return buf;
}

}  // namespace

int descriptor_of(const std::string& path) {
  if (path == kStdoutPath) return 1;
  static const std::pair<const char*, int> kNamed[] = {
      {"/dev/stdin", 0}, {"/dev/stdout", 1}, {"/dev/stderr", 2}};
  for (const auto& [name, fd] : kNamed)
    if (path == name) return fd;
  const std::string own = "/proc/" + std::to_string(::getpid()) + "/fd/";
  for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"), own}) {
    if (!path.starts_with(prefix)) continue;
    const std::string n = path.substr(prefix.size());
    if (n.empty() || n.size() > 6 ||
        !std::all_of(n.begin(), n.end(), [](char c) { return std::isdigit(c) != 0; }))
      return -1;
    return std::stoi(n);
  }
  return -1;
}

std::string temporary_name(const std::string& target) {
  const fs::path p(target);
  // Appended piece by piece: "." + std::string draws GCC 12's false -Wrestrict (bug 105329).
  std::string name(".");
  name += p.filename().string();
  name += ".pxflow-" + std::to_string(::getpid()) + ".tmp";
  return p.has_parent_path() ? (p.parent_path() / name).string() : name;
}

bool is_pxflow_temporary(const std::string& filename) {
  return parse_temporary(filename, nullptr, nullptr);
}

PlannedPath::~PlannedPath() { discard(); }

std::string PlannedPath::try_open(bool clean) {
  if (descriptor_ >= 0) {  // standard output, or another descriptor the caller opened
    direct_ = true;
    const int flags = ::fcntl(descriptor_, F_GETFL);
    if (flags < 0) return "names descriptor " + std::to_string(descriptor_) + ", which is not open";
    if ((flags & O_ACCMODE) == O_RDONLY)
      return "names descriptor " + std::to_string(descriptor_) + ", which is open for reading only";
    return "";
  }
  target_ = follow_links(path_);
  struct stat st {};
  const bool exists = ::stat(target_.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) return "is a directory";
  if (exists && !S_ISREG(st.st_mode)) {  // a device or FIFO: written in place, opened late
    direct_ = true;
    if (::access(target_.c_str(), W_OK) != 0) return "cannot be written: " + errno_text();
    return "";
  }
  if (exists && (::access(target_.c_str(), W_OK) != 0 || (st.st_mode & 0222) == 0))
    return "is read-only (mode " + mode_text(st.st_mode) +
           "); pxflow does not replace a file that is not writable: chmod u+w it or choose "
           "another name";
  const std::string dir = folder_of(target_);
  const std::string name = fs::path(target_).filename().string();
  if (clean) remove_dead_temporaries(dir, [&](const std::string& n) { return n == name; });
  if (std::string why = space_problem(dir); !why.empty()) return why;
  tmp_ = temporary_name(target_);
  fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0 && errno == EEXIST) {  // this process's own, from an earlier plan
    ::unlink(tmp_.c_str());
    fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  }
  if (fd_ < 0) {
    const std::string why = errno_text();
    tmp_.clear();
    return "cannot be created: " + why;
  }
  if (exists) {  // the replacement keeps the owner and mode (the owner first: chown clears setuid)
    if (::fchown(fd_, st.st_uid, st.st_gid) != 0) {
      // Only root may give a file away; the group, when the user is in it.
      (void)!::fchown(fd_, static_cast<uid_t>(-1), st.st_gid);
    }
    if (::fchmod(fd_, st.st_mode & 07777) != 0) {
      const std::string why = errno_text();
      discard();
      return "cannot keep its mode " + mode_text(st.st_mode) + ": " + why;
    }
  }
  slot_ = in_flight::begin(tmp_, target_, fd_,
                           stream_ ? in_flight::Kind::stream : in_flight::Kind::whole_file,
                           static_cast<in_flight::Marker>(marker_));
  return "";
}

void PlannedPath::open() {
  prepared_ = true;
  if (const std::string why = try_open(); !why.empty())
    throw InputError(label() + ": " + why + " (checked before any work)");
}

void PlannedPath::append(std::string_view bytes) {
  if (!prepared_) throw std::logic_error(label() + ": written before its plan was prepared");
  if (done_) throw std::logic_error(label() + ": written after it was finished");
  if (failed_) throw std::logic_error(label() + ": written after a failed write");
  int fd = fd_;
  if (descriptor_ >= 0) {
    if (descriptor_ == 1) std::fflush(stdout);  // what printf wrote comes first
    fd = descriptor_;
  } else if (fd_ < 0 && direct_) {
    // A FIFO's open waits for its reader: a signal cuts it short.
    while ((fd_ = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY)) < 0 && errno == EINTR)
      stop_if_interrupted_while("opening " + label());
    if (fd_ < 0) throw OutputError(label() + ": cannot open: " + errno_text());
    fd = fd_;
  }
  if (write_all(fd, bytes)) {
    size_ += bytes.size();
    return;
  }
  const int error = errno;
  const std::string why = errno_text();
  if (error == EPIPE) stop_now(SIGPIPE, label() + ": its reader went away (EPIPE)");
  if (!direct_) {
    failed_ = true;
    discard();
    throw OutputError(label() + ": cannot write: " + why + " (the previous file is unchanged)");
  }
  if (descriptor_ == 1) throw OutputError(label() + ": cannot write to standard output: " + why);
  throw OutputError(label() + ": cannot write: " + why);
}

void PlannedPath::commit() {
  if (done_) return;
  done_ = true;
  if (descriptor_ >= 0) {
    if (descriptor_ == 1) check_stdout();
    return;
  }
  // The safety net of the one door: a file read after the plan was prepared is an input too.
  for (const std::string& in : inputs_noted())
    if (!direct_ && same_file(target_, in)) {
      discard();
      throw InputError(label() + ": is an input (" + in +
                       ", read during the run); pxflow never overwrites an input");
    }
  bool ok = direct_ || ::fsync(fd_) == 0;
  std::string why = errno_text();
  if (ok && !direct_) in_flight::set_kind(slot_, in_flight::Kind::complete);
  if (fd_ >= 0 && ::close(fd_) != 0 && ok) ok = false, why = errno_text();
  fd_ = -1;
  if (ok && !direct_ && ::rename(tmp_.c_str(), target_.c_str()) != 0)
    ok = false, why = errno_text();
  if (!ok) {
    failed_ = true;
    discard();
    throw OutputError(label() + ": cannot write: " + why +
                      (direct_ ? "" : " (the previous file is unchanged)"));
  }
  in_flight::end(slot_);
  slot_ = -1;
  tmp_.clear();
  ++g_files_changed;
}

void PlannedPath::discard() {
  in_flight::set_kind(slot_, in_flight::Kind::discarded);
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!tmp_.empty()) ::unlink(tmp_.c_str());
  tmp_.clear();
  in_flight::end(slot_);
  slot_ = -1;
}

void OutputFile::write(std::string_view bytes) {
  append(bytes);
  commit();
}

OutputStream::OutputStream(std::string option, std::string path, StreamFormat format)
    : PlannedPath(std::move(option), std::move(path)) {
  stream_ = true;
  marker_ = static_cast<int>(format == StreamFormat::csv ? in_flight::Marker::csv
                                                         : in_flight::Marker::json_lines);
}

OutputStream::~OutputStream() {
  const int sig = interrupt_signal();
  stop(sig != 0 ? signal_name(sig) : "error");
}

void OutputStream::header(std::string_view bytes) {
  append(bytes);
  record_end_ = size_;
  in_flight::record(slot_, size_, 0);
}

void OutputStream::add(std::string_view bytes) {
  append(bytes);
  ++records_;
  record_end_ = size_;
  in_flight::record(slot_, size_, records_);
}

void OutputStream::finish() { commit(); }

bool OutputStream::stop(const std::string& stopped_by) noexcept {
  if (!prepared_ || done_ || failed_) return false;
  if (records_ == 0) {
    done_ = true;
    discard();
    return false;
  }
  char marker[160];
  const std::size_t n = in_flight::format_marker(
      marker, sizeof marker, static_cast<in_flight::Marker>(marker_), records_, stopped_by.c_str());
  if (descriptor_ >= 0 || direct_) {
    // Written in place: the marker follows, unless the reader is gone.
    done_ = true;
    const int fd = descriptor_ >= 0 ? descriptor_ : fd_;
    if (descriptor_ == 1) std::fflush(stdout);
    const bool marked = stopped_by != "SIGPIPE" && fd >= 0 && write_all(fd, {marker, n});
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    return descriptor_ < 0 && marked;  // standard output is never a file "kept"
  }
  try {
    const off_t end = static_cast<off_t>(record_end_);
    if (::ftruncate(fd_, end) != 0 || ::lseek(fd_, end, SEEK_SET) != end)
      throw OutputError(label() + ": cannot cut it to its last record: " + errno_text());
    size_ = record_end_;
    append({marker, n});
    commit();
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pxflow: error: %s\n", e.what());
    done_ = true;
    discard();
    return false;
  }
}

void OutputFolder::write(const std::string& name, std::string_view bytes) {
  const std::string path = (fs::path(dir_) / name).string();
  if (plan_ == nullptr) throw std::logic_error(option_ + " " + path + ": folder not prepared");
  plan_->check_not_an_input(option_, path);
  // Written whole, as a planned file is: its temporary first, renamed into place.
  OutputFile file(option_, path);
  file.prepared_ = true;
  if (const std::string why = file.try_open(false); !why.empty())
    throw OutputError(file.label() + ": " + why);
  file.write(bytes);
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

OutputStream& OutputPlan::stream(const std::string& option, const std::string& path,
                                 StreamFormat format) {
  if (prepared_) throw std::logic_error(option + ": output added after the plan was prepared");
  return streams_.emplace_back(option, path, format);
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
  if (descriptor_of(path) >= 0) return;  // standard output, or a descriptor of the caller's
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
      const int fa = descriptor_of(a.path), fb = descriptor_of(b.path);
      if (fa == 1 && fb == 1)
        throw InputError(a.option + " " + a.path + " and " + b.option + " " + b.path +
                         ": only one of them can write to standard output (-)");
      if (fa >= 0 && fa == fb)
        throw InputError(a.option + " " + a.path + " and " + b.option + " " + b.path +
                         ": both write to descriptor " + std::to_string(fa) +
                         "; give each output its own");
      // A descriptor and a file: the file the descriptor writes to (`--csv /dev/stdout > f`).
      const auto file_of = [](const std::string& p, int fd) {
        return fd >= 0 ? "/proc/self/fd/" + std::to_string(fd) : p;
      };
      const bool one_file =
          (fa < 0 && fb < 0 && resolved(a.path) == resolved(b.path)) ||
          ((fa < 0 || fb < 0) && same_file(file_of(a.path, fa), file_of(b.path, fb)));
      if (one_file)
        throw InputError(a.option + " " + a.path + " and " + b.option + " " + b.path +
                         ": the same file; give each output its own name");
    }
  prepared_ = true;
  // Create every temporary now: an output that cannot be written fails before any work.
  for (OutputFile& f : files_) f.open();
  for (OutputStream& s : streams_) s.open();
  for (OutputFolder& f : folders_) {
    remove_dead_temporaries(f.dir_, [&](const std::string& name) {
      return name == kProbeName || matches(name, f.pattern_);
    });
    if (const std::string why = space_problem(f.dir_); !why.empty())
      throw InputError(f.option_ + " " + f.dir_ + ": " + why + " (checked before any work)");
    const std::string probe = temporary_name((fs::path(f.dir_) / kProbeName).string());
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
  const bool cout_lost = !std::cout;
  errno = 0;
  const bool flush_failed = std::fflush(stdout) != 0;
  const int error = errno;
  if (!cout_lost && !flush_failed && !std::ferror(stdout)) return;
  std::cout.clear();
  std::clearerr(stdout);
  // An earlier write may have failed where errno is long gone: a pipe without a reader says
  // so in poll().
  struct pollfd p {
    1, POLLOUT, 0
  };
  if (error == EPIPE || (::poll(&p, 1, 0) == 1 && (p.revents & POLLERR) != 0))
    stop_now(SIGPIPE, "standard output: its reader went away (EPIPE)");
  throw OutputError("cannot write to standard output: " +
                    (error != 0 ? std::string(std::strerror(error)) : "a write failed"));
}

}  // namespace pxflow
