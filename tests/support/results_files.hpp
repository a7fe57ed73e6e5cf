// Results files for report tests: small `pxflow check --json` and `pxflow bench --json` files
// (c.json, b.json in `dir`) of the reference rows, for tests that feed a report without running
// anything else, and a report's sections read back.
#pragma once
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "run_program.hpp"

namespace pxflow::test {

inline void make_small_results(const TempDir& dir) {
  REQUIRE(run_pxflow({"check", "--backends", "ref-original,ref-local", "--generated-only", "--json",
                      dir.path("c.json")})
              .exit_code == 0);
  REQUIRE(run_pxflow({"bench", "--backends", "ref-original", "--batch", "1", "--min-time", "0",
                      "--json", dir.path("b.json")})
              .exit_code == 0);
}

// The section of a report's results.json with this key (nullptr: none).
inline const nlohmann::json* section(const nlohmann::json& results, const std::string& key) {
  for (const auto& s : results["sections"])
    if (s["key"] == key) return &s;
  return nullptr;
}

}  // namespace pxflow::test
