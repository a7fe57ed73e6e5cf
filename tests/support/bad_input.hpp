// The bad-input contract of every pxflow command, as a test assertion: exit 2, exactly one
// stderr line containing `needle`, nothing on stdout (no partial output).
#pragma once
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "run_program.hpp"

namespace pxflow::test {

inline void require_bad_input(const std::vector<std::string>& args, const std::string& needle) {
  const auto r = run_pxflow(args);
  INFO("stderr: " << r.err << "stdout: " << r.out);
  CHECK(r.exit_code == 2);
  CHECK(r.err_lines() == 1);
  CHECK(r.err.find(needle) != std::string::npos);
  CHECK(r.out.empty());
}

}  // namespace pxflow::test
