#include "bench_compare.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <tuple>

#include "bench.hpp"
#include "bench_stats.hpp"
#include "csv_table.hpp"
#include "errors.hpp"
#include "number_text.hpp"
#include "result_fields_json.hpp"

namespace pxflow {
namespace {

std::string str(const Json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}

// Everything that makes a row's work what it is, as (name, value): rows of two files are
// compared only where every value is equal. Files of different machines (--across-machines)
// compare the threads asked for (all cores is all cores) and not the device, which differs.
using RowKey = std::vector<std::pair<std::string, std::string>>;
RowKey row_key(const Json& r, bool across_machines) {
  auto text = [](const Json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); };
  RowKey k{{bench_key::kBackend, str(r, bench_key::kBackend)},
           {"clock", str(r, bench_key::kSource)},
           {bench_key::kSweep, str(r, bench_key::kSweep)},
           {bench_key::kProfile, str(r, bench_key::kProfile)}};
  if (r.contains(bench_key::kParams) && r[bench_key::kParams].is_object())
    for (const auto& [name, value] : r[bench_key::kParams].items())
      k.push_back({name, text(value)});
  else  // a file older than "params": what it has
    for (const char* name : {bench_key::kWidth, bench_key::kHeight, bench_key::kSearchRadius})
      k.push_back({name, text(r.value(name, Json()))});
  k.push_back({bench_key::kBatch, text(r.value(bench_key::kBatch, Json()))});
  if (across_machines) {
    const int asked = r.value(bench_key::kThreadsRequested, -1);
    k.push_back({bench_key::kThreads, asked == 0  ? "all"
                                      : asked > 0 ? std::to_string(asked)
                                                  : "?"});
  } else {
    k.push_back({bench_key::kThreads, text(r.value(bench_key::kThreads, Json()))});
    k.push_back({bench_key::kDevice, str(r, bench_key::kDevice)});
  }
  return k;
}

// "blocks 8 in A, 2 in B; threads 2 in A, 1 in B": how two keys differ.
std::string key_difference(const RowKey& a, const RowKey& b, const std::string& la,
                           const std::string& lb) {
  std::string d;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (a[i] != b[i])
      d += (d.empty() ? "" : "; ") + a[i].first + " " + a[i].second + " in " + la + ", " +
           b[i].second + " in " + lb;
  return d.empty() ? "their parameters differ" : d;
}

std::size_t differences(const RowKey& a, const RowKey& b) {
  if (a.size() != b.size()) return a.size() + b.size();
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

bool measured(const Json& r) {
  return r.contains(bench_key::kMedianNs) && r[bench_key::kMedianNs].is_number() &&
         r[bench_key::kMedianNs].get<double>() > 0;
}

// The values the statistics are over: each process's median; one process: its samples (a file
// older than the processes, or bench --processes 1).
std::vector<double> process_medians(const Json& r) {
  if (r.contains(bench_key::kProcessMedians) && r[bench_key::kProcessMedians].is_array())
    return r[bench_key::kProcessMedians].get<std::vector<double>>();
  return {r[bench_key::kMedianNs].get<double>()};
}

int sample_count(const Json& r) {
  if (r.contains(bench_key::kSamples) && r[bench_key::kSamples].is_array())
    return static_cast<int>(r[bench_key::kSamples].size());
  return 1;
}

// Why the bench that wrote `f` called its machine disturbed, or empty.
std::string disturbance(const BenchFile& f) {
  return f.bench.contains("machine") && f.bench["machine"].is_object()
             ? str(f.bench["machine"], "disturbed")
             : "";
}

// The row's verdict and, with a gate, its outcome (bench_compare.hpp).
void judge(CompareRow& c, const std::string& inconclusive, double fail_above) {
  const double limit = 1 + fail_above / 100;
  if (!inconclusive.empty()) {
    c.verdict = "inconclusive", c.why = inconclusive;
    if (fail_above >= 0) c.gate = "inconclusive";
    return;
  }
  const bool exact = c.p_value < 0;
  const bool significant = exact ? c.ratio != 1.0 : c.p_value < kSignificanceLevel;
  c.verdict = significant && c.ratio_ci_low > 1    ? "slower"
              : significant && c.ratio_ci_high < 1 ? "faster"
                                                   : "not significant";
  if (fail_above < 0) return;
  if (significant && c.ratio_ci_low > limit)
    c.gate = "fail";
  else if (c.ratio_ci_high <= limit)
    c.gate = "pass";
  else {
    c.gate = "inconclusive";
    c.why = "its interval [" + formatted("%.3f", c.ratio_ci_low) + ", " +
            formatted("%.3f", c.ratio_ci_high) + "] holds " + formatted("%.3f", limit) +
            ": more processes (bench --processes, compare --rounds) or a quieter machine";
  }
}

CompareRow compare_rows(const BenchFile& base_file, const BenchFile& file, const Json& base,
                        const Json& row, double fail_above) {
  CompareRow c;
  c.file = file.label;
  c.backend = str(row, bench_key::kBackend), c.sweep = str(row, bench_key::kSweep),
  c.setting = str(row, bench_key::kProfile);
  c.source = str(row, bench_key::kSource);
  c.width = row.value(bench_key::kWidth, 0), c.height = row.value(bench_key::kHeight, 0);
  c.search_radius = row.value(bench_key::kSearchRadius, 0),
  c.batch = row.value(bench_key::kBatch, 0);
  c.threads = row.value(bench_key::kThreads, 0),
  c.base_threads = base.value(bench_key::kThreads, 0);
  const std::vector<double> a = process_medians(base), b = process_medians(row);
  c.base_samples = sample_count(base), c.samples = sample_count(row);
  c.base_processes = static_cast<int>(a.size()), c.processes = static_cast<int>(b.size());
  c.base_median_ns = base[bench_key::kMedianNs].get<double>();
  c.median_ns = row[bench_key::kMedianNs].get<double>();
  std::string inconclusive;
  // An exact clock counts the same cycles every run: any difference is the change itself.
  if (row.value(bench_key::kExactClock, false) && base.value(bench_key::kExactClock, false)) {
    c.ratio = c.ratio_ci_low = c.ratio_ci_high = c.median_ns / c.base_median_ns;
  } else {
    const RatioInterval r = ratio_interval95(a, b);
    c.ratio = r.ratio, c.ratio_ci_low = r.low, c.ratio_ci_high = r.high;
    c.p_value = mann_whitney_p(a, b);
    if (a.size() < 2 || b.size() < 2)
      inconclusive = (a.size() < 2 ? base_file.label : file.label) +
                     "'s row is one process (bench --processes 1, or a file older than them): "
                     "no run-to-run variance to judge by";
    else if (!r.bounded)
      inconclusive = "too few processes for a 95 % interval (" + std::to_string(a.size()) +
                     " and " + std::to_string(b.size()) + "; 4 and 4 at least)";
    for (const BenchFile* f : {&base_file, &file})
      if (inconclusive.empty() && !disturbance(*f).empty())
        inconclusive = f->label + " was measured on a disturbed machine (see the warning)";
  }
  judge(c, inconclusive, fail_above);
  return c;
}

std::string row_name(const std::string& label, const Json& r) {
  char b[200];
  std::snprintf(b, sizeof b, "%s: %s %s batch=%d %dx%d S=%d threads=%d (%s)", label.c_str(),
                str(r, bench_key::kBackend).c_str(), str(r, bench_key::kSweep).c_str(),
                r.value(bench_key::kBatch, 0), r.value(bench_key::kWidth, 0),
                r.value(bench_key::kHeight, 0), r.value(bench_key::kSearchRadius, 0),
                r.value(bench_key::kThreads, 0), str(r, bench_key::kSource).c_str());
  return b;
}

// The baseline's measured rows that `f` did not measure (a row that failed or was not run there,
// or a backend it lacks): listed, so that a row missing from a gated run is seen (the gate
// judges the rows compared; a failed row is the check's to fail).
void list_missing(const BenchFile& base, const BenchFile& f, bool across,
                  std::vector<std::string>& out) {
  std::map<RowKey, std::string> in_f;  // every row of f: its note when not measured
  for (const Json& r : f.bench["rows"])
    if (!in_f.contains(row_key(r, across)) || measured(r))
      in_f[row_key(r, across)] = measured(r)                        ? ""
                                 : str(r, bench_key::kNote).empty() ? "none"
                                                                    : str(r, bench_key::kNote);
  std::set<RowKey> listed;
  for (const Json& r : base.bench["rows"]) {
    const RowKey key = row_key(r, across);
    if (!measured(r) || listed.contains(key)) continue;
    const auto it = in_f.find(key);
    if (it != in_f.end() && it->second.empty()) continue;
    listed.insert(key);
    const std::string note = it == in_f.end() ? "" : it->second;
    out.push_back(row_name(f.label, r) + ": measured in " + base.label + " only" +
                  (note.empty() ? "" : " (" + f.label + "'s note: " + note + ")"));
  }
}

template <auto M>
Json when_tested(const CompareRow& r) {
  return r.*M >= 0 ? Json(r.*M) : Json();
}
template <auto M>
constexpr ResultField<CompareRow> tested_field(const char* key) {
  return {key, &when_tested<M>, nullptr, true, true};
}
// The interval's ends, left out when too few processes bound it (0..infinity).
template <auto M>
Json when_bounded(const CompareRow& r) {
  return std::isfinite(r.ratio_ci_high) ? Json(r.*M) : Json();
}
template <auto M>
constexpr ResultField<CompareRow> bounded_field(const char* key) {
  return {key, &when_bounded<M>, nullptr, true, true};
}

// In compare.csv's column order; compare.json's row objects have the same keys.
constexpr std::array kCompareRowFields{
    member_field<&CompareRow::file>("file"),
    member_field<&CompareRow::backend>(bench_key::kBackend),
    member_field<&CompareRow::sweep>(bench_key::kSweep),
    member_field<&CompareRow::setting>(bench_key::kProfile),
    member_field<&CompareRow::width>(bench_key::kWidth),
    member_field<&CompareRow::height>(bench_key::kHeight),
    member_field<&CompareRow::search_radius>(bench_key::kSearchRadius),
    member_field<&CompareRow::batch>(bench_key::kBatch),
    member_field<&CompareRow::threads>(bench_key::kThreads),
    member_field<&CompareRow::base_threads>("baseline_threads"),
    member_field<&CompareRow::source>(bench_key::kSource),
    member_field<&CompareRow::base_samples>("baseline_samples"),
    member_field<&CompareRow::samples>("samples"),
    member_field<&CompareRow::base_processes>("baseline_processes"),
    member_field<&CompareRow::processes>(bench_key::kProcesses),
    member_field<&CompareRow::base_median_ns>("baseline_median_ns_per_frame"),
    member_field<&CompareRow::median_ns>(bench_key::kMedianNs),
    member_field<&CompareRow::ratio>("ratio"),
    bounded_field<&CompareRow::ratio_ci_low>("ratio_ci_low"),
    bounded_field<&CompareRow::ratio_ci_high>("ratio_ci_high"),
    tested_field<&CompareRow::p_value>("p_value"),
    member_field<&CompareRow::verdict>("verdict"),
    member_field<&CompareRow::gate>("gate"),
    member_field<&CompareRow::why>("why"),
};

}  // namespace

std::string file_label(std::size_t index) {
  return std::string(1, static_cast<char>('A' + std::min<std::size_t>(index, 25)));
}

void check_bench_file(const std::string& path, const Json& j) {
  if (!j.is_object() || !j.contains("rows") || !j["rows"].is_array())
    throw InputError(path + ": not a bench file (expected the output of pxflow bench --json)");
  try {
    for (const Json& r : j["rows"]) {
      (void)r.at(bench_key::kBackend).get<std::string>(),
          (void)r.at(bench_key::kSweep).get<std::string>();
      (void)r.at(bench_key::kSource).get<std::string>(), (void)r.at(bench_key::kBatch).get<int>();
      if (measured(r) && r.contains(bench_key::kSamples))
        (void)r[bench_key::kSamples].get<std::vector<double>>();
      if (measured(r))
        for (double m : process_medians(r))
          if (!(m > 0 && std::isfinite(m)))
            throw InputError(path + ": a row's process median is not a positive time (" +
                             row_name("row", r) + ")");
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path + ": a malformed bench file (" + e.what() + ")");
  }
}

std::string file_machine(const BenchFile& f) {
  const Json& p = f.bench.contains("provenance") ? f.bench["provenance"] : Json::object();
  const Json& m = p.contains("machine") ? p["machine"] : Json::object();
  const std::string host = str(m, "host"), cpu = str(m, "cpu");
  if (host.empty() && cpu.empty()) return "machine not recorded";
  return (host.empty() ? "?" : host) + " (" + (cpu.empty() ? "?" : cpu) + ")";
}

std::string file_identity(const BenchFile& f) {
  const Json& p = f.bench.contains("provenance") ? f.bench["provenance"] : Json::object();
  const Json& m = p.contains("machine") ? p["machine"] : Json::object();
  const Json& build = f.bench.contains("pxflow") ? f.bench["pxflow"] : Json::object();
  std::string s = f.path + ": " + file_machine(f);
  if (m.contains("cores")) s += ", " + std::to_string(m.value("cores", 0)) + " cores";
  s += "; pxflow " + (str(build, "version").empty() ? "?" : str(build, "version")) + " at " +
       (str(build, "commit").empty() ? "?" : str(build, "commit"));
  if (p.contains("build")) s += ", " + str(p["build"], "compiler");
  if (!str(m, "date").empty()) s += "; " + str(m, "date");
  if (!disturbance(f).empty()) s += "; DISTURBED run";
  return s;
}

// "h (AMD EPYC ...)" of every file: the machine a file's numbers are of.
std::string machine_key(const BenchFile& f) { return file_machine(f); }

BenchComparison compare_bench_files(std::span<const BenchFile> files,
                                    const CompareOptions& options) {
  BenchComparison c;
  c.fail_above = options.fail_above;
  const bool across = options.across_machines;
  for (const BenchFile& f : files.subspan(1))
    if (machine_key(f) != machine_key(files.front())) {
      const std::string what = files.front().label + " (" + files.front().path + ") and " +
                               f.label + " (" + f.path + ") were measured on different machines, " +
                               machine_key(files.front()) + " and " + machine_key(f);
      if (!across)
        throw InputError(what +
                         ": compare them with --across-machines (rows are then paired by "
                         "the threads asked for, not by device)");
      if (c.across_machines.empty()) c.across_machines = what;
    }
  for (const BenchFile& f : files) {
    c.files.push_back(file_identity(f));
    if (const std::string why = disturbance(f); !why.empty())
      c.warnings.push_back(f.label + " was measured on a disturbed machine (" + why +
                           "): its host-clock rows are inconclusive; rerun on a quiet machine");
    if (!f.bench.value("complete", true))
      c.warnings.push_back(f.label + " is incomplete: a signal stopped its bench after " +
                           std::to_string(f.bench.value("points_done", 0L)) + " of " +
                           std::to_string(f.bench.value("points_total", 0L)) +
                           " points; only the points it measured are compared");
  }
  std::vector<std::pair<RowKey, const Json*>> base;  // the baseline's measured rows
  for (const Json& r : files.front().bench["rows"])
    if (measured(r)) base.push_back({row_key(r, across), &r});
  for (const BenchFile& f : files.subspan(1))
    for (const Json& r : f.bench["rows"]) {
      if (!measured(r)) continue;
      const RowKey key = row_key(r, across);
      const auto same =
          std::find_if(base.begin(), base.end(), [&](auto& b) { return b.first == key; });
      if (same != base.end()) {
        c.rows.push_back(compare_rows(files.front(), f, *same->second, r, options.fail_above));
        continue;
      }
      // The nearest row of the same backend says what differs.
      const std::pair<RowKey, const Json*>* nearest = nullptr;
      for (const auto& b : base)
        if (b.first.front() == key.front() &&
            (!nearest || differences(b.first, key) < differences(nearest->first, key)))
          nearest = &b;
      c.not_compared.push_back(
          row_name(f.label, r) +
          (nearest ? ": not comparable: " +
                         key_difference(nearest->first, key, files.front().label, f.label)
                   : ": not measured in " + files.front().label));
    }
  for (const BenchFile& f : files.subspan(1))
    list_missing(files.front(), f, across, c.not_compared);
  return c;
}

int comparison_exit(const BenchComparison& c) {
  if (c.rows.empty()) return 1;
  bool inconclusive = false;
  for (const CompareRow& r : c.rows) {
    if (r.gate == "fail") return 1;
    inconclusive = inconclusive || r.gate == "inconclusive";
  }
  return inconclusive ? kInconclusiveExit : 0;
}

std::span<const ResultField<CompareRow>> compare_row_fields() { return kCompareRowFields; }

Json comparison_json(const BenchComparison& c) {
  Json rows = Json::array();
  for (const CompareRow& r : c.rows) rows.push_back(fields_json(compare_row_fields(), r));
  return {{"files", c.files},
          {"baseline", "A"},
          {"significance_level", kSignificanceLevel},
          {"fail_above_percent", c.fail_above >= 0 ? Json(c.fail_above) : Json()},
          {"across_machines", c.across_machines.empty() ? Json() : Json(c.across_machines)},
          {"exit", comparison_exit(c)},
          {"rows", rows},
          {"not_compared", c.not_compared},
          {"warnings", c.warnings}};
}

std::string comparison_csv(const BenchComparison& c) {
  Json rows = Json::array();
  for (const CompareRow& r : c.rows) rows.push_back(fields_json(compare_row_fields(), r));
  return csv_table(csv_columns(compare_row_fields()), rows);
}

std::string ratio_text(const CompareRow& r) {
  return formatted("%.3f", r.ratio) + " [" + formatted("%.3f", r.ratio_ci_low) + ", " +
         (std::isfinite(r.ratio_ci_high) ? formatted("%.3f", r.ratio_ci_high) : "inf") + "]";
}

std::string point_text(const CompareRow& r) {
  return r.sweep + " batch=" + std::to_string(r.batch) + " " + std::to_string(r.width) + "x" +
         std::to_string(r.height) + " S=" + std::to_string(r.search_radius) +
         " threads=" + std::to_string(r.threads);
}

void print_comparison(const BenchComparison& c, std::ostream& out) {
  for (std::size_t i = 0; i < c.files.size(); ++i)
    out << file_label(i) << ": " << c.files[i] << "\n";
  if (!c.across_machines.empty()) out << "across machines: " << c.across_machines << "\n";
  char line[600];
  const char* format = "%-4s %-16s %-44s %-22s %13s %13s  %-26s %8s  %-15s %s\n";
  std::snprintf(line, sizeof line, format, "file", "backend", "point", "clock", "A ns/frame",
                "ns/frame", "ratio [95% CI]", "p", "verdict", c.fail_above >= 0 ? "gate" : "");
  out << "\n" << line;
  for (const CompareRow& r : c.rows) {
    const std::string gate = r.gate + (r.why.empty() ? "" : ": " + r.why);
    std::snprintf(line, sizeof line, format, r.file.c_str(), r.backend.c_str(),
                  point_text(r).c_str(), r.source.c_str(),
                  formatted("%.1f", r.base_median_ns).c_str(),
                  formatted("%.1f", r.median_ns).c_str(), ratio_text(r).c_str(),
                  r.p_value < 0 ? "exact" : formatted("%.4f", r.p_value).c_str(), r.verdict.c_str(),
                  c.fail_above >= 0 ? gate.c_str() : r.why.c_str());
    out << line;
  }
  for (const std::string& n : c.not_compared) out << "not compared: " << n << "\n";
  for (const std::string& w : c.warnings) out << "warning: " << w << "\n";
}

}  // namespace pxflow
