// The CLI's subcommands. Each adds itself to the app and returns the action to run when it was
// the one chosen. Actions return the process exit code; bad input is thrown as InputError
// (main prints it as one line and exits 2).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "option_spec.hpp"
#include "params.hpp"
#include "shared_options.hpp"

namespace pxflow::cli {

struct Command {
  CommandSpec* spec = nullptr;  // its options, owned by the top level's CommandSpec
  std::function<int()> run;
  // Command lines that show it at work, after "pxflow ", each ending in "  # what it does":
  // the Examples of its --help and man page (help_sections.hpp).
  std::vector<std::string> examples{};
  // Cheap runs of the command (each under a second or two) for the generated file-and-signal
  // matrix (tests/cli/file_matrix.py, docs/files-and-signals.md "The file-and-signal matrix,
  // generated from the option table"): argument lists after "pxflow CMD" with placeholders for
  // inputs the matrix makes ({PREV} {NEXT}: PNG frames; {RAW}: raw 64x64 frames back to back;
  // {PAIRS}: a list of pairs; {CHECK}: a check file of one shard; {BENCH}: a bench file; {DATA}: a
  // copy of the sample data; {VECTORS}, {RECORDS}: vectors). The matrix adds each output option to
  // the first run that accepts it. `long_runs` take seconds, for stopping mid-work: their outputs
  // are {OUT}.ext (the previous file stays, or a whole new one) or {KEPT}.ext (the work finished
  // before a stop is kept, marked incomplete). A command with a path option and no run fails the
  // matrix.
  std::vector<std::string> matrix_runs{};
  std::vector<std::string> long_runs{};
};

Command add_flow_command(CommandSpec& app);
Command add_merge_command(CommandSpec& app);    // pxflow merge: check shards combined
Command add_compare_command(CommandSpec& app);  // pxflow compare: bench files side by side
Command add_backends_command(CommandSpec& app);
Command add_check_command(CommandSpec& app);
Command add_bench_command(CommandSpec& app);
Command add_report_command(CommandSpec& app);
Command add_accuracy_command(CommandSpec& app);

// Options that describe the problem, shared by every command that runs kernels.
struct ProblemOptions {
  std::string profile{kDefaultProfile};
  std::vector<std::string> sets;  // KEY=VALUE

  void add_to(CommandSpec& app);
  // The profile with every --set applied in order; width/height default to `frame` when given
  // and not set explicitly (an explicit value that differs from the frame is an error). Valid.
  Params resolve(std::optional<std::pair<int, int>> frame) const;
  bool sets_key(std::string_view key) const;  // whether a --set names this key
};

}  // namespace pxflow::cli
