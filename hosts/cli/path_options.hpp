// Every option whose value is a path says, where it is declared (OptionSpec::path_kind), what
// pxflow does with it. The
// kind is used twice, so that no command has to remember either:
//   - before a command runs, every input option's value is noted as an input of the process
//     (io/file_inputs.hpp), so an output onto it, or inside an input folder, is refused;
//   - `pxflow --list-options` prints every command's options with their kinds and the command's
//     cheap runs, from which tests/cli/file_matrix.py generates its cases (a new option or
//     command is in the matrix without a new test).
// An option with a string value that declares neither a path kind nor a type name of its own
// ("TEXT", CLI11's default) fails that test: every value says what it is.
#pragma once
#include <string>

namespace pxflow::cli {

enum class PathKind {
  InputFile,     // a file read: a JSON file, a list of pairs, a frame
  InputFolder,   // a folder read inside (--data): nothing is written in it
  InputSource,   // a file, a folder, a glob or - (flow's SOURCE)
  OutputFile,    // a file written, '-' standard output
  OutputFolder,  // an existing folder files are written into (--repro-dir, flow --draw)
  OwnedFolder,   // a folder pxflow makes and owns (report --out): its rule is io's
  UpdatedFile,   // a file read, then replaced whole by the result (check --resume FILE)
};

const char* path_kind_name(PathKind kind);  // "input-file", ...

// An option's kind; `suffix` is the file name ending a value must have (".png"), for the matrix's
// file names.
struct DeclaredPath {
  PathKind kind;
  std::string suffix;
};

struct CommandSpec;  // option_spec.hpp

// Notes the values of every input option given to `sub` as inputs (io/file_inputs.hpp).
void note_given_inputs(const CommandSpec& sub);

}  // namespace pxflow::cli
