// pxflow report names every machine (issue 36): each bench file keeps its own provenance, never
// the local machine's; series and sections of a report of several machines name theirs; a bench
// of its own points (bench --batch 1,16) is shown point by point; a bench a signal stopped is
// read and said to be incomplete. The bench files are one real bench, its provenance rewritten.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "results_files.hpp"
#include "run_program.hpp"
#include "svg_chart.hpp"

namespace pxflow::test {
namespace {

using nlohmann::json;

// A real bench of the reference rows at batch 1 and 16 (a custom sweep), as `name` in `dir`.
json bench_file(const TempDir& dir, const std::string& name) {
  const RunResult r = run_pxflow({"bench", "--backends", "ref-original,ref-local", "--batch",
                                  "1,16", "--min-time", "0", "--json", dir.path(name)});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return json::parse(slurp(dir.path(name)));
}

// `bench` as if measured on another machine, written as `name`.
void write_as_machine(const TempDir& dir, json bench, const std::string& name,
                      const std::string& host, const std::string& cpu) {
  json& m = bench["provenance"]["machine"];
  m["host"] = host, m["cpu"] = cpu, m["cores"] = 96, m["os"] = "Far OS " + host;
  dir.write(name, bench.dump());
}

// Every cell and text of the sections whose key starts with `prefix`, one string.
std::string sections_text(const json& results, const std::string& prefix) {
  std::string all;
  for (const auto& s : results["sections"]) {
    if (s["key"].get<std::string>().rfind(prefix, 0) != 0) continue;
    all += s["title"].get<std::string>() + "\n" + s["text"].get<std::string>() + "\n";
    for (const auto& row : s["rows"])
      for (const auto& cell : row) all += cell.get<std::string>() + "\n";
  }
  return all;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

RunResult report(const TempDir& dir, const std::string& out, std::vector<std::string> benches,
                 bool check_here = false) {
  std::vector<std::string> args{"report",        "--out",      dir.path(out),
                                "--no-accuracy", "--backends", "ref-original,ref-local"};
  if (!check_here) args.insert(args.end(), {"--check-json", dir.path("c.json")});
  args.push_back("--bench-json");
  for (const auto& b : benches) args.push_back(dir.path(b));
  return run_pxflow(args);
}

}  // namespace

TEST_CASE("report --bench-json A B of two machines names both, from the files, never this one",
          "[report][machines]") {
  TempDir dir;
  make_small_results(dir);
  const json bench = bench_file(dir, "real.json");
  write_as_machine(dir, bench, "a.json", "far-host-a", "Far CPU A 9000");
  write_as_machine(dir, bench, "b.json", "far-host-b", "Far CPU B 7000");
  const RunResult r = report(dir, "r", {"a.json", "b.json"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  // results.json: each file's provenance, as the file records it; nothing measured here.
  const json& files = j["provenance"]["bench_files"];
  REQUIRE(files.size() == 2);
  CHECK(files[0]["label"] == "A");
  CHECK(files[0]["path"] == dir.path("a.json"));
  CHECK(files[0]["machine"]["host"] == "far-host-a");
  CHECK(files[1]["machine"]["cpu"] == "Far CPU B 7000");
  CHECK(files[1]["build"]["commit"] == bench["provenance"]["build"]["commit"]);
  CHECK(j["provenance"]["measured_here"].empty());
  // A block per file, in the first screen, naming its path and machine.
  for (const auto& [key, host, cpu] :
       {std::tuple{"provenance-a", "far-host-a", "Far CPU A 9000"},
        std::tuple{"provenance-b", "far-host-b", "Far CPU B 7000"}}) {
    INFO(key);
    const json* block = section(j, key);
    REQUIRE(block);
    const std::string text = sections_text(j, key);
    CHECK(contains(text, host));
    CHECK(contains(text, cpu));
    CHECK(contains((*block)["title"].get<std::string>(), key[11] == 'a' ? "a.json" : "b.json"));
  }
  // The local machine names none of the files' figures: not in any provenance block, and the
  // report measured nothing here, so not on the page at all.
  const std::string local_cpu = j["provenance"]["machine"]["cpu"];
  const std::string local_host = j["provenance"]["machine"]["host"];
  const std::string md = slurp(dir.path("r/report.md"));
  const std::string html = slurp(dir.path("r/report.html"));
  if (local_cpu != "unknown") {
    CHECK(!contains(sections_text(j, ""), local_cpu));
    CHECK(!contains(md, local_cpu));
  }
  CHECK(!contains(sections_text(j, "provenance"), "host " + local_host + ","));
  for (const char* name : {"far-host-a", "Far CPU A 9000", "far-host-b", "Far CPU B 7000"}) {
    CHECK(contains(md, name));
    CHECK(contains(html, name));
  }
  // Two machines: the bench's sections say whose they are, and every series of the chart
  // across the files names its machine.
  const json* throughput = section(j, "throughput");
  REQUIRE(throughput);
  CHECK(contains((*throughput)["title"].get<std::string>(), "A: far-host-a (Far CPU A 9000)"));
  REQUIRE(!(*throughput)["charts"].empty());
  for (const auto& bar : (*throughput)["charts"][0]["bars"])
    CHECK(contains(bar["label"].get<std::string>(), "far-host-a"));
  const json* comparison = section(j, "comparison");
  REQUIRE(comparison);
  REQUIRE((*comparison)["charts"].size() == 1);
  int a = 0, b = 0;
  for (const auto& s : (*comparison)["charts"][0]["series"]) {
    const std::string name = s["name"];
    a += name.rfind("A ", 0) == 0 && contains(name, "far-host-a (Far CPU A 9000)");
    b += name.rfind("B ", 0) == 0 && contains(name, "far-host-b (Far CPU B 7000)");
  }
  CHECK(a == 2);
  CHECK(b == 2);
}

TEST_CASE(
    "report of one file from another machine names that machine and no other but a check run here "
    "makes two",
    "[report][machines]") {
  TempDir dir;
  make_small_results(dir);
  write_as_machine(dir, bench_file(dir, "real.json"), "far.json", "far-host", "Far CPU 1");
  const RunResult r = report(dir, "one", {"far.json"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("one/results.json")));
  REQUIRE(j["provenance"]["bench_files"].size() == 1);
  CHECK(j["provenance"]["bench_files"][0]["machine"]["host"] == "far-host");
  CHECK(contains(sections_text(j, "provenance-a"), "Far CPU 1, 96 cores"));
  // The local CPU is not the bench's: with nothing measured here it is not shown.
  const json* own = section(j, "provenance");
  REQUIRE(own);
  for (const auto& row : (*own)["rows"]) CHECK(row[0] != "CPU");
  CHECK(contains(sections_text(j, "backends"), "far-host (Far CPU 1)"));
  const json* throughput = section(j, "throughput");
  REQUIRE(throughput);
  CHECK(!contains((*throughput)["title"].get<std::string>(),
                  "far-host"));  // one machine: no label needed

  // The check run here: this machine measured it, and the bench's sections name theirs.
  const RunResult here = report(dir, "two", {"far.json"}, true);
  INFO(here.out << here.err);
  REQUIRE(here.exit_code == 0);
  const json k = json::parse(slurp(dir.path("two/results.json")));
  CHECK(k["provenance"]["measured_here"] == json::array({"check"}));
  CHECK(contains(sections_text(k, "provenance"), "check (on this machine)"));
  REQUIRE(section(k, "throughput"));
  CHECK(
      contains((*section(k, "throughput"))["title"].get<std::string>(), "A: far-host (Far CPU 1)"));
}

TEST_CASE("report: a bench of its own points (--batch 1,16) shows every point", "[report]") {
  TempDir dir;
  make_small_results(dir);
  json bench = bench_file(dir, "b.json");
  const RunResult r = report(dir, "r", {"b.json"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  const json* points = section(j, "scaling-custom");
  REQUIRE(points);
  CHECK((*points)["header"] == json::array({"backend", "batch 1", "batch 16", "note"}));
  REQUIRE((*points)["rows"].size() == 2);
  for (const auto& row : (*points)["rows"]) {
    CHECK(row[1] != "-");  // a figure at batch 1
    CHECK(row[2] != "-");  // and at batch 16
  }
  REQUIRE((*points)["charts"].size() == 1);
  for (const auto& s : (*points)["charts"][0]["series"]) CHECK(s["points"].size() == 2);
  CHECK(!section(j, "scaling-batch"));  // no default sweep ran: none is said to be left out
  CHECK(!contains(slurp(dir.path("r/report.md")), "left this sweep out"));

  // Two parameters varied (batch and, planted, the search radius): a row per point and backend.
  json rows = json::array();
  for (const auto& row : bench["rows"]) {
    rows.push_back(row);
    json wide = row;
    wide["search_radius"] = 2;
    rows.push_back(wide);
  }
  bench["rows"] = rows;
  dir.write("b.json", bench.dump());
  REQUIRE(report(dir, "r2", {"b.json"}).exit_code == 0);
  const json k = json::parse(slurp(dir.path("r2/results.json")));
  const json* table = section(k, "scaling-custom");
  REQUIRE(table);
  CHECK((*table)["rows"].size() == 8);  // 2 backends x (batch 1, 16) x (S=2, 4)
  CHECK((*table)["header"][1] == "point");
  CHECK((*table)["charts"].empty());
  CHECK(contains((*table)["text"].get<std::string>(), "over batch, radius"));
}

TEST_CASE("report: a bench a signal stopped is read and said to be incomplete", "[report]") {
  TempDir dir;
  make_small_results(dir);
  json bench = json::parse(slurp(dir.path("b.json")));
  bench["complete"] = false, bench["points_done"] = 1, bench["points_total"] = 3;
  dir.write("b.json", bench.dump());
  const RunResult r = report(dir, "r", {"b.json"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  const std::string said = "incomplete: a signal stopped this bench after 1 of 3 points";
  CHECK(contains(sections_text(j, "provenance-a"), said));
  CHECK(j["provenance"]["bench_files"][0]["complete"] == false);
  CHECK(j["provenance"]["bench_files"][0]["points_total"] == 3);
  CHECK(contains(slurp(dir.path("r/report.md")), said));
}

TEST_CASE("chart: a long series name widens the legend, and the chart scales to the page",
          "[report]") {
  Chart c;
  c.title = "t";
  c.x = {"x", false}, c.y = {"y", false};
  c.series.push_back({std::string(100, 'n'), {{1, 1}, {2, 2}}, backend_style(0)});
  const std::string svg = svg_chart(c);
  const auto at = svg.find("width='") + 7;
  CHECK(std::stoi(svg.substr(at)) > 70 + 540 + 100 * 6);
  CHECK(contains(svg, "viewBox='0 0 "));
}

}  // namespace pxflow::test
