// Every option whose value is a real number is declared here, with its range: "nan", "inf" and
// values outside the range are refused with one line (exit 2) by one validator, never by each
// command (CLI11's Range lets nan through: `bench --min-time nan` once timed nothing and exited
// 0). `pxflow --list-options` prints each one's range, and tests/cli/file_matrix.py gives every
// one nan, inf and both sides of its range; a test fails on a CLI::Range of reals anywhere.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <utility>

namespace pxflow::cli {

// Checks `option`'s value: a finite number in lo..hi. Returns the option.
CLI::Option* declare_real(CLI::Option* option, double lo, double hi);

// The range declare_real() gave `option`, if any.
std::optional<std::pair<double, double>> declared_real(const CLI::Option* option);

}  // namespace pxflow::cli
