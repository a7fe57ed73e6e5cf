#include "bench_compare.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <tuple>

#include "bench_stats.hpp"
#include "errors.hpp"
#include "report_csv.hpp"

namespace pxflow {
namespace {

std::string str(const Json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}

// The point a row measured: rows of two files are compared when their keys are equal. The
// thread count belongs to the key only in the thread sweep; elsewhere a row ran on all of its
// machine's cores, which differ from machine to machine.
using PointKey = std::tuple<std::string, std::string, std::string, int, int, int, int, int>;
PointKey point_key(const Json& r) {
  const std::string sweep = str(r, "sweep");
  return {str(r, "backend"),    sweep,
          str(r, "profile"),    r.value("width", 0),
          r.value("height", 0), r.value("search_radius", 0),
          r.value("batch", 0),  sweep == "threads" ? r.value("threads", 0) : 0};
}

bool measured(const Json& r) {
  return r.contains("median_ns_per_frame") && r["median_ns_per_frame"].is_number() &&
         r["median_ns_per_frame"].get<double>() > 0;
}

std::vector<double> samples(const Json& r) {
  if (r.contains("samples_ns_per_frame") && r["samples_ns_per_frame"].is_array())
    return r["samples_ns_per_frame"].get<std::vector<double>>();
  return {r["median_ns_per_frame"].get<double>()};  // a file older than the samples
}

// A row's median interval, the median itself where the file has none.
std::pair<double, double> median_interval(const Json& r) {
  const double m = r["median_ns_per_frame"].get<double>();
  return {r.value("median_ci_low_ns", m), r.value("median_ci_high_ns", m)};
}

CompareRow compare_rows(const std::string& label, const Json& base, const Json& row) {
  CompareRow c;
  c.file = label;
  c.backend = str(row, "backend"), c.sweep = str(row, "sweep"), c.setting = str(row, "profile");
  c.source = str(row, "source");
  c.width = row.value("width", 0), c.height = row.value("height", 0);
  c.search_radius = row.value("search_radius", 0), c.batch = row.value("batch", 0);
  c.threads = row.value("threads", 0), c.base_threads = base.value("threads", 0);
  const std::vector<double> a = samples(base), b = samples(row);
  c.base_samples = static_cast<int>(a.size()), c.samples = static_cast<int>(b.size());
  c.base_median_ns = base["median_ns_per_frame"].get<double>();
  c.median_ns = row["median_ns_per_frame"].get<double>();
  c.ratio = c.median_ns / c.base_median_ns;
  // Both medians inside their 95 % intervals (each 95 %, so both at least 90 %): the ratio
  // inside the quotient of the intervals' far ends.
  const auto [a_low, a_high] = median_interval(base);
  const auto [b_low, b_high] = median_interval(row);
  c.ratio_ci_low = b_low / a_high, c.ratio_ci_high = b_high / a_low;
  // An exact clock counts the same cycles every run: any difference is the change itself.
  const bool exact = row.value("exact_clock", false) && base.value("exact_clock", false);
  bool significant = c.ratio != 1.0;
  if (!exact) {
    c.p_value = mann_whitney_p(a, b);
    significant = c.p_value < kSignificanceLevel;
  }
  c.verdict = !significant ? "same" : c.ratio > 1 ? "slower" : "faster";
  return c;
}

// Why the bench that wrote `f` called its machine disturbed, or empty.
std::string disturbance(const BenchFile& f) {
  return f.bench.contains("machine") && f.bench["machine"].is_object()
             ? str(f.bench["machine"], "disturbed")
             : "";
}

std::string row_name(const std::string& label, const Json& r) {
  char b[200];
  std::snprintf(b, sizeof b, "%s: %s %s batch=%d %dx%d S=%d threads=%d (%s)", label.c_str(),
                str(r, "backend").c_str(), str(r, "sweep").c_str(), r.value("batch", 0),
                r.value("width", 0), r.value("height", 0), r.value("search_radius", 0),
                r.value("threads", 0), str(r, "source").c_str());
  return b;
}

// The baseline's measured points that `f` did not measure (a row that failed or was not run
// there, or a backend it lacks): listed, so that a row missing from a gated run is seen (the
// gate judges the rows compared; a failed row is the check's to fail).
void list_missing(const BenchFile& base, const BenchFile& f, std::vector<std::string>& out) {
  std::map<PointKey, std::string> in_f;  // every point of f: its note when not measured
  for (const Json& r : f.bench["rows"])
    if (!in_f.contains(point_key(r)) || measured(r))
      in_f[point_key(r)] = measured(r) ? "" : str(r, "note").empty() ? "none" : str(r, "note");
  std::set<PointKey> listed;
  for (const Json& r : base.bench["rows"]) {
    const PointKey key = point_key(r);
    if (!measured(r) || listed.contains(key)) continue;
    const auto it = in_f.find(key);
    if (it != in_f.end() && it->second.empty()) continue;
    listed.insert(key);
    const std::string note = it == in_f.end() ? "" : it->second;
    out.push_back(row_name(f.label, r) + ": measured in " + base.label + " only" +
                  (note.empty() ? "" : " (" + f.label + "'s note: " + note + ")"));
  }
}

std::string fixed(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

template <auto M>
Json when_tested(const CompareRow& r) {
  return r.*M >= 0 ? Json(r.*M) : Json();
}
template <auto M>
constexpr ResultField<CompareRow> tested_field(const char* key) {
  return {key, &when_tested<M>, nullptr, true, true};
}

// In compare.csv's column order; compare.json's row objects have the same keys.
constexpr std::array kCompareRowFields{
    member_field<&CompareRow::file>("file"),
    member_field<&CompareRow::backend>("backend"),
    member_field<&CompareRow::sweep>("sweep"),
    member_field<&CompareRow::setting>("profile"),
    member_field<&CompareRow::width>("width"),
    member_field<&CompareRow::height>("height"),
    member_field<&CompareRow::search_radius>("search_radius"),
    member_field<&CompareRow::batch>("batch"),
    member_field<&CompareRow::threads>("threads"),
    member_field<&CompareRow::base_threads>("baseline_threads"),
    member_field<&CompareRow::source>("source"),
    member_field<&CompareRow::base_samples>("baseline_samples"),
    member_field<&CompareRow::samples>("samples"),
    member_field<&CompareRow::base_median_ns>("baseline_median_ns_per_frame"),
    member_field<&CompareRow::median_ns>("median_ns_per_frame"),
    member_field<&CompareRow::ratio>("ratio"),
    member_field<&CompareRow::ratio_ci_low>("ratio_ci_low"),
    member_field<&CompareRow::ratio_ci_high>("ratio_ci_high"),
    tested_field<&CompareRow::p_value>("p_value"),
    member_field<&CompareRow::verdict>("verdict"),
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
      (void)r.at("backend").get<std::string>(), (void)r.at("sweep").get<std::string>();
      (void)r.at("source").get<std::string>(), (void)r.at("batch").get<int>();
      if (measured(r) && r.contains("samples_ns_per_frame"))
        (void)r["samples_ns_per_frame"].get<std::vector<double>>();
    }
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

BenchComparison compare_bench_files(std::span<const BenchFile> files) {
  BenchComparison c;
  for (const BenchFile& f : files) {
    c.files.push_back(file_identity(f));
    if (const std::string why = disturbance(f); !why.empty())
      c.warnings.push_back(f.label + " was measured on a disturbed machine (" + why +
                           "): a significant change may be that load, not the build; rerun "
                           "both on a quiet machine");
    if (!f.bench.value("complete", true))
      c.warnings.push_back(f.label + " is incomplete: a signal stopped its bench after " +
                           std::to_string(f.bench.value("points_done", 0L)) + " of " +
                           std::to_string(f.bench.value("points_total", 0L)) +
                           " points; only the points it measured are compared");
  }
  // The baseline's measured rows by point, each point's clocks in its file's order.
  std::map<PointKey, std::vector<const Json*>> base;
  for (const Json& r : files.front().bench["rows"])
    if (measured(r)) base[point_key(r)].push_back(&r);
  for (const BenchFile& f : files.subspan(1))
    for (const Json& r : f.bench["rows"]) {
      if (!measured(r)) continue;
      const auto it = base.find(point_key(r));
      if (it == base.end()) {
        c.not_compared.push_back(row_name(f.label, r) + ": not measured in " + files.front().label);
        continue;
      }
      const auto same_clock = std::find_if(it->second.begin(), it->second.end(), [&](auto* b) {
        return str(*b, "source") == str(r, "source");
      });
      if (same_clock != it->second.end()) {
        c.rows.push_back(compare_rows(f.label, **same_clock, r));
        continue;
      }
      std::string clocks;
      for (const Json* b : it->second) clocks += (clocks.empty() ? "" : ", ") + str(*b, "source");
      c.not_compared.push_back(row_name(f.label, r) + ": not comparable: " + files.front().label +
                               " timed this point by another clock (" + clocks + ")");
    }
  for (const BenchFile& f : files.subspan(1)) list_missing(files.front(), f, c.not_compared);
  return c;
}

bool slower_beyond(const CompareRow& r, double percent) {
  return r.verdict == "slower" && (r.ratio - 1) * 100 > percent;
}

std::span<const ResultField<CompareRow>> compare_row_fields() { return kCompareRowFields; }

Json comparison_json(const BenchComparison& c) {
  Json rows = Json::array();
  for (const CompareRow& r : c.rows) rows.push_back(fields_json(compare_row_fields(), r));
  return {{"files", c.files},
          {"baseline", "A"},
          {"significance_level", kSignificanceLevel},
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
  return fixed("%.3f", r.ratio) + " [" + fixed("%.3f", r.ratio_ci_low) + ", " +
         fixed("%.3f", r.ratio_ci_high) + "]";
}

std::string point_text(const CompareRow& r) {
  return r.sweep + " batch=" + std::to_string(r.batch) + " " + std::to_string(r.width) + "x" +
         std::to_string(r.height) + " S=" + std::to_string(r.search_radius) +
         " threads=" + std::to_string(r.threads);
}

void print_comparison(const BenchComparison& c, std::ostream& out) {
  for (std::size_t i = 0; i < c.files.size(); ++i)
    out << file_label(i) << ": " << c.files[i] << "\n";
  char line[400];
  const char* format = "%-4s %-16s %-44s %-22s %13s %13s  %-26s %8s  %s\n";
  std::snprintf(line, sizeof line, format, "file", "backend", "point", "clock", "A ns/frame",
                "ns/frame", "ratio [95% CI]", "p", "verdict");
  out << "\n" << line;
  for (const CompareRow& r : c.rows) {
    std::snprintf(line, sizeof line, format, r.file.c_str(), r.backend.c_str(),
                  point_text(r).c_str(), r.source.c_str(), fixed("%.1f", r.base_median_ns).c_str(),
                  fixed("%.1f", r.median_ns).c_str(), ratio_text(r).c_str(),
                  r.p_value < 0 ? "exact" : fixed("%.4f", r.p_value).c_str(), r.verdict.c_str());
    out << line;
  }
  for (const std::string& n : c.not_compared) out << "not compared: " << n << "\n";
  for (const std::string& w : c.warnings) out << "warning: " << w << "\n";
}

}  // namespace pxflow
