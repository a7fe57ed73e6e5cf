// One vocabulary and one error style across the subcommands: option errors name the option, the
// bad value and what is allowed, and where to read more; `--json -` is standard output.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "bad_input.hpp"
#include "build_paths.hpp"
#include "run_program.hpp"
#include "sample_data.hpp"
#include "shared_options.hpp"

using pxflow::test::require_bad_input;
using pxflow::test::run_pxflow;

TEST_CASE("option errors in pxflow's style, not CLI11's sentences", "[cli][errors]") {
  require_bad_input(
      {"check", "--cases", "1e3"},
      "--cases: '1e3': must be a number from 1 to 100000000 (see pxflow check --help)");
  require_bad_input({"bench", "--min-time", "1000"},
                    "--min-time: '1000': must be a number from 0 to 600 (see pxflow bench --help)");
  require_bad_input({"check", "--seed", "1", "--seed", "2"},
                    "--seed: given 2 times: give it once (see pxflow check --help)");
  require_bad_input({"flow", "--backend"}, "--backend: needs a value (see pxflow flow --help)");
  require_bad_input({"report"}, "--out: missing: it is required (see pxflow report --help)");
  require_bad_input({"check", "--bogus"}, "unknown option --bogus (see pxflow check --help)");
  require_bad_input({"backends", "extra"},
                    "unexpected argument 'extra' (see pxflow backends --help)");
  require_bad_input({"-V"}, "unknown option -V (see pxflow --help)");
  require_bad_input({"--nope=3", "check"}, "unknown option --nope (see pxflow --help)");
  require_bad_input({}, "no command given");
  require_bad_input({"frobnicate"}, "unknown command 'frobnicate' (see pxflow --help)");
}

TEST_CASE("no CLI11 sentence reaches the user", "[cli][errors]") {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"check", "--cases", "0"},
                                               {"check", "--json"},
                                               {"flow", "a.png", "b.png", "c.png"},
                                               {"accuracy", "--cases", "0"},
                                               {"check", "--threads", "-1"}}) {
    const auto r = run_pxflow(args);
    INFO(r.err);
    CHECK(r.exit_code == 2);
    for (const char* clis : {"At Most", "not in range", "not expected", "required TEXT", "Value "})
      CHECK(r.err.find(clis) == std::string::npos);
    CHECK(r.err.find("--help)") != std::string::npos);
  }
}

TEST_CASE("pxflow backends --json lists every row with its family", "[cli][all-probes]") {
  const auto table = run_pxflow({"backends"});
  const auto r = run_pxflow({"backends", "--json", "-"});
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);  // the JSON alone on stdout
  REQUIRE(j["backends"].is_array());
  REQUIRE(j["backends"].size() >= 4);
  CHECK(j["backends"][0]["backend"] == "ref-original");
  CHECK(j["backends"][0]["family"] == "reference");
  CHECK(j["backends"][0]["available"] == true);
  for (const auto& row : j["backends"]) {
    const std::string name = row["backend"];
    // the table and the JSON agree on every row's status
    const auto at = table.out.find("\n" + name + " ");
    REQUIRE(at != std::string::npos);
    const bool listed_available =
        table.out.compare(table.out.find_first_not_of(' ', at + 1 + name.size()), 9, "available") ==
        0;
    CHECK(listed_available == row["available"].get<bool>());
    CHECK(row["available"].get<bool>() == row["reason"].get<std::string>().empty());
  }
}

TEST_CASE("a loop of symbolic links is named as such, not 'no such file'", "[cli][errors]") {
  pxflow::test::TempDir dir;
  const std::string a = dir.path("a.png"), b = dir.path("b.png");
  REQUIRE(::symlink(a.c_str(), b.c_str()) == 0);
  REQUIRE(::symlink(b.c_str(), a.c_str()) == 0);
  require_bad_input({"flow", a, b}, "a.png: a loop of symbolic links");
  require_bad_input({"flow", a}, "a.png: a loop of symbolic links");
  require_bad_input({"flow", dir.path("none.png"), b}, "none.png: no such file");
}

