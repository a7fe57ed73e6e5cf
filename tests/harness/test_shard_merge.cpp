// Campaigns split over a CI matrix: `pxflow check --shard K/M` and `pxflow merge`. M shards
// merged must be the unsharded run, failures included (test-bitflip fails on purpose,
// test-unavailable cannot run, test-small-only is n/a above 64x64); merge refuses files that are
// not one campaign's shards and calls a campaign with shards missing incomplete.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "build_paths.hpp"
#include "json_file.hpp"
#include "run_program.hpp"

using nlohmann::json;
using pxflow::test::last_line;
using pxflow::test::read_json;
using pxflow::test::run_program;
using pxflow::test::RunResult;
using pxflow::test::slurp;
using pxflow::test::TempDir;

namespace {

RunResult pxflow_run(const std::vector<std::string>& args) {
  return run_program(build_paths::pxflow_with_test_rows, args);
}

// "<stem><k>.json", appended piece by piece: GCC 12 warns on "s" + std::to_string(k) + ...
// (-Wrestrict, a false positive, GCC bug 105329).
std::string numbered_json(const char* stem, int k) {
  std::string name = stem;
  name += std::to_string(k);
  name += ".json";
  return name;
}

// Runs `check` with `args` once whole and once as `m` shards, merges the shards (given in
// reverse order: merge sorts them), and returns {whole, merged}.
std::pair<json, json> whole_and_merged(const TempDir& dir, std::vector<std::string> args, int m,
                                       int expected_exit) {
  args.insert(args.begin(), "check");
  auto with = [&](std::vector<std::string> extra) {
    auto a = args;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const RunResult whole = pxflow_run(with({"--json", dir.path("whole.json")}));
  INFO(whole.out << whole.err);
  REQUIRE(whole.exit_code == expected_exit);
  std::vector<std::string> merge = {"merge", "--json", dir.path("merged.json")};
  for (int k = m; k >= 1; --k) {
    const std::string file = dir.path(numbered_json("shard", k));
    const RunResult r =
        pxflow_run(with({"--shard", std::to_string(k) + "/" + std::to_string(m), "--json", file}));
    INFO(r.out << r.err);
    REQUIRE((r.exit_code == 0 || r.exit_code == 1));
    merge.push_back(file);
  }
  const RunResult merged = pxflow_run(merge);
  INFO(merged.out << merged.err);
  CHECK(merged.exit_code == expected_exit);
  CHECK(last_line(merged.out) == last_line(whole.out));  // "N passed, M failed, K skipped"
  return {read_json(dir.path("whole.json")), read_json(dir.path("merged.json"))};
}

void require_same_results(const json& whole, const json& merged) {
  for (const char* key : {"verdict", "seed", "cases", "pairs", "passed", "failed", "skipped",
                          "not_applicable", "compared", "campaign", "pxflow"})
    CHECK(whole[key] == merged[key]);
  REQUIRE(whole["backends"].size() == merged["backends"].size());
  for (std::size_t b = 0; b < whole["backends"].size(); ++b) {
    const json &w = whole["backends"][b], &g = merged["backends"][b];
    INFO(w["backend"]);
    for (const char* key : {"backend", "state", "reason", "implementation", "device", "passed",
                            "failed", "not_applicable", "pairs", "failures", "limits"})
      CHECK(w[key] == g[key]);
  }
}

}  // namespace

TEST_CASE("shard: a fuzz campaign in 3 shards merges into the unsharded run, failures included",
          "[shard]") {
  TempDir dir;
  // 1000 pairs: 4 batches (256, 256, 256, 232), so the shards hold 1, 1 and 2 of them.
  const auto [whole, merged] = whole_and_merged(
      dir, {"--backends", "ref-original,ref-local,test-bitflip", "--cases", "1000", "--seed", "3"},
      3, 1);
  require_same_results(whole, merged);
  CHECK(whole["verdict"] == "failed");
  CHECK(whole["campaign"]["kind"] == "fuzz");
  CHECK(whole["campaign"]["cases"] == 4);
  const json& bitflip = whole["backends"][2];
  CHECK(bitflip["failed"] == 4);
  CHECK(bitflip["failures"].size() > 4);  // mismatch lines of every batch, not just one
  // The shards are disjoint, contiguous and together the whole campaign.
  long next = 0, pairs = 0;
  for (int k = 1; k <= 3; ++k) {
    const json s = read_json(dir.path(numbered_json("shard", k)));
    CHECK(s["shard"]["index"] == k);
    CHECK(s["shard"]["first_case"] == next);
    next = s["shard"]["end_case"];
    pairs += s["pairs"].get<long>();
  }
  CHECK(next == 4);
  CHECK(pairs == 1000);
  REQUIRE(merged["merged_from"].size() == 3);
  CHECK(merged["merged_from"][0]["index"] == 1);  // sorted, though given 3, 2, 1
  CHECK(merged["missing_shards"].empty());
}

TEST_CASE("shard: the fixed corpus splits too, with skips, n/a and a required backend", "[shard]") {
  TempDir dir;
  const auto [whole, merged] =
      whole_and_merged(dir,
                       {"--backends", "ref-original,test-bitflip,test-small-only,test-unavailable",
                        "--require", "test-unavailable", "--generated-only", "--seed", "5"},
                       5, 1);
  require_same_results(whole, merged);
  CHECK(whole["campaign"]["kind"] == "fixed-corpus");
  // 16 generated cases and the limit cases (check_limits.hpp) of the three rows that opened:
  // SPEC's corners and each row's own edges and radius sweep.
  CHECK(whole["campaign"]["cases"] == 94);
  CHECK(whole["backends"][2]["not_applicable"] == 11);  // test-small-only above 64x64
  CHECK(whole["backends"][3]["failures"].size() == 1);  // "required but cannot run", once
  CHECK(whole["backends"][3]["failed"] == 0);           // no case ran ...
  CHECK(whole["failed"].get<long>() >= 65);             // ... but all its 65 count as failed
  CHECK(merged["merged_from"].size() == 5);

  // Without the requirement the unavailable backend is skipped in every shard: skipped merged.
  TempDir dir2;
  const auto [w2, m2] = whole_and_merged(
      dir2, {"--backends", "ref-local,test-unavailable", "--generated-only"}, 2, 0);
  require_same_results(w2, m2);
  CHECK(w2["skipped"] == 65);  // 16 generated cases and its 49 limit cases
  CHECK(m2["backends"][1]["state"] == "skipped");
}

TEST_CASE("shard: a shard whose cases are all n/a exits 0, merge judges the campaign", "[shard]") {
  TempDir dir;
  // The generated corpus is 4 cases per setting, then 46 limit cases: of 12 shards of these 62
  // cases, shard 3/12 holds cases 10..14, 320x240 and 640x480 ones, n/a for test-small-only.
  std::vector<std::string> merge = {"merge", "--json", dir.path("m.json")};
  for (int k = 1; k <= 12; ++k) {
    const std::string file = dir.path(numbered_json("s", k));
    const RunResult r = pxflow_run({"check", "--backend", "test-small-only", "--generated-only",
                                    "--shard", std::to_string(k) + "/12", "--json", file});
    INFO(r.out);
    CHECK(r.exit_code == 0);
    const json j = read_json(file);
    CHECK(j["verdict"] == (k != 3 ? "passed" : "nothing-checked"));
    if (k == 3)
      CHECK(r.out.find("compared nothing: exit 0, pxflow merge judges") != std::string::npos);
    merge.push_back(file);
  }
  const RunResult m = pxflow_run(merge);
  CHECK(m.exit_code == 0);
  CHECK(read_json(dir.path("m.json"))["passed"] == 51);
  // A campaign in which no shard compared anything tested nothing: merge exits 1.
  std::vector<std::string> skipped = {"merge", "--json", "-"};
  for (int k = 1; k <= 2; ++k) {
    const std::string file = dir.path(numbered_json("u", k));
    CHECK(pxflow_run({"check", "--backend", "test-unavailable", "--generated-only", "--shard",
                      std::to_string(k) + "/2", "--json", file})
              .exit_code == 0);
    skipped.push_back(file);
  }
  const RunResult none = pxflow_run(skipped);
  CHECK(none.exit_code == 1);
  CHECK(json::parse(none.out)["verdict"] == "nothing-checked");
  CHECK(none.err.find("nothing was checked") != std::string::npos);
}

TEST_CASE("merge: mismatched, repeated or merged files are refused with one line", "[shard]") {
  TempDir dir;
  auto shard = [&](const std::string& name, std::vector<std::string> args,
                   const std::string& backends = "ref-local") {
    args.insert(args.begin(), {"check", "--backends", backends, "--generated-only"});
    args.insert(args.end(), {"--json", dir.path(name)});
    const RunResult r = pxflow_run(args);
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
  };
  shard("a1.json", {"--shard", "1/2"});
  shard("a2.json", {"--shard", "2/2"});
  shard("seed2.json", {"--shard", "2/2", "--seed", "2"});
  shard("of3.json", {"--shard", "2/3"});
  shard("more.json", {"--shard", "2/2"}, "ref-local,ref-global");
  // A shard of another build: the same file with another commit.
  json other = read_json(dir.path("a2.json"));
  other["pxflow"]["commit"] = "0123456789ab";
  dir.write("commit.json", other.dump());
  json inputs = read_json(dir.path("a2.json"));
  inputs["campaign"]["corpus_fingerprint"] = "0000000000000000";
  dir.write("inputs.json", inputs.dump());
  dir.write("broken.json", "{\"seed\": 1");
  dir.write("bench.json", "{\"rows\": []}");

  const std::string out = dir.path("out.json");
  auto refused = [&](std::vector<std::string> files, const std::string& says) {
    files.insert(files.begin(), {"merge", "--json", out});
    const RunResult r = pxflow_run(files);
    INFO(r.out << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err_lines() == 1);
    CHECK(r.err.find(says) != std::string::npos);
    CHECK(r.err.find("(see pxflow merge --help)") != std::string::npos);
    CHECK(slurp(out).empty());  // nothing written
  };
  refused({dir.path("a1.json"), dir.path("seed2.json")}, "seed 2 (");
  refused({dir.path("a1.json"), dir.path("of3.json")}, "shard count 3 (");
  refused({dir.path("a1.json"), dir.path("more.json")}, "backends ref-local,ref-global (");
  refused({dir.path("a1.json"), dir.path("commit.json")}, "pxflow commit 0123456789ab (");
  refused({dir.path("a1.json"), dir.path("inputs.json")}, "corpus fingerprint 0000000000000000");
  refused({dir.path("a1.json"), dir.path("a2.json"), dir.path("a2.json")}, "shard 2/2 again");
  refused({dir.path("broken.json")}, "not valid JSON");
  refused({dir.path("bench.json")}, "not a complete check file");
  refused({dir.path("nope.json")}, "nope.json: no such file");

  // A merged file is no shard; OUT may not be one of the inputs.
  REQUIRE(
      pxflow_run({"merge", "--json", dir.path("m.json"), dir.path("a1.json"), dir.path("a2.json")})
          .exit_code == 0);
  refused({dir.path("m.json")}, "a merged file");
  const RunResult self = pxflow_run(
      {"merge", "--json", dir.path("a1.json"), dir.path("a1.json"), dir.path("a2.json")});
  CHECK(self.exit_code == 2);
  CHECK(self.err.find("is an input") != std::string::npos);
}

TEST_CASE("merge: shards missing make an incomplete verdict, exit 1, and - writes stdout",
          "[shard]") {
  TempDir dir;
  for (const char* k : {"1", "3"}) {
    const RunResult r =
        pxflow_run({"check", "--backends", "ref-local", "--generated-only", "--shard",
                    std::string(k) + "/3", "--json", dir.path(std::string("s") + k + ".json")});
    REQUIRE(r.exit_code == 0);
  }
  const RunResult r =
      pxflow_run({"merge", "--json", "-", dir.path("s3.json"), dir.path("s1.json")});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  const json m = json::parse(r.out);  // stdout is the JSON alone; the summary went to stderr
  CHECK(m["verdict"] == "incomplete");
  CHECK(m["missing_shards"] == json::array({2}));
  CHECK(m["backends"][0]["state"] == "incomplete");
  CHECK(m["cases"].get<long>() < m["campaign"]["cases"].get<long>());
  CHECK(r.err.find("incomplete: shard 2/3 not given") != std::string::npos);
}

TEST_CASE("merge: the merged file is a check file pxflow report accepts", "[shard]") {
  TempDir dir;
  for (const char* k : {"1", "2"})
    REQUIRE(
        pxflow_run({"check", "--backends", "ref-original,ref-local", "--generated-only", "--shard",
                    std::string(k) + "/2", "--json", dir.path(std::string("s") + k + ".json")})
            .exit_code == 0);
  REQUIRE(
      pxflow_run({"merge", "--json", dir.path("m.json"), dir.path("s1.json"), dir.path("s2.json")})
          .exit_code == 0);
  REQUIRE(pxflow_run({"bench", "--backends", "ref-original", "--batch", "1", "--min-time", "0",
                      "--json", dir.path("b.json")})
              .exit_code == 0);
  const RunResult r = pxflow_run({"report", "--out", dir.path("report"), "--check-json",
                                  dir.path("m.json"), "--bench-json", dir.path("b.json"),
                                  "--no-accuracy", "--backends", "ref-original"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  // 16 generated and 49 limit cases.
  CHECK(slurp(dir.path("report/report.md")).find("65 cases (373 frame pairs)") !=
        std::string::npos);
}

TEST_CASE("report: a check's failure lines and an incomplete merge, named, and not a pass",
          "[shard][report]") {
  TempDir dir;
  REQUIRE(pxflow_run({"bench", "--backends", "ref-original", "--batch", "1", "--min-time", "0",
                      "--json", dir.path("b.json")})
              .exit_code == 0);
  auto report = [&](const std::string& check, const std::string& out) {
    const RunResult r = pxflow_run({"report", "--out", dir.path(out), "--check-json",
                                    dir.path(check), "--bench-json", dir.path("b.json"),
                                    "--no-accuracy", "--backends", "ref-original"});
    INFO(r.out << r.err);
    CHECK(r.exit_code == 1);
    return slurp(dir.path(out + "/report.md"));
  };
  // test-bitflip fails on purpose: its lines, as check printed them, are in Conformance.
  const RunResult failed = pxflow_run({"check", "--backends", "ref-original,test-bitflip",
                                       "--generated-only", "--json", dir.path("f.json")});
  REQUIRE(failed.exit_code == 1);
  const std::string line = read_json(dir.path("f.json"))["backends"][1]["failures"][0];
  REQUIRE(line.rfind("FAIL test-bitflip case=", 0) == 0);
  const std::string md = report("f.json", "rf");
  const auto conformance = md.find("## Conformance");
  REQUIRE(conformance != std::string::npos);
  CHECK(md.find("- `" + line + "`", conformance) < md.find("\n## ", conformance + 1));

  // A merge of shard 1/2 alone: the report says which shard is missing and is not a pass.
  REQUIRE(pxflow_run({"check", "--backends", "ref-original,ref-local", "--generated-only",
                      "--shard", "1/2", "--json", dir.path("s1.json")})
              .exit_code == 0);
  REQUIRE(pxflow_run({"merge", "--json", dir.path("m.json"), dir.path("s1.json")}).exit_code == 1);
  CHECK(
      report("m.json", "rm").find("Incomplete: shard 2/2 not given: its cases were not checked") !=
      std::string::npos);
}

TEST_CASE("check --shard, --backend and --json -: the options and their errors",
          "[shard][all-probes]") {
  for (const char* bad : {"0/2", "3/2", "2", "1/0", "a/b", "1/2/3", "+1/2", ""}) {
    const RunResult r = pxflow_run({"check", "--generated-only", "--shard", bad});
    INFO(bad << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err_lines() == 1);
    CHECK(r.err.find("K/M with 1 <= K <= M") != std::string::npos);
  }
  // 300 pairs are 2 batches: a third shard would run nothing.
  RunResult r = pxflow_run({"check", "--cases", "300", "--shard", "3/3"});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("the campaign has 2 cases") != std::string::npos);

  r = pxflow_run({"check", "--backend", "ref-local,ref-global"});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--backend: 'ref-local,ref-global': one backend name") != std::string::npos);
  r = pxflow_run({"check", "--backend", "ref-local", "--backends", "ref-global"});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("give one of them") != std::string::npos);
  r = pxflow_run({"check", "--backends", ","});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("(see pxflow check --help)") != std::string::npos);

