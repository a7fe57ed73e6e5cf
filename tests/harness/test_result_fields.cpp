// The field tables (bench_row_fields, check_report_fields, backend_outcome_fields) against
// docs/report-schema.json and the CSV files: a field the JSON writer has, the schema or a CSV
// lacks (or the other way round) fails here, as instructions_per_frame once did.
#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <set>
#include <sstream>

#include "bench.hpp"
#include "bench_compare.hpp"
#include "build_paths.hpp"
#include "check.hpp"
#include "report_csv.hpp"

namespace pxflow {
namespace {

Json schema() {
  std::ifstream in(build_paths::report_schema);
  REQUIRE(in);
  return Json::parse(in);
}

std::set<std::string> properties(const Json& object_schema) {
  std::set<std::string> keys;
  for (const auto& [key, _] : object_schema.at("properties").items()) keys.insert(key);
  return keys;
}

template <class T>
std::set<std::string> keys_of(std::span<const ResultField<T>> fields, bool required_only = false) {
  std::set<std::string> keys;
  for (const ResultField<T>& f : fields)
    if (!required_only || !f.optional) keys.insert(f.key);
  return keys;
}

std::set<std::string> as_set(const Json& array) { return array.get<std::set<std::string>>(); }

std::vector<std::string> csv_line(const std::string& csv, int line) {
  std::istringstream in(csv);
  std::string text;
  for (int i = 0; i <= line; ++i) std::getline(in, text);
  std::vector<std::string> cells;
  std::istringstream cells_in(text);
  for (std::string cell; std::getline(cells_in, cell, ',');) cells.push_back(cell);
  if (!text.empty() && text.back() == ',') cells.push_back("");
  return cells;
}

}  // namespace

TEST_CASE("schema: a bench row's properties are bench_row_fields(), closed", "[schema]") {
  const Json row = schema().at("definitions").at("bench_row");
  CHECK(properties(row) == keys_of(bench_row_fields()));
  CHECK(as_set(row.at("required")) == keys_of(bench_row_fields(), true));
  CHECK(row.at("additionalProperties") == false);
}

TEST_CASE("schema: a compare row's properties are compare_row_fields(), closed", "[schema]") {
  const Json row = schema().at("definitions").at("compare_row");
  CHECK(properties(row) == keys_of(compare_row_fields()));
  CHECK(as_set(row.at("required")) == keys_of(compare_row_fields(), true));
  CHECK(row.at("additionalProperties") == false);
}

TEST_CASE("schema: the check's and its backends' properties are their field tables", "[schema]") {
  const Json check = schema().at("definitions").at("check");
  CHECK(properties(check) == keys_of(check_report_fields()));
  CHECK(check.at("additionalProperties") == false);
  const Json backend = check.at("properties").at("backends").at("items");
  CHECK(properties(backend) == keys_of(backend_outcome_fields()));
  CHECK(backend.at("additionalProperties") == false);
  for (const Json* s : {&check, &backend})
    for (const std::string& key : as_set(s->at("required"))) {
      INFO(key);
      CHECK(properties(*s).contains(key));
    }
}

TEST_CASE("results.csv: a column per bench row field, empty where a row lacks it", "[schema]") {
  BenchReport r;
  BenchRow m4;
  m4.backend = "m4-qemu", m4.pois_per_frame = 64, m4.instructions_per_frame = 123456;
  BenchRow host;
  host.backend = "ref-original", host.pois_per_frame = 64, host.cycles_per_frame = 5000;
  r.rows = {m4, host};
  const std::string csv = bench_csv(bench_json(r));
  const std::vector<std::string> header = csv_line(csv, 0);
  CHECK(header == csv_columns(bench_row_fields()));
  // Every key but the lists and the parameters (the JSON's only: no CSV cell).
  std::set<std::string> keys = keys_of(bench_row_fields());
  for (const char* list :
       {"samples_ns_per_frame", "samples_per_process", "process_medians_ns_per_frame", "params"})
    keys.erase(list);
  CHECK(std::set<std::string>(header.begin(), header.end()) == keys);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  // Registry order: ref-original first (m4-qemu is a family row, or unknown to this build).
  const std::vector<std::string> ref = csv_line(csv, 1), dev = csv_line(csv, 2);
  REQUIRE(ref.size() == header.size());
  REQUIRE(dev.size() == header.size());
  CHECK(dev.at(column("instructions_per_frame")) == "123456.0");
  CHECK(ref.at(column("instructions_per_frame")).empty());
  CHECK(ref.at(column("cycles_per_frame")) == "5000.0");
  CHECK(dev.at(column("cycles_per_frame")).empty());
  CHECK(dev.at(column("pois_per_frame")) == "64");
}

TEST_CASE("conformance.csv: a column per scalar field of a check backend", "[schema]") {
  CheckReport r;
  r.backends.push_back(
      {"ref-local", BackendState::kPassed, "", "", "host", 3, 0, 1, 6, 0.5, 0.0, {}, {}});
  const std::string csv = conformance_csv(check_json(r));
  CHECK(csv_line(csv, 0) == csv_columns(backend_outcome_fields()));
  std::set<std::string> all = keys_of(backend_outcome_fields());
  all.erase("failures");  // lines, in results.json only
  all.erase("limits");    // likewise
  const std::vector<std::string> header = csv_line(csv, 0);
  CHECK(std::set<std::string>(header.begin(), header.end()) == all);
  CHECK(csv_line(csv, 1).at(1) == "\"passed\"");
}

TEST_CASE("check file: written and read back through its table, field for field", "[schema]") {
  CheckReport r;
  r.seed = 7, r.cases = 3, r.pairs = 6, r.passed = 1, r.compared = 3, r.command = "pxflow check";
  r.backends.push_back({"ref-local",
                        BackendState::kFailed,
                        "",
                        "ref-local",
                        "host",
                        2,
                        1,
                        0,
                        6,
                        0.25,
                        0.0,
                        {"a line"},
                        {}});
  const CheckReport back = check_from_json(check_json(r));
  CHECK(check_json(back) == check_json(r));
  CHECK(back.backends.at(0).failures == std::vector<std::string>{"a line"});
}

}  // namespace pxflow