TEST_CASE("every JSON file pxflow writes starts with pxflow {version, commit}",
          "[cli][json][all-probes]") {
  pxflow::test::TempDir dir;
  const std::string a = pxflow::kSampleDataDir + std::string("/rubberwhale1.png");
  const std::string b = pxflow::kSampleDataDir + std::string("/rubberwhale2.png");
  const std::string check = "--generated-only";
  // Each writer, then the file it wrote (the report's results.json: report_results_match_schema).
  const std::vector<std::pair<std::vector<std::string>, std::string>> writers = {
      {{"flow", "--json", dir.path("flow.json"), "--jsonl", dir.path("flow.jsonl"), a, b},
       "flow.json"},
      {{}, "flow.jsonl"},
      {{"check", "--backends", "ref-local", check, "--shard", "1/2", "--json", dir.path("s1.json")},
       "s1.json"},
      {{"check", "--backends", "ref-local", check, "--shard", "2/2", "--json", dir.path("s2.json")},
       "s2.json"},
      {{"merge", "--json", dir.path("merged.json"), dir.path("s1.json"), dir.path("s2.json")},
       "merged.json"},
      {{"bench", "--backend", "ref-local", "--batch", "1", "--min-time", "0", "--json",
        dir.path("bench.json")},
       "bench.json"},
      {{"backends", "--json", dir.path("backends.json")}, "backends.json"},
      // The families' commands, where this build has them.
      {{"gap8", "--cores", "1", "--variant", "local", "--json", dir.path("gap8.json")},
       "gap8.json"},
      {{"vectors", "--out", dir.path("vec"), "--cases", "2"}, "vec/manifest.json"},
      {{"accuracy", "--cases", "4", "--video-pairs", "0", "--json", dir.path("accuracy.json")},
       "accuracy.json"},
  };
  std::string commit;
  for (const auto& [args, file] : writers) {
    CAPTURE(file);
    if (!args.empty()) {
      const auto r = run_pxflow(args);
      INFO(r.err);
      if (r.exit_code == 2 && r.err.find("unknown") != std::string::npos) continue;  // not built
      REQUIRE(r.exit_code == 0);
    }
    const auto j = nlohmann::ordered_json::parse(pxflow::test::slurp(dir.path(file)));
    REQUIRE(j.begin().key() == "pxflow");
    CHECK(j["pxflow"]["version"].get<std::string>().rfind("0.", 0) == 0);
    const std::string c = j["pxflow"]["commit"];
    CHECK(!c.empty());
    CHECK((commit.empty() || c == commit));  // one build wrote them all
    commit = c;
  }
  // accuracy's rows are the report's (accuracy_rows_json): pxflow, LK and DIS on 4 pairs.
  const auto acc = nlohmann::json::parse(pxflow::test::slurp(dir.path("accuracy.json")));
  CHECK(acc["command"].get<std::string>().rfind("pxflow accuracy --cases 4", 0) == 0);
  REQUIRE(acc["rows"].size() >= 3);
  CHECK(acc["rows"][0]["frames"] == 4);
  // Whole counts are integers in gap8's JSON, where it was written.
  if (std::ifstream(dir.path("gap8.json"))) {
    const auto g = nlohmann::json::parse(pxflow::test::slurp(dir.path("gap8.json")));
    const auto& one = g["variants"]["local"]["1"];
    for (const char* key : {"cycles", "instructions", "interpolations", "sad_ops"})
      CHECK(one[key].is_number_integer());
    CHECK(one["phases"]["flow"].is_number_integer());
  }
}

TEST_CASE("a count of one is singular: 1 pair, 1 point, 1 case", "[cli]") {
  pxflow::test::TempDir dir;
  const std::string data = pxflow::kSampleDataDir;
  dir.write("list.txt", data + "/rubberwhale1.png " + data + "/rubberwhale2.png\n");
  const auto flow = run_pxflow({"flow", "--pairs", dir.path("list.txt")});
  INFO(flow.err);
  CHECK(flow.out.find(": 1 pair (2 frames) in ") != std::string::npos);
  const auto bench =
      run_pxflow({"bench", "--backend", "ref-local", "--batch", "1", "--min-time", "0"});
  CHECK(bench.out.rfind("pxflow bench: 1 point; ", 0) == 0);
  // The generated corpus has 65 cases for ref-local (16 and 49 limit cases): its last shard of
  // 65 has one.
  const auto check =
      run_pxflow({"check", "--backends", "ref-local", "--generated-only", "--shard", "65/65"});
  INFO(check.out);
  CHECK(check.out.find("shard 65/65: 1 case, ") != std::string::npos);
  for (const auto* r : {&flow, &bench, &check})
    for (const char* plural : {" 1 pairs", " 1 points", " 1 cases", " 1 threads", " 1 frames"})
      CHECK(r->out.find(plural) == std::string::npos);
}