  // --backend NAME, the JSON on stdout, the mismatch lines and the summary on stderr.
  r = pxflow_run(
      {"check", "--backend", "test-bitflip", "--generated-only", "--json", "-", "--no-repro"});
  CHECK(r.exit_code == 1);
  const json j = json::parse(r.out);
  CHECK(j["backends"].size() == 1);
  CHECK(j["backends"][0]["backend"] == "test-bitflip");
  CHECK(j["command"] ==
        "pxflow check --backend test-bitflip --seed 1 --generated-only --json - --no-repro");
  CHECK(j["shard"] == json({{"index", 1}, {"count", 1}, {"first_case", 0}, {"end_case", 65}}));
  CHECK(r.err.find("FAIL test-bitflip case=") != std::string::npos);
  CHECK(last_line(r.err).find(" failed, 0 skipped") != std::string::npos);
}

TEST_CASE("check: progress counts the fixed corpus against its total, the summary its time",
          "[shard]") {
  const RunResult r =
      pxflow_run({"check", "--backend", "ref-local", "--generated-only", "--progress"});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  // 16 generated cases of 300 pairs, 49 limit cases of 65 (check_limits.hpp: SPEC's corners,
  // ref-local's strips and its radius sweep S = 1..31).
  CHECK(r.err.find("check: 1 of 65 cases, 96 of 373 pairs") != std::string::npos);
  CHECK(r.out.find("65 cases, 373 pairs in ") != std::string::npos);
  const RunResult s = pxflow_run(
      {"check", "--backend", "ref-local", "--cases", "600", "--shard", "2/2", "--progress"});
  CHECK(s.exit_code == 0);
  CHECK(s.err.find("check: 1 of 2 cases, 256 of 344 pairs") != std::string::npos);
  CHECK(s.out.find("shard 2/2: 2 cases, 344 pairs (cases 1..2 of the campaign's 3)") !=
        std::string::npos);
}

#ifdef PXFLOW_TEST_HAS_CPU_ROWS
TEST_CASE("check names the implementation the cpu row dispatched to", "[shard]") {
  const RunResult r = pxflow_run({"check", "--backend", "cpu", "--generated-only", "--json", "-"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const json b = json::parse(r.out)["backends"][0];
  const std::string isa = b["implementation"];
  CHECK(!isa.empty());
  CHECK(isa != "cpu");           // one of the ISA rows: swar, sse2, ..., avx512bw
  CHECK(b["device"] == "host");  // as flow --json says it
  CHECK(r.err.find("passed          65     373     0") != std::string::npos);  // 49 limit cases
  CHECK(r.err.find("s  " + isa + "\n") != std::string::npos);  // the summary's "runs as" column
}
#endif
