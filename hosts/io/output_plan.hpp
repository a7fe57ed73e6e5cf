// Files pxflow writes, the one way. A command declares every path it will write, and every file
// it will read, in one OutputPlan, and prepares the plan before any work. prepare() refuses, as
// one line and exit 2 (InputError):
//   - an output that is an input, or lies in a folder the command reads (--data);
//   - two outputs that are the same file;
//   - an output that cannot be created: each one's temporary file is created then, beside it.
// Nothing else can write a file: a file is written only through the handle its plan returned.
//
// A whole file (OutputFile: --json, a report's files) goes to its temporary and is renamed into
// place only when complete, so an interrupt, a crash or a full disk leaves the previous file
// intact. A stream (OutputStream: --jsonl, --csv) is appended to as each pair completes and is
// renamed into place when the run ends, finished or not, so no completed pair is ever lost; a run
// that completed nothing leaves the previous file. A device or FIFO (/dev/full, a pipe) is written
// directly. Every write and close is checked: a failure is an OutputError (one line, exit 1).
// The path "-" is standard output.
#pragma once
#include <cstddef>
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

// One planned output file: its temporary is opened by OutputPlan::prepare().
class PlannedPath {
 public:
  PlannedPath(std::string option, std::string path)
      : option_(std::move(option)), path_(std::move(path)) {}
  PlannedPath(const PlannedPath&) = delete;
  PlannedPath& operator=(const PlannedPath&) = delete;
  ~PlannedPath();
  const std::string& option() const { return option_; }
  const std::string& path() const { return path_; }
  bool to_stdout() const { return path_ == kStdoutPath; }

 protected:
  friend class OutputPlan;
  void open();  // creates the temporary (or checks a device is writable)
  void append(std::string_view bytes);
  void commit();   // renames the temporary into place
  void discard();  // removes the temporary
  std::string label() const { return option_ + " " + path_; }
  std::string option_, path_, tmp_;
  int fd_ = -1;
  bool direct_ = false;  // standard output, a device or a FIFO: no temporary
  bool prepared_ = false, done_ = false;
};

// A file written whole, once.
class OutputFile : public PlannedPath {
 public:
  using PlannedPath::PlannedPath;
  void write(std::string_view bytes);
};

// Records appended as they complete; see the top of this file.
class OutputStream : public PlannedPath {
 public:
  using PlannedPath::PlannedPath;
  ~OutputStream();                      // an unfinished stream keeps what it holds (see above)
  void header(std::string_view bytes);  // written first; alone it is not worth keeping
  void add(std::string_view bytes);     // one completed record, at once in the file
  void finish();                        // the run is complete
  std::size_t records() const { return records_; }

 private:
  std::size_t records_ = 0;
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
  OutputStream& stream(const std::string& option, const std::string& path);
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
// was lost (e.g. `pxflow flow --json A B > /dev/full`).
void check_stdout();

}  // namespace pxflow
