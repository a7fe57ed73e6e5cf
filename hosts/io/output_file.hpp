// Files pxflow writes, the one way: the path is checked before any work (its folder exists, it
// is not a folder, it is none of the inputs), and the bytes go to a temporary file beside it that
// is renamed into place only when complete, so an interrupt, a crash or a full disk leaves the
// previous file intact. A device or FIFO (e.g. /dev/full, a pipe) is written directly. Every
// write and close is checked: a failure is an OutputError (one line, exit 1). The path "-" is
// standard output (`--json -`).
#pragma once
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pxflow {

struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws InputError naming `option` (e.g. "--json") when `path` cannot be an output: empty, a
// folder, in a folder that does not exist, or the same file (device and inode) as one of
// `inputs`.
void check_output_path(const std::string& option, const std::string& path,
                       std::span<const std::string> inputs = {});

// Throws InputError when `path` is the same file (device and inode) as one of `inputs`.
void check_not_an_input(const std::string& option, const std::string& path,
                        std::span<const std::string> inputs);

inline constexpr const char* kStdoutPath = "-";

// Writes `bytes` to `path` as described above ("-": standard output, checked like a file);
// throws OutputError when any step fails.
void write_output_file(const std::string& path, std::string_view bytes);

// Flushes standard output (C and C++ streams) and throws OutputError when anything written to it
// was lost (e.g. `pxflow flow --json A B > /dev/full`).
void check_stdout();

}  // namespace pxflow