// One vocabulary: the README's table is the code's table (hosts/cli/shared_options.cpp), and
// every command that takes a shared option shows its one help text.
TEST_CASE("readme_shared_options: the README's table is the code's, every --help says the same",
          "[cli][vocabulary]") {
  const std::string readme =
      pxflow::test::slurp(std::string(build_paths::source_dir) + "/README.md");
  const std::string begin = "<!-- shared options: ", end = "<!-- end of shared options -->";
  const auto from = readme.find('\n', readme.find(begin)) + 1;
  REQUIRE(readme.find(begin) != std::string::npos);
  REQUIRE(readme.find(end) != std::string::npos);
  CHECK(readme.substr(from, readme.find(end) - from) == pxflow::cli::shared_options_markdown());
  int declared = 0;
  for (const char* command :
       {"flow", "check", "bench", "report", "accuracy", "backends", "gap8", "vectors"}) {
    const auto help = run_pxflow({command, "--help"});
    if (help.exit_code == 2) continue;  // a family's command this build lacks
    REQUIRE(help.exit_code == 0);
    for (const auto& o : pxflow::cli::shared_options()) {
      if (help.out.find("  " + o.name + " ") == std::string::npos) continue;
      CAPTURE(command, o.name);
      CHECK(help.out.find(o.meaning) != std::string::npos);
      CHECK(help.out.find("Default: " + o.defaults) != std::string::npos);
      ++declared;
    }
  }
  CHECK(declared >= 25);  // each shared option in at least two commands
  // accuracy takes --backend, so it takes --device too.
  CHECK(run_pxflow({"accuracy", "--help"}).out.find("  --device D") != std::string::npos);
  // gyro_comp is a key, but only 0 is taken (pxflow has no gyro rates).
  CHECK(run_pxflow({"flow", "--help"}).out.find("gyro_comp (0 only)") != std::string::npos);
}

TEST_CASE("a misspelt option is named, with the nearest one", "[cli][errors][vocabulary]") {
  // CLI11 alone said "unexpected argument '5'": the misspelt name ate no value.
  require_bad_input({"check", "--case", "5"},
                    "unknown option --case (did you mean --cases?) (see pxflow check --help)");
  require_bad_input({"accuracy", "--thread", "2"},
                    "unknown option --thread (did you mean --threads?)");
  require_bad_input({"flow", "--bakend", "ref-local", "a.png", "b.png"},
                    "unknown option --bakend (did you mean --backend?)");
  require_bad_input({"bench", "--batch=1", "--min-tim", "0"},
                    "unknown option --min-tim (did you mean --min-time?)");
  require_bad_input({"--device-timout", "3", "check"},
                    "unknown option --device-timout (did you mean --device-timeout?)");
  // A name near none: no guess.
  const auto far = run_pxflow({"check", "--bogus", "1"});
  CHECK(far.err == "pxflow: error: unknown option --bogus (see pxflow check --help)\n");
  // Old spellings whose meaning differed name the new one.
  require_bad_input({"bench", "--size", "64x64"}, "--size: renamed: give --sizes WxH[,WxH...]");
  require_bad_input({"bench", "--sweep-threads", "2"},
                    "--sweep-threads: renamed: give --threads N");
}

TEST_CASE("bench --threads N is one count, --thread-sweep LIST a sweep", "[cli][vocabulary]") {
  auto threads_of_rows = [](const std::vector<std::string>& sweep) {
    std::vector<std::string> args = {"bench",      "--backend", "ref-local", "--batch", "1",
                                     "--min-time", "0",         "--json",    "-"};
    args.insert(args.end(), sweep.begin(), sweep.end());
    const auto r = run_pxflow(args);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    std::vector<int> threads;
    const auto j = nlohmann::json::parse(r.out);
    for (const auto& row : j["rows"]) threads.push_back(row["threads"]);
    return threads;
  };
  CHECK(threads_of_rows({"--threads", "1"}) == std::vector<int>{1});
  CHECK(threads_of_rows({"--thread-sweep", "1,2"}) == std::vector<int>{1, 2});
  require_bad_input({"bench", "--threads", "1", "--thread-sweep", "1,2"},
                    "--threads 1: given with --thread-sweep 1,2: give one of them");
}

TEST_CASE("progress lines on the long runs: accuracy and vectors take --progress",
          "[cli][vocabulary]") {
  pxflow::test::TempDir dir;
  const auto accuracy =
      run_pxflow({"accuracy", "--cases", "2", "--video-pairs", "0", "--progress"});
  INFO(accuracy.err);
  CHECK(accuracy.exit_code == 0);
  CHECK(accuracy.err.find("accuracy: synthetic, camera 64x64") != std::string::npos);
  const auto vectors =
      run_pxflow({"vectors", "--out", dir.path("v"), "--cases", "2", "--progress"});
  if (vectors.exit_code == 2 && vectors.err.find("unknown command") != std::string::npos) return;
  INFO(vectors.err);
  CHECK(vectors.exit_code == 0);
  CHECK(vectors.err.find("vectors: 0 of 2 pairs made") != std::string::npos);
}
