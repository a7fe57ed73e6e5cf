// Files pxflow writes, the one way. A command declares every path it will write, and every file
// it will read, in one OutputPlan, and prepares the plan before any work. prepare() refuses, as
// one line and exit 2 (InputError):
//   - an output that is an input, or lies in a folder the command reads (--data);
//   - two outputs that are the same file (two spellings of standard output included);
//   - an existing output this user may not write, or whose mode has no write bit at all (root
//     bypasses the bits; pxflow does not, like `cp -i`: chmod u+w it or choose another name);
//   - an output on a file system with less than kMinFreeBytes free (or no free inode);
//   - an output that cannot be created: each one's temporary file is created then.
// Nothing else can write a file: a file is written only through the handle its plan returned.
//
// Where a path writes (as GNU cp, sort -o, sed -i and rsync do):
//   - "-", /dev/stdout, /dev/fd/1 and /proc/self/fd/1 are standard output; /dev/stderr,
//     /dev/fd/N and /proc/self/fd/N write to that open descriptor;
//   - a symbolic link is written at its target: the temporary lives beside the target and is
//     renamed onto it, the link stays a link;
//   - an existing file keeps its mode and owner (the temporary gets them before the rename);
//   - any other device or FIFO (/dev/null, a named pipe) is written in place, never renamed over.
// Temporaries are hidden and named as pxflow's own: ".NAME.pxflow-PID.tmp" beside NAME
// (temporary_name, is_pxflow_temporary). Those of a process that is gone (a SIGKILL) are removed
// when a later run prepares NAME.
//
// A whole file (OutputFile: --json, a report's files) goes to its temporary and is renamed into
// place only when complete, so an interrupt, a crash or a full disk leaves the previous file
// intact. A stream (OutputStream: --jsonl, --csv) is appended to as each record completes. A
// finished stream is renamed into place as it is. A stream that stopped early (a signal, EPIPE
// on standard output, a bad frame, a failed backend) and holds records is kept: it ends at its
// last complete record, followed by one marker line (io/in_flight.hpp, in_flight::
// format_marker), so no completed record is lost and a partial file is never taken for a whole
// one:
//   JSON lines: {"incomplete": {"records": 243, "stopped_by": "SIGINT"}}
//   CSV:        # incomplete: 243 records, stopped by SIGINT
// stopped_by is the signal's name, or "bad input", "write error", "backend error", "error". A
// stream that completed nothing leaves the previous file. Every write and close is checked: a
// failure is an OutputError (one line, exit 1); the file it was for is then never kept (its
// previous version stays).
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pxflow {

struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr const char* kStdoutPath = "-";

// An output's file system must have at least this much free space before the work starts
// (a run that would fail at its first write is refused at once instead).
inline constexpr std::uint64_t kMinFreeBytes = std::uint64_t{1} << 20;

// The open descriptor a path names: 1 for "-", N for /dev/fd/N, /proc/self/fd/N (or this
// process's PID for self), 0, 1, 2 for /dev/stdin, /dev/stdout, /dev/stderr; -1 for a file.
int descriptor_of(const std::string& path);

// The hidden temporary of `target` (a path): ".NAME.pxflow-PID.tmp" in its folder.
std::string temporary_name(const std::string& target);
// True for a file name (no folder) temporary_name makes, of any process.
bool is_pxflow_temporary(const std::string& filename);

// One planned output file: its temporary is opened by OutputPlan::prepare().
class PlannedPath {
 public:
  PlannedPath(std::string option, std::string path)
      : option_(std::move(option)), path_(std::move(path)), descriptor_(descriptor_of(path_)) {}
  PlannedPath(const PlannedPath&) = delete;
  PlannedPath& operator=(const PlannedPath&) = delete;
  ~PlannedPath();
  const std::string& option() const { return option_; }
  const std::string& path() const { return path_; }
  bool to_stdout() const { return descriptor_ == 1; }

 protected:
  friend class OutputPlan;
  friend class OutputFolder;
  void open();  // throws InputError: see the top of this file
  // What stops `open` (one line after the label), or "" when it is ready. `clean`: remove the
  // dead temporaries of the target first (an OutputFolder did so once for all its files).
  std::string try_open(bool clean = true);
  void append(std::string_view bytes);  // OutputError; EPIPE: the SIGPIPE stop (Interrupted)
  void commit();                        // renames the temporary into place
  void discard();                       // removes the temporary
  std::string label() const { return option_ + " " + path_; }
  std::string option_, path_;
  int descriptor_;      // descriptor_of(path_)
  std::string target_;  // path_ with its links followed
  std::string tmp_;
  int fd_ = -1;
  int slot_ = -1;        // in the signal handler's table (core/interrupt.hpp)
  bool direct_ = false;  // a descriptor, a device or a FIFO: no temporary
  bool stream_ = false;
  int marker_ = 0;          // in_flight::Marker, for a stream
  std::uint64_t size_ = 0;  // bytes in the temporary
  bool prepared_ = false, done_ = false, failed_ = false;
};

// A file written whole, once.
class OutputFile : public PlannedPath {
 public:
  using PlannedPath::PlannedPath;
  void write(std::string_view bytes);
};

enum class StreamFormat { json_lines, csv };  // which marker ends an incomplete stream

// Records appended as they complete; see the top of this file.
class OutputStream : public PlannedPath {
 public:
  OutputStream(std::string option, std::string path, StreamFormat format);
  ~OutputStream();                      // an unfinished stream: stop("error")
  void header(std::string_view bytes);  // written first; alone it is not worth keeping
  void add(std::string_view bytes);     // one completed record, at once in the file
  void finish();                        // the run is complete
  // The run stopped early (`stopped_by`: see the top of this file): a stream with records is
  // cut to its last one, marked and kept; true when a file was kept. Never throws: a failure is
  // one line on stderr, and the previous file stays.
  bool stop(const std::string& stopped_by) noexcept;
  std::size_t records() const { return records_; }

 private:
  std::size_t records_ = 0;
  std::uint64_t record_end_ = 0;  // size_ after the last complete record (or the header)
};

// A folder the command writes files into as it goes (flow --draw DIR: pair-NNNNNN.png), each
// file whole and at once. It must exist; prepare() checks a file can be created in it.
class OutputFolder {
 public:
  OutputFolder(std::string option, std::string dir, std::string pattern)
      : option_(std::move(option)), dir_(std::move(dir)), pattern_(std::move(pattern)) {}
  const std::string& dir() const { return dir_; }
  // Writes `name` (a plain file name) in the folder; refuses an input.
  void write(const std::string& name, std::string_view bytes);
  // Removes the files of the pattern that this run did not write (an earlier, longer run's
  // pair-000004.png): the folder's pictures are one run's. Called when the run ends or stops.
  void remove_earlier();
  // Makes the folder `name` (a relative path) inside: false when it exists; OutputError when it
  // cannot be made (check's pxflow-repro-N).
  bool make_subfolder(const std::string& name);

 private:
  friend class OutputPlan;
  std::string option_, dir_, pattern_;  // pattern: e.g. "pair-NNNNNN.png", for messages
  std::vector<std::string> written_;
  const class OutputPlan* plan_ = nullptr;
};

// Inputs are the process's (io/file_inputs.hpp): every file read through hosts/io and every input
// option of the command's table, whichever plan is asking; read() and read_folder() add to them.
class OutputPlan {
 public:
  void read(const std::string& path);  // a file the command reads ("-" ignored)
  void read_all(const std::vector<std::string>& paths);
  void read_folder(const std::string& option, const std::string& dir);  // nothing written inside
  OutputFile& file(const std::string& option, const std::string& path);
  OutputStream& stream(const std::string& option, const std::string& path,
                       StreamFormat format = StreamFormat::json_lines);
  OutputFolder& folder(const std::string& option, const std::string& dir,
                       const std::string& pattern);
  // A folder the plan's files go into, owned by pxflow (report --out, vectors --out; the rule of
  // io/owned_folder.hpp, with `manifest` the file name of its list of files): prepare() refuses
  // a folder of other files and creates a missing one, removed again if prepare() refuses.
  void make_folder(const std::string& option, const std::string& dir, const std::string& manifest);
  // Checks the plan as described at the top and opens every temporary; throws InputError.
  void prepare();
  // Throws InputError when `path` is one of the inputs (for outputs named during the run).
  void check_not_an_input(const std::string& option, const std::string& path) const;

 private:
  void check_output(const std::string& option, const std::string& path, bool is_folder) const;
  void check_not_in_input_folder(const std::string& option, const std::string& path) const;
  void check_and_open();
  std::deque<OutputFile> files_;
  std::deque<OutputStream> streams_;
  std::deque<OutputFolder> folders_;
  struct MadeFolder {
    std::string option, dir, manifest;
  };
  std::vector<MadeFolder> made_folders_;
  bool prepared_ = false;
};

// How many files this process has written or replaced so far (standard output aside): an
// interrupted run says "no output file was changed" only when it is 0.
std::size_t files_changed();

// Flushes standard output (C and C++ streams) and throws OutputError when anything written to it
// was lost (e.g. `pxflow flow --json A B > /dev/full`); a reader that went away (EPIPE,
// `| head -3`) is the SIGPIPE stop instead (Interrupted, exit 141).
void check_stdout();

}  // namespace pxflow
