// The m4-qemu row's timing, honestly labelled: the bench reports instructions per frame (never
// cycles), the count is the same from run to run under -icount to within the counter's tick (5
// instructions: the tick's phase at the start of a run depends on how long the core slept in
// real time), the report's Cortex-M4 section puts it beside the paper's estimate, and its
// results.csv has the count in the instructions_per_frame column.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "run_program.hpp"

namespace {

using pxflow::test::run_pxflow;

// The m4-qemu row of a bench table: the line that names the row and its device clock.
std::string m4_line(const std::string& out) {
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);)
    if (line.find("m4-qemu ") != std::string::npos &&
        line.find("qemu-icount-instructions") != std::string::npos)
      return line;
  FAIL("no m4-qemu row timed by qemu-icount-instructions");
  return {};
}

// A CSV line's cells up to the note (the last column, the only one that may hold a comma).
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

}  // namespace

TEST_CASE("m4-qemu bench: instructions per frame, never cycles, the same every run",
          "[m4][timing]") {
  pxflow::test::TempDir dir;
  const auto a = run_pxflow({"bench", "--backends", "m4-qemu", "--json", dir.path("a.json")});
  const auto b = run_pxflow({"bench", "--backends", "m4-qemu", "--json", dir.path("b.json")});
  INFO(a.out << a.err);
  REQUIRE(a.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  const std::string line = m4_line(a.out);
  CHECK(line.find("qemu-icount-instructions") != std::string::npos);
  CHECK(line.find(" instr") != std::string::npos);  // the count is labelled instructions
  CHECK(line.find("cycles") == std::string::npos);
  std::vector<double> counts;
  for (const char* file : {"a.json", "b.json"}) {
    const auto j = nlohmann::json::parse(pxflow::test::slurp(dir.path(file)));
    bool first = true;  // each file's first point (64x64, batch 1) is the one compared
    for (const auto& row : j["rows"])
      if (row["backend"] == "m4-qemu" && row.contains("instructions_per_frame")) {
        CHECK_FALSE(row.contains("cycles_per_frame"));
        if (first) counts.push_back(row["instructions_per_frame"].get<double>());
        first = false;
      }
  }
  REQUIRE(counts.size() == 2);
  // at least the 91,520 SAD instructions of a fully accepted frame, fewer than 2 million
  CHECK(counts[0] > 91520);
  CHECK(counts[0] < 2e6);
  CHECK(std::abs(counts[0] - counts[1]) <= 5);  // one tick of the 25 MHz SysTick
}

TEST_CASE("m4-qemu report: the Cortex-M4 section beside the paper's estimate", "[m4][timing]") {
  pxflow::test::TempDir dir;
  REQUIRE(run_pxflow(
              {"check", "--backends", "m4-qemu", "--cases", "2", "--json", dir.path("check.json")})
              .exit_code == 0);
  const auto bench =
      run_pxflow({"bench", "--backends", "m4-qemu", "--json", dir.path("bench.json")});
  REQUIRE(bench.exit_code == 0);
  // An instruction count is no time: the bench's table gives no ns/frame or frames/s beside it.
  const std::regex timed_row("m4-qemu +qemu-icount-instructions +- +- +- +- +[0-9]+ instr ");
  const std::regex any_row("m4-qemu +qemu-icount-instructions ");
  std::istringstream lines(bench.out);
  int rows = 0;
  for (std::string line; std::getline(lines, line);)
    if (std::regex_search(line, any_row)) {
      INFO(line);
      CHECK(std::regex_search(line, timed_row));
      ++rows;
    }
  CHECK(rows > 0);
  const auto r = run_pxflow({"report", "--out", dir.path("report"), "--check-json",
                             dir.path("check.json"), "--bench-json", dir.path("bench.json"),
                             "--backends", "m4-qemu", "--no-accuracy"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const std::string md = pxflow::test::slurp(dir.path("report/report.md"));
  CHECK(md.find("## Cortex-M4 (m4-qemu) beside the ISCAS 2022 paper") != std::string::npos);
  CHECK(md.find("| USAD8/USADA8 per frame | 91520 | 91520 |") != std::string::npos);
  CHECK(md.find("| cycles attributed to those SADs | - | 22880 |") != std::string::npos);
  CHECK(md.find("| 648560 |") != std::string::npos);
  // One line per sweep table, labelled and filled with the instruction count, its n/a and
  // not-run cells included.
  CHECK(md.find("m4-qemu (model clock)") == std::string::npos);
  CHECK(md.find("| m4-qemu (instruction count) | 559") != std::string::npos);
  // results.csv carries the count (its only device figure) in its own column, as the JSON does.
  std::istringstream csv(pxflow::test::slurp(dir.path("report/results.csv")));
  std::string header;
  std::getline(csv, header);
  const std::vector<std::string> columns = cells_of(header);
  const auto at = std::find(columns.begin(), columns.end(), "instructions_per_frame");
  REQUIRE(at != columns.end());
  int counted_rows = 0;
  for (std::string line; std::getline(csv, line);) {
    if (line.find("\"qemu-icount-instructions\"") == std::string::npos) continue;
    INFO(line);
    const std::vector<std::string> cells = cells_of(line);
    REQUIRE(cells.size() > static_cast<std::size_t>(at - columns.begin()));
    CHECK(std::stod(cells[at - columns.begin()]) > 0);
    ++counted_rows;
  }
  CHECK(counted_rows > 0);
}
