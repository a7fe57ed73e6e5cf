// pxflow bench's table and JSON, and pxflow report's provenance, row order, charts and sweeps,
// through the binary (and the chart helpers directly, for their ticks and styles).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "results_files.hpp"
#include "run_program.hpp"
#include "svg_chart.hpp"

namespace pxflow::test {
namespace {

using nlohmann::json;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// A report of the files in `dir`, without accuracy; --backends (of the reference rows, which
// every build has) also leaves out the family sections.
RunResult report_from(const TempDir& dir, const std::string& out,
                      std::vector<std::string> extra = {"--backends",
                                                        "ref-original,ref-local,ref-global"}) {
  std::vector<std::string> args{
      "report",           "--out",        dir.path(out),      "--check-json",
      dir.path("c.json"), "--bench-json", dir.path("b.json"), "--no-accuracy"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_pxflow(args);
}

}  // namespace

#ifdef PXFLOW_TEST_CPU_BUILT
TEST_CASE("bench: one aligned table, the implementation cpu ran, the bound as columns", "[bench]") {
  const RunResult r = run_pxflow(
      {"bench", "--backends", "cpu,ref-original,ref-local", "--batch", "1,2", "--min-time", "0"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto lines = lines_of(r.out);
  // What `cpu` dispatched to is named before the table: an ISA row's name, and no thread count
  // (each point's line says its threads: the thread sweep runs the same backend on one).
  bool cpu_named = false;
  for (const auto& l : lines)
    if (l.rfind("  cpu ", 0) == 0)
      for (const std::string isa : {"avx512bw", "avx2", "sse41", "sse2", "swar", "neon"})
        cpu_named |= l.size() > isa.size() && l.ends_with(" " + isa);
  CHECK(cpu_named);
  for (const auto& l : lines)
    if (l.rfind("-- ", 0) == 0) CHECK(l.find(" threads=") != std::string::npos);
  // Registry order whatever order --backends named them in; every timed row's columns start
  // where the header's do.
  std::size_t header = 0;
  while (header < lines.size() && lines[header].rfind("backend ", 0) != 0) ++header;
  REQUIRE(header < lines.size());
  const std::string& h = lines[header];
  const std::size_t clock_at = h.find("clock"), fps_end = h.find("frames/s") + 8;
  std::vector<std::string> order;
  for (std::size_t i = header + 1; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.find("host-steady-clock") == std::string::npos) continue;
    order.push_back(l.substr(0, l.find(' ')));
    CHECK(l.find("host-steady-clock") == clock_at);
    CHECK(l.size() >= fps_end);
    CHECK(l[fps_end] == ' ');  // frames/s right-aligned under its header
    CHECK(l[fps_end - 1] != ' ');
  }
  CHECK(order == std::vector<std::string>{"ref-original", "ref-local", "cpu", "ref-original",
                                          "ref-local", "cpu"});
  CHECK(r.out.find("the bound\n") == std::string::npos);  // no list of bound lines after it
  CHECK(h.find("bound/frame") != std::string::npos);
  CHECK(h.find("of bound") != std::string::npos);
  CHECK(h.find("vs ref") != std::string::npos);
}
#endif

TEST_CASE("bench --json - writes the JSON to stdout and the table to stderr", "[bench]") {
  const RunResult r = run_pxflow(
      {"bench", "--backend", "ref-local", "--batch", "1", "--min-time", "0", "--json", "-"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(r.out);  // nothing but the JSON on stdout
  CHECK(j["command"] == "pxflow bench --backend ref-local --batch 1 --min-time 0 --json -");
  REQUIRE(j["backends"].size() == 1);
  CHECK(j["backends"][0]["backend"] == "ref-local");
  CHECK(j["rows"][0]["exact_clock"] == false);
  CHECK(r.err.find("host-steady-clock") != std::string::npos);

  const RunResult both =
      run_pxflow({"bench", "--backend", "ref-local", "--backends", "ref-original"});
  CHECK(both.exit_code == 2);
  CHECK(both.err_lines() == 1);
  CHECK(both.err.find("--backend ref-local: given with --backends ref-original") !=
        std::string::npos);
  CHECK(both.err.find("(see pxflow bench --help)") != std::string::npos);
}

TEST_CASE("report: provenance first, in results.json, and the commands as run", "[report]") {
  TempDir dir;
  make_small_results(dir);
  const RunResult r = report_from(dir, "r", {"--backends", "ref-local,ref-original"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  const json& build = j["provenance"]["build"];
  CHECK(!build["commit"].get<std::string>().empty());
  CHECK(build["dirty"].is_boolean());
  CHECK(build["cxx_flags"].get<std::string>().find("-ffp-contract=off") != std::string::npos);
  CHECK(!j["provenance"]["machine"]["cpu"].get<std::string>().empty());
  // The bench file's own command line, and the report's as given.
  CHECK(j["commands"]["bench"].get<std::string>().rfind(
            "pxflow bench --backends ref-original --batch 1 --min-time 0 --json ", 0) == 0);
  CHECK(j["commands"]["report"].get<std::string>().find(
            " --backends ref-local,ref-original --no-accuracy") != std::string::npos);
  const std::string md = slurp(dir.path("r/report.md"));
  CHECK(md.find("# pxflow report\n\n## Provenance\n") == 0);
  CHECK(md.find("| pxflow | 0.") != std::string::npos);
  const std::string html = slurp(dir.path("r/report.html"));
  CHECK(html.find("<h2 id='provenance'>") < html.find("<h2 id='conformance'>"));
  // The sections of results.json are the page's: the same cells.
  const json* conformance = section(j, "conformance");
  REQUIRE(conformance);
  CHECK(md.find("| " + (*conformance)["rows"][1][0].get<std::string>() + " | passed |") !=
        std::string::npos);
}

TEST_CASE("report --quick records the bench command that reruns its bench", "[report]") {
  TempDir dir;
  make_small_results(dir);
  const RunResult r =
      run_pxflow({"report", "--out", dir.path("r"), "--check-json", dir.path("c.json"),
                  "--no-accuracy", "--quick", "--threads", "1", "--backends", "ref-local"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  const std::string recorded = j["commands"]["bench"];
  CHECK(recorded == "pxflow bench --backends ref-local --threads 1 --quick");
  // Run as recorded (its words need no quoting), with its JSON kept: the same points.
  std::vector<std::string> args;
  std::istringstream words(recorded);
  for (std::string w; words >> w;) args.push_back(w);
  REQUIRE(args.front() == "pxflow");
  args.erase(args.begin());
  args.insert(args.end(), {"--json", dir.path("again.json")});
  const RunResult again = run_pxflow(args);
  INFO(again.err);
  REQUIRE(again.exit_code == 0);
  const auto points = [](const json& bench) {
    std::set<std::string> out;
    for (const auto& row : bench["rows"])
      out.insert(row["sweep"].get<std::string>() + " " + row["width"].dump() + "x" +
                 row["height"].dump() + " batch " + row["batch"].dump() + " threads " +
                 row["threads"].dump());
    return out;
  };
  CHECK(points(json::parse(slurp(dir.path("again.json")))) == points(j["bench"]));
  CHECK(points(j["bench"]).size() == 6);  // batch 1, 16, 256 and the three frame sizes
}

TEST_CASE("report: registry order in every table, whatever order the files have", "[report]") {
  TempDir dir;
  make_small_results(dir);
  json check = json::parse(slurp(dir.path("c.json")));
  std::reverse(check["backends"].begin(), check["backends"].end());  // ref-local first
  dir.write("c.json", check.dump());
  REQUIRE(report_from(dir, "r").exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  REQUIRE(section(j, "conformance"));
  const json& rows = (*section(j, "conformance"))["rows"];
  REQUIRE(rows.size() == 2);
  CHECK(rows[0][0] == "ref-original");
  CHECK(rows[1][0] == "ref-local");
  const std::string csv = slurp(dir.path("r/conformance.csv"));
  CHECK(csv.find("\"ref-original\"") < csv.find("\"ref-local\""));
}

TEST_CASE("report: every sweep run is a table and a chart, one left out says so", "[report]") {
  TempDir dir;
  make_small_results(dir);
  REQUIRE(run_pxflow({"bench", "--backends", "ref-original,ref-local,ref-global", "--min-time", "0",
                      "--batch", "1", "--json", dir.path("b.json")})
              .exit_code == 0);
  // Rename the custom points into the sweeps the default bench runs, as it would write them.
  json bench = json::parse(slurp(dir.path("b.json")));
  json rows = json::array();
  for (auto r : bench["rows"]) {
    r["sweep"] = "batch";
    rows.push_back(r);
    for (int S : {2, 8}) {
      json x = r;
      x["sweep"] = "radius", x["search_radius"] = S;
      x["frames_per_s"] = r["frames_per_s"].get<double>() * 4 / S;
      rows.push_back(x);
    }
    json t = r;
    t["sweep"] = "threads", t["threads"] = 1;
    rows.push_back(t);
  }
  bench["rows"] = rows;
  dir.write("b.json", bench.dump());
  const RunResult r = report_from(dir, "r");
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  for (const char* key : {"scaling-batch", "scaling-radius", "scaling-threads"}) {
    const json* s = section(j, key);
    REQUIRE(s);
    INFO(key);
    CHECK((*s)["rows"].size() == 3);
    REQUIRE((*s)["charts"].size() == 1);
    CHECK((*s)["charts"][0]["series"].size() == 3);
  }
  // The radius sweep joins the batch point at the profile's S=4: three columns and the note.
  CHECK((*section(j, "scaling-radius"))["header"] ==
        json::array({"backend", "S=2", "S=4", "S=8", "note"}));
  CHECK((*section(j, "scaling-radius"))["charts"][0]["x_axis"]["integer"] == true);
  const json* size = section(j, "scaling-size");
  REQUIRE(size);
  CHECK((*size)["rows"].empty());
  CHECK((*size)["text"].get<std::string>().find("Not part of this bench run") == 0);
  CHECK(slurp(dir.path("r/report.md")).find("Not measured") == std::string::npos);
}

TEST_CASE("report: every backend of a chart has a colour and a marker of its own", "[report]") {
  std::set<std::string> colours, markers;
  for (std::size_t i = 0; i < 20; ++i) {
    const ChartStyle s = backend_style(i);
    colours.insert(s.colour);
    markers.insert(s.marker);
    CHECK(s.colour != reference_style().colour);
  }
  CHECK(colours.size() == 20);
  CHECK(markers.size() == 7);
  TempDir dir;
  make_small_results(dir);
  REQUIRE(run_pxflow({"bench", "--backends", "ref-original,ref-local,ref-global", "--batch", "1,16",
                      "--min-time", "0", "--json", dir.path("b.json")})
              .exit_code == 0);
  json bench = json::parse(slurp(dir.path("b.json")));
  for (auto& r : bench["rows"]) r["sweep"] = "batch";  // as the default sweeps name them
  dir.write("b.json", bench.dump());
  REQUIRE(report_from(dir, "r").exit_code == 0);
  const json j = json::parse(slurp(dir.path("r/results.json")));
  int charts = 0;
  for (const auto& s : j["sections"])
    for (const auto& c : s["charts"]) {
      std::set<std::string> seen;
      const json& items = c["kind"] == "bar" ? c["bars"] : c["series"];
      for (const auto& item : items)
        seen.insert(item["style"]["colour"].get<std::string>() +
                    item["style"]["marker"].get<std::string>());
      CHECK(seen.size() == items.size());
      charts += s["key"] != "bound";  // the bound section's charts, one per point, checked too
    }
  CHECK(charts == 2);  // the throughput bars and the batch sweep's lines
}

TEST_CASE("chart axes are labelled at 1-2-5 ticks, whole numbers where asked", "[report]") {
  CHECK(axis_ticks(1, 10, true) == std::vector<double>{1, 2, 5, 10});
  CHECK(axis_ticks(1000, 200000, true) ==
        std::vector<double>{1000, 2000, 5000, 10000, 20000, 50000, 100000, 200000});
  // Beyond three decades only the decades, so that labels do not collide.
  CHECK(axis_ticks(1, 1e5, true) == std::vector<double>{1, 10, 100, 1000, 10000, 100000});
  CHECK(axis_range(1, 8, false, true) == std::pair<double, double>{0, 8});
  CHECK(axis_ticks(0, 8, false, true) == std::vector<double>{0, 2, 4, 6, 8});
  CHECK(axis_ticks(1, 2, false, true) == std::vector<double>{1, 2});  // threads: no 1.5
  CHECK(axis_range(1300, 140000, true) == std::pair<double, double>{1000, 200000});
  // A zero on a log axis (a row whose value is 0) once looped without end, filling memory:
  // the ticks are the linear ones; values no axis can show give one tick.
  CHECK(axis_ticks(0, 10, true) == std::vector<double>{0, 2, 4, 6, 8, 10});
  CHECK(axis_ticks(1e300, -1e300, true).size() == 1);
  CHECK(axis_ticks(-INFINITY, INFINITY, false).size() == 1);
  // A chart whose log axes hold a 0 draws them linear: every coordinate a number.
  Chart chart{"zero", {"x", true}, {"y", true}, {{"row", {{0, 0}, {4, 2}}, {}}}, {}, ""};
  CHECK(svg_chart(chart).find("nan") == std::string::npos);
  chart = Chart{"zero", {"x", true}, {"y", true}, {}, {{"row", 0, {}}, {"other", 3, {}}}, "op/s"};
  CHECK(svg_chart(chart).find("nan") == std::string::npos);
}

TEST_CASE("report: options that would do nothing, and unknown backends, are refused", "[report]") {
  TempDir dir;
  make_small_results(dir);
  const RunResult threads =
      report_from(dir, "r", {"--backends", "ref-original,ref-local", "--threads", "1"});
  CHECK(threads.exit_code == 2);
  CHECK(threads.err_lines() == 1);
  CHECK(threads.err.find("--threads: has no effect") != std::string::npos);
  // --backend shapes the accuracy table and the pictures only: refused alike without them.
  const RunResult backend =
      report_from(dir, "r", {"--backends", "ref-original,ref-local", "--backend", "ref-local"});
  CHECK(backend.exit_code == 2);
  CHECK(backend.err_lines() == 1);
  CHECK(backend.err.find("--backend: has no effect") != std::string::npos);
  CHECK(backend.out.empty());
  const RunResult unknown =
      report_from(dir, "r", {"--backends", "ref-original,ref-local", "--backend", "no-such"});
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.err.find("no-such") != std::string::npos);
}

}  // namespace pxflow::test
