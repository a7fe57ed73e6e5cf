// Every option whose value is a real number is declared with its range (OptionSpec::real_in):
// "nan", "inf" and values outside the range are refused with one line (exit 2) by one check,
// never by each command (CLI11's Range lets nan through: `bench --min-time nan` once timed nothing
// and exited 0). `pxflow --list-options` prints each one's range, and tests/cli/file_matrix.py
// gives every one nan, inf and both sides of its range.
#pragma once
#include <string>

namespace pxflow::cli {

// "" when `text` is a finite number in lo..hi, else the line parse_errors.cpp rewords.
std::string real_value_problem(const std::string& text, double lo, double hi);

// What such a value is, in --help: "FLOAT in [0 - 600]".
std::string real_value_name(double lo, double hi);

}  // namespace pxflow::cli
