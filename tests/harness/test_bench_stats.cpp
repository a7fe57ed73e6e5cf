// The bench's statistics (bench_stats.hpp) on samples with known answers, and `pxflow bench`
// keeping its promise: --min-time seconds of samples at least, every sample in the JSON, the
// interval around the median, the machine's state recorded.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "bench_stats.hpp"
#include "run_program.hpp"

namespace pxflow::test {
namespace {

using nlohmann::json;

TEST_CASE("the median's interval holds the median and widens to min..max with few samples",
          "[bench-stats]") {
  CHECK(median_of({3, 1, 2}) == 2);
  CHECK(median_of({4, 1, 3, 2}) == 2.5);
  // n = 5: ranks 1 and 5 (the binomial covers 94 % there): min..max.
  CHECK(median_ci95({5, 1, 4, 2, 3}) == std::pair<double, double>{1, 5});
  // n = 100, values 1..100: ranks floor(50 - 9.8) = 40 and ceil(50 + 9.8) + 1 = 61.
  std::vector<double> v;
  for (int i = 100; i >= 1; --i) v.push_back(i);
  CHECK(median_ci95(v) == std::pair<double, double>{40, 61});
}

TEST_CASE("noisy: a wide interval or a median far above the fastest sample", "[bench-stats]") {
  CHECK_FALSE(is_noisy(100, 97, 104, 95));
  CHECK(is_noisy(100, 90, 111, 95));  // interval 21 % of the median
  CHECK(is_noisy(100, 99, 101, 60));  // median 1.67x the minimum
}

TEST_CASE("Mann-Whitney U: the normal approximation with ties and continuity", "[bench-stats]") {
  // Separated samples, n = 5 and 5: U = 0, mean 12.5, variance 5 * 5 * 11 / 12, z = 12 / 4.787:
  // p = 0.01219 (scipy.stats.mannwhitneyu(..., method='asymptotic') gives the same).
  const std::vector<double> a{1, 2, 3, 4, 5}, b{6, 7, 8, 9, 10};
  CHECK(mann_whitney_p(a, b) == Approx(0.0121858).epsilon(1e-4));
  CHECK(mann_whitney_p(b, a) == mann_whitney_p(a, b));
  // Ties across the samples: scipy 1.x (method='asymptotic') gives 0.169368 for these.
  const std::vector<double> c{1, 2, 2, 3, 5, 7}, d{2, 3, 3, 4, 8, 9, 9};
  CHECK(mann_whitney_p(c, d) == Approx(0.169368).epsilon(1e-4));
  CHECK(mann_whitney_p(a, a) == 1.0);  // identical samples are never different
  CHECK(mann_whitney_p(std::vector<double>{1}, b) == 1.0);
}

TEST_CASE("ratio_interval95: the Hodges-Lehmann ratio and the interval that inverts the U test",
          "[bench]") {
  const std::vector<double> a{100, 101, 102, 103, 104};
  std::vector<double> slower;
  for (double x : a) slower.push_back(x * 1.1);
  const RatioInterval r = ratio_interval95(a, slower);
  REQUIRE(r.bounded);
  CHECK(r.ratio == Approx(1.1));
  // 5 and 5: the third smallest and third largest of the 25 log-differences (the exact table's).
  CHECK(r.low == Approx(111.1 / 104).epsilon(1e-12));
  CHECK(r.high == Approx(114.4 / 101).epsilon(1e-12));
  CHECK(mann_whitney_p(a, slower) < 0.05);
  // 3 and 3 cannot reach 95 %: unbounded, whatever the data.
  const RatioInterval few =
      ratio_interval95(std::vector<double>{1, 1, 1}, std::vector<double>{2, 2, 2});
  CHECK_FALSE(few.bounded);
  CHECK(few.ratio == Approx(2.0));
  // 4 and 4 is the least that can: the smallest and largest difference.
  const RatioInterval four = ratio_interval95(std::vector<double>{1, 1.1, 1.2, 1.3},
                                              std::vector<double>{2, 2.1, 2.2, 2.3});
  REQUIRE(four.bounded);
  CHECK(four.low == Approx(2.0 / 1.3));
  CHECK(four.high == Approx(2.3 / 1.0));
}

TEST_CASE("bench --min-time is a minimum of measured samples, each kept in the JSON", "[bench]") {
  const RunResult r = run_pxflow({"bench", "--backends", "ref-original,ref-local", "--batch", "1",
                                  "--min-time", "0.3", "--json", "-"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(r.out);
  REQUIRE(j["rows"].size() == 2);
  for (const auto& row : j["rows"]) {
    INFO(row.dump());
    CHECK(row["measured_s"].get<double>() >= 0.3);
    CHECK(row["repeats"].get<int>() >= 5);
    CHECK(row["samples_ns_per_frame"].size() == row["repeats"].get<std::size_t>());
    CHECK(row["median_ci_low_ns"] <= row["median_ns_per_frame"]);
    CHECK(row["median_ns_per_frame"] <= row["median_ci_high_ns"]);
    CHECK(row["min_ns_per_frame"] <= row["median_ci_low_ns"]);
    // The unit of replication is a process: five by default, each one's median kept, the
    // row's median theirs.
    REQUIRE(row["processes"] == 5);
    const auto medians = row["process_medians_ns_per_frame"].get<std::vector<double>>();
    REQUIRE(medians.size() == 5);
    CHECK(row["median_ns_per_frame"].get<double>() == median_of(medians));
    int samples = 0;
    for (int n : row["samples_per_process"].get<std::vector<int>>()) samples += n;
    CHECK(samples == row["repeats"].get<int>());
  }
  CHECK(j["replication"]["unit"] == "process");
  CHECK(j["replication"]["processes"] == 5);
  // The machine around the run, and the verdict on it, on the last line of the table.
  CHECK(j["machine"]["before"]["cpus"].get<int>() > 0);
  CHECK(j["machine"]["others_cpu_share"].get<double>() >= 0);
  CHECK(r.err.find("\nmachine: ") != std::string::npos);

  const RunResult capped =
      run_pxflow({"bench", "--backends", "ref-local", "--batch", "1", "--min-time", "2",
                  "--max-samples", "6", "--processes", "3", "--json", "-"});
  REQUIRE(capped.exit_code == 0);
  // A process ends at --max-samples, or at --min-time's share (2/3 s) of samples, whichever
  // comes first. Each sample is sized to a twentieth of that share from the checked run, so on a
  // steady machine the cap comes first; on a loaded one a sample can take four times its size
  // and the share come first, after kMinSamples (5). Never more than the cap, never fewer than 5.
  const json row = json::parse(capped.out)["rows"][0];
  INFO(row.dump());
  int samples = 0, short_of_cap = 0;
  for (int n : row["samples_per_process"].get<std::vector<int>>()) {
    CHECK(n <= 6);
    CHECK(n >= 5);
    samples += n;
    short_of_cap += n < 6;
  }
  CHECK(row["samples_per_process"].size() == 3);
  CHECK(row["repeats"] == samples);
  // measured_s is the processes' sum: each one short of the cap measured its whole share.
  CHECK(row["measured_s"].get<double>() >= short_of_cap * 2.0 / 3);
}

}  // namespace
}  // namespace pxflow::test
