// Every timed row of pxflow bench and pxflow report shows its bound and the fraction of it
// achieved, or says why it has none (docs/harness.md, "The bound of every row"); the report
// charts the fractions, one chart per point.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "bench_bound.hpp"
#include "results_files.hpp"
#include "run_program.hpp"

namespace pxflow::test {
namespace {

using nlohmann::json;

// SPEC §6's SAD bytes of a px4flow-64 frame: 64 POIs x (81 + 8) x 64.
constexpr double kSadBytes64 = 364544;

// The one rule: a timed row has its bound (a unit, a figure, the fraction achieved and its
// inverse), or a bound "none: why" with the reason in its note; a row not timed has neither.
void require_bound(const json& row) {
  INFO(row.dump());
  const std::string bound = row.value("bound", "");
  if (row["samples_ns_per_frame"].empty()) {
    CHECK(bound.empty());
    return;
  }
  REQUIRE_FALSE(bound.empty());
  if (bound.rfind("none: ", 0) == 0) {
    CHECK(row["note"].get<std::string>().find("no bound: " + bound.substr(6)) != std::string::npos);
    CHECK_FALSE(row.contains("bound_fraction"));
    return;
  }
  REQUIRE(row.contains("bound_per_frame"));
  REQUIRE(row.contains("bound_fraction"));
  CHECK_FALSE(row["bound_unit"].get<std::string>().empty());
  CHECK(row["bound_fraction"].get<double>() * row["bound_ratio"].get<double>() ==
        Approx(1.0).epsilon(1e-9));
}

// The rows of `wanted` this build registers, comma-separated (a row a build lacks is an unknown
// name to --backends).
std::string registered(const std::set<std::string>& wanted) {
  const RunResult r = run_pxflow({"backends"});
  REQUIRE(r.exit_code == 0);
  std::istringstream in(r.out);
  std::string list;
  for (std::string line; std::getline(in, line);) {
    const std::string name = line.substr(0, line.find(' '));
    if (wanted.contains(name)) list += (list.empty() ? "" : ",") + name;
  }
  return list;
}

double host_bytes_per_cycle(const json& bench, int threads) {
  for (const auto& t : bench["bound"]["by_threads"])
    if (t["threads"] == threads) return t["bytes_per_cycle"].get<double>();
  FAIL("no bound measured on " << threads << " threads");
  return 0;
}

// The figures each kind of row's bound must have (docs/harness.md, "The bound of every row").
void check_figure(const json& bench, const json& row) {
  INFO(row.dump());
  const std::string unit = row.value("bound_unit", ""), backend = row["backend"];
  if (backend == "gap8-fast") {  // 4 bytes per cycle on each of 8 cores
    CHECK(unit == "cycles");
    CHECK(row["bound_per_frame"].get<double>() == kSadBytes64 / 32);
    CHECK(row["bound_fraction"].get<double>() ==
          Approx(kSadBytes64 / 32 / row["cycles_per_frame"].get<double>()));
  } else if (backend == "m4-qemu") {  // one USADA8 per 4 bytes
    CHECK(unit == "instructions");
    CHECK(row["bound_per_frame"].get<double>() == kSadBytes64 / 4);
  } else if (unit == "tsc-cycles") {  // the host's ceiling on the row's threads
    CHECK(row["bound_per_frame"].get<double>() ==
          Approx(kSadBytes64 / host_bytes_per_cycle(bench, row["threads"].get<int>())));
  } else if (unit == "ns") {  // a CPU device: the ceiling on all cores at the TSC's rate
    CHECK((backend == "opencl" || backend == "vulkan"));
    const double hz = bench["bound"]["tsc_hz"].get<double>();
    const double bpc = host_bytes_per_cycle(bench, row["threads"].get<int>());
    CHECK(row["bound_per_frame"].get<double>() == Approx(kSadBytes64 / (bpc * hz) * 1e9));
  }
}

}  // namespace

TEST_CASE("bench: every timed row shows its bound and the fraction achieved, or why it has none",
          "[bench]") {
  const std::string backends =
      registered({"ref-original", "cpu", "gap8-fast", "m4-qemu", "opencl", "vulkan"});
  const RunResult r = run_pxflow({"bench", "--backends", backends, "--batch", "1", "--min-time",
                                  "0", "--processes", "1", "--json", "-"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(r.out);
  int timed = 0;
  for (const auto& row : j["rows"]) {
    require_bound(row);
    if (row.contains("bound_fraction")) check_figure(j, row);
    timed += !row["samples_ns_per_frame"].empty();
  }
  CHECK(timed >= 1);
#if defined(PXFLOW_TEST_CPU_BUILT) && defined(__x86_64__)
  for (const auto& row : j["rows"])  // the host's ceiling is measured: every host row has it
    if (row["source"] == "host-steady-clock+tsc") CHECK(row["bound_unit"] == "tsc-cycles");
#endif
  // The table: every timed row's line has a fraction or says "none".
  std::istringstream table(r.err);
  for (std::string line; std::getline(table, line);)
    if (line.find("host-steady-clock") != std::string::npos ||
        line.find("-cycles ") != std::string::npos)
      CHECK((line.find(" %") != std::string::npos || line.find(" none ") != std::string::npos));
}

TEST_CASE("bench --no-bound: host rows say they have no bound, a model's bound stays", "[bench]") {
  const std::string backends = registered({"ref-original", "gap8-fast"});
  const RunResult r = run_pxflow({"bench", "--backends", backends, "--batch", "1", "--min-time",
                                  "0", "--processes", "1", "--no-bound", "--json", "-"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(r.out);
  for (const auto& row : j["rows"]) {
    require_bound(row);
    if (row["backend"] == "ref-original")
      CHECK(row["bound"] == "none: not measured (bench --no-bound)");
    if (row["backend"] == "gap8-fast") CHECK(row["bound_unit"] == "cycles");
  }
}

// set_row_bound over every kind of row the bench meets: a timed row never leaves it without a
// bound or a reason, and a GPU says which figure it lacks.
TEST_CASE("set_row_bound: every timed row gets a bound or a reason", "[bench]") {
  const BenchBound host{"test ceiling", "tsc", nullptr, nullptr};
  for (const bool with_host : {false, true})
    for (const bool on_host : {false, true})
      for (const char* kind : {"", "cpu", "gpu", "other"})
        for (const bool own : {false, true})
          for (const char* source :
               {"host-steady-clock+tsc", "host-steady-clock", "device-clock"}) {
            BenchRow row;
            row.backend = "x", row.source = source, row.threads = 2, row.pois_per_frame = 64;
            row.search_radius = 4, row.samples_ns_per_frame = {1000};
            row.median_ns_per_frame = 1000, row.cycles_per_frame = 5000;
            BoundInputs in;
            in.host = with_host ? &host : nullptr;
            in.why_none = "no host bound here";
            in.host_bytes_per_cycle = [](int threads) { return 32.0 * threads; };
            in.tsc_hz = [] { return 2e9; };
            in.on_host = on_host, in.device_kind = kind;
            if (own) in.device = Backend::DeviceBound{"model bound", "cycles", 100};
            set_row_bound(row, in);
            INFO(source << " kind=" << kind << " host=" << with_host << " on_host=" << on_host
                        << " own=" << own << ": " << row.bound);
            REQUIRE_FALSE(row.bound.empty());
            CHECK((row.bound_fraction > 0) != (row.bound.rfind("none: ", 0) == 0));
            if (std::string(kind) == "gpu" && !on_host && !(own && source[0] == 'd'))
              CHECK(row.bound.find("GPU") != std::string::npos);
          }
  BenchRow untimed;  // not timed: left as it is, its note says why
  set_row_bound(untimed, BoundInputs{});
  CHECK(untimed.bound.empty());
}

TEST_CASE("report: one chart per point of every row's fraction of its bound", "[report]") {
  TempDir dir;
  make_small_results(dir);
  REQUIRE(run_pxflow({"bench", "--backends", "ref-original,ref-local", "--batch", "1,2",
                      "--min-time", "0", "--processes", "1", "--json", dir.path("b.json")})
              .exit_code == 0);
  const RunResult r = run_pxflow({"report", "--out", dir.path("r"), "--check-json",
                                  dir.path("c.json"), "--bench-json", dir.path("b.json"),
                                  "--no-accuracy", "--backends", "ref-original,ref-local"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  const json* bound = section(j, "bound");
  REQUIRE(bound);
  CHECK((*bound)["header"] ==
        json::array({"point", "backend", "clock", "bound/frame", "of bound", "bound"}));
  REQUIRE((*bound)["rows"].size() == 4);  // 2 points x 2 backends, all timed
  std::size_t bars = 0;
  for (const auto& c : (*bound)["charts"]) {
    CHECK(c["kind"] == "bar");
    CHECK(c["unit"] == "% of bound");
    bars += c["bars"].size();
  }
  std::size_t with_bound = 0;
  for (const auto& row : (*bound)["rows"]) {
    CHECK_FALSE(row[5].get<std::string>().empty());  // the bound, or "none: why"
    with_bound += row[4].get<std::string>().ends_with(" %");
  }
  CHECK(bars == with_bound);  // every row with a bound is a bar of its point's chart
#if defined(PXFLOW_TEST_CPU_BUILT) && defined(__x86_64__)
  CHECK((*bound)["charts"].size() == 2);  // one per point
  CHECK(with_bound == 4);
#endif
}

}  // namespace pxflow::test
