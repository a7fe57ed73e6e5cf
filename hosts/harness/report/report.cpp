#include "report.hpp"

#include <filesystem>
#include <iterator>
#include <sstream>

#include "errors.hpp"
#include "json_document.hpp"
#include "owned_folder.hpp"
#include "provenance.hpp"
#include "registry.hpp"
#include "report_csv.hpp"
#include "report_sections.hpp"
#include "svg_chart.hpp"
#include "system_files.hpp"

namespace pxflow {
namespace {

using report::Section;

constexpr const char* kManifest = ".pxflow-report";

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                       (unsigned char)bytes[i + 2];
    out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], k[v & 63]};
  }
  if (i < bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16 |
                       (i + 1 < bytes.size() ? (unsigned char)bytes[i + 1] << 8 : 0);
    out += {k[v >> 18], k[(v >> 12) & 63], i + 1 < bytes.size() ? k[(v >> 6) & 63] : '=', '='};
  }
  return out;
}

// A table cell: a '|' would end it, so it is escaped.
std::string md_cell(const std::string& c) {
  std::string out;
  for (char ch : c) {
    if (ch == '|') out.push_back('\\');
    out.push_back(ch);
  }
  return out;
}

std::string render_md(const std::vector<Section>& secs) {
  std::ostringstream o;
  o << "# pxflow report\n";
  for (const auto& s : secs) {
    o << "\n## " << s.title << "\n\n" << s.text << "\n";
    for (const auto& p : s.pictures) o << "\n![" << p.caption << "](" << p.file << ")\n";
    for (const auto& c : s.charts)
      o << "\nChart (in report.html; its data in results.json): " << c.title << "\n";
    if (s.rows.empty()) continue;
    o << "\n|";
    for (const auto& h : s.header) o << " " << md_cell(h) << " |";
    o << "\n|";
    for (std::size_t i = 0; i < s.header.size(); ++i) o << "---|";
    for (const auto& r : s.rows) {
      o << "\n|";
      for (const auto& c : r) o << " " << md_cell(c) << " |";
    }
    o << "\n";
  }
  return o.str();
}

// A section's text, escaped, its `code` spans and **strong** spans (Markdown's, as report.md
// writes them: the first screen's warning) as <code> and <strong>, and its line breaks (a list of
// failure lines) as <br>.
std::string html_text(const std::string& text) {
  std::string out;
  bool code = false, strong = false;
  std::size_t start = 0;
  auto plain = [&](const std::string& t) {
    const std::string escaped = html_escape(t);
    for (std::size_t i = 0; i < escaped.size(); ++i) {
      if (!code && escaped.compare(i, 2, "**") == 0) {
        out += strong ? "</strong>" : "<strong>";
        strong = !strong, ++i;
      } else {
        out += escaped[i] == '\n' ? std::string("<br>") : std::string(1, escaped[i]);
      }
    }
  };
  for (std::size_t tick = text.find('`'); tick != std::string::npos;
       start = tick + 1, tick = text.find('`', start)) {
    plain(text.substr(start, tick - start));
    out += code ? "</code>" : "<code>";
    code = !code;
  }
  plain(text.substr(start));
  if (code) out += "</code>";  // an unpaired backtick: the rest is code, the tag closed
  if (strong) out += "</strong>";
  return out;
}

std::string html_table(const Section& s) {
  std::ostringstream o;
  o << "<table><tr>";
  for (const auto& h : s.header) o << "<th>" << html_escape(h) << "</th>";
  o << "</tr>";
  for (const auto& r : s.rows) {
    o << "<tr>";
    for (const auto& c : r)
      o << "<td class='" << (c == "failed" || c == "passed" ? c : "") << "'>" << html_escape(c)
        << "</td>";
    o << "</tr>";
  }
  o << "</table>";
  return o.str();
}

std::string render_html(const std::vector<Section>& secs, const std::filesystem::path& dir) {
  std::ostringstream o;
  o << "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>pxflow "
       "report</title><style>"
       "body{font-family:sans-serif;max-width:1060px;margin:1em auto;padding:0 1em;color:#222}"
       "h1{margin:0.2em 0}table{border-collapse:collapse;margin:0.6em 0}"
       "td,th{border:1px solid #ccc;padding:3px 8px;font-size:13px;vertical-align:top}"
       "p{font-size:14px;line-height:1.4}th{background:#f0f0f0}code{background:#f4f4f4;padding:1px "
       "4px}"
       "td.failed{color:#b00;font-weight:bold}td.passed{color:#070}"
       "td:first-child{white-space:nowrap}"
       ".first td,.first th{font-size:12px;padding:2px 6px}.first p{font-size:13px;margin:0.3em 0}"
       ".first h2{font-size:16px;margin:0.5em 0 0.2em}"
       "</style></head><body><h1>pxflow report</h1>";
  bool first_screen = true;
  for (const auto& s : secs) {
    const bool first = s.key.starts_with("provenance") || s.key == "backends";
    if (first_screen && !first) {
      o << "</div>";
      first_screen = false;
    }
    if (first && s.key == "provenance") o << "<div class='first'>";
    o << "<h2 id='" << html_escape(s.key) << "'>" << html_escape(s.title) << "</h2><p>"
      << html_text(s.text) << "</p>";
    for (const auto& c : s.charts) o << "<div>" << svg_chart(c) << "</div>";
    for (const auto& p : s.pictures)  // inlined, so the page stays one self-contained file
      o << "<figure><img alt='" << html_escape(p.caption)
        << "' style='max-width:100%' src='data:image/png;base64,"
        << base64(read_own_output((dir / p.file).string())) << "'><figcaption>"
        << html_escape(p.caption) << "</figcaption></figure>";
    if (!s.rows.empty()) o << html_table(s);
  }
  if (first_screen) o << "</div>";
  o << "</body></html>\n";
  return o.str();
}

Json section_json(const Section& s) {
  Json charts = Json::array();
  for (const auto& c : s.charts) charts.push_back(report::chart_json(c));
  Json pictures = Json::array();
  for (const auto& p : s.pictures) pictures.push_back({{"caption", p.caption}, {"file", p.file}});
  return {{"key", s.key},   {"title", s.title}, {"text", s.text},      {"header", s.header},
          {"rows", s.rows}, {"charts", charts}, {"pictures", pictures}};
}

// The files write_report() writes (the pictures aside).
const std::vector<std::string>& report_file_names() {
  static const std::vector<std::string> names{"report.md",   "report.html",     "results.json",
                                              "results.csv", "conformance.csv", "accuracy.csv"};
  return names;
}

}  // namespace

void write_stopped_manifest(ReportOutputs& out, const std::vector<std::string>& kept) {
  std::vector<std::string> names = out.previous;
  for (const std::string& name : kept)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  out.files[kManifest]->write(manifest_text(names));
}

std::size_t registry_rank(const std::string& backend) {
  const auto& rows = backend_rows();
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].name == backend) return i;
  return rows.size();
}

ReportOutputs plan_report(OutputPlan& plan, const std::string& out_dir,
                          const std::vector<std::string>& pictures) {
  namespace fs = std::filesystem;
  plan.make_folder("--out", out_dir, kManifest);
  ReportOutputs out;
  out.dir = out_dir;
  for (const std::string& name : report_file_names())
    out.files[name] = &plan.file("--out", (fs::path(out_dir) / name).string());
  out.files[kManifest] = &plan.file("--out", (fs::path(out_dir) / kManifest).string());
  for (const std::string& name : pictures)
    out.pictures[name] = &plan.file("--out", (fs::path(out_dir) / name).string());
  out.previous = manifest_names(out_dir, kManifest);
  return out;
}

namespace {

// The throughput, scaling and custom-point sections of the report's bench.
void add_bench_sections(const ReportInputs& in, bool several, std::vector<Section>& secs) {
  report::MachineTag tag;  // a report of one machine stays uncluttered
  if (several && !in.bench_files.empty())
    tag = {" — " + in.bench_files.front().label + ": " + file_machine(in.bench_files.front()),
           " — " + file_machine(in.bench_files.front())};
  secs.push_back(report::throughput(in.bench, in.bench_command, tag));
  // A bench of its own points (custom) ran none of the default sweeps: its points are shown
  // whole, and no sweep is said to be left out.
  const bool custom = report::has_sweep(in.bench, "custom");
  for (const char* sweep : {"batch", "size", "radius", "threads"})
    if (!custom || report::has_sweep(in.bench, sweep))
      secs.push_back(report::scaling(in.bench, sweep, tag));
  for (Section& s : report::custom_points(in.bench, tag)) secs.push_back(std::move(s));
  secs.push_back(report::bound_section(in.bench, tag));
}

// The comparison of the bench files (two at least): its sections, and its JSON for results.json.
Json add_comparison_sections(const ReportInputs& in, bool several, std::vector<Section>& secs) {
  // A report is where hardware is compared: files of other machines are what it is for.
  const BenchComparison c = compare_bench_files(in.bench_files, {.across_machines = true});
  for (Section& s : report::comparison_sections(in.bench_files, c, several))
    secs.push_back(std::move(s));
  return comparison_json(c);
}

// results.json but its "commands" (a placeholder here) and "sections", and the CLI extensions'
// parts (write_report fills them in).
Json results_json(const ReportInputs& in, const Json& build, const Json& machine,
                  const Json& comparison) {
  Json pictures = Json::array();
  for (const auto& p : in.pictures) pictures.push_back({{"caption", p.caption}, {"file", p.file}});
  return {{"schema", "pxflow-report"},
          {"schema_version", 1},
          {"provenance",
           {{"build", build},
            {"machine", machine},
            {"backends", in.backends},
            {"backends_source", in.backends_source},
            {"measured_here", in.measured_here},
            {"bench_files", report::bench_files_json(in.bench_files)}}},
          {"commands", nullptr},
          {"check", in.check},
          {"bench", in.bench},
          {"comparison", comparison},
          {"accuracy", in.accuracy.empty()
                           ? Json()
                           : Json{{"command", in.accuracy_command}, {"rows", in.accuracy_rows}}},
          {"pictures", pictures}};
}

// The report's files, its manifest, and the previous run's files this one did not write removed.
void write_report_files(ReportOutputs& out, const ReportInputs& in,
                        const std::vector<Section>& secs, const Json& results) {
  const std::filesystem::path dir(out.dir);
  out.files["report.md"]->write(render_md(secs));
  out.files["report.html"]->write(render_html(secs, dir));
  out.files["results.json"]->write(json_document(results));
  out.files["results.csv"]->write(bench_csv(in.bench));
  out.files["conformance.csv"]->write(conformance_csv(in.check));
  out.files["accuracy.csv"]->write(accuracy_csv(in.accuracy_rows));
  std::vector<std::string> written = report_file_names();
  for (const auto& p : in.pictures) written.push_back(p.file);
  out.files[kManifest]->write(manifest_text(written));
  std::vector<std::string> may_write;
  for (const auto& [name, file] : out.files) may_write.push_back(name);
  for (const auto& [name, file] : out.pictures) may_write.push_back(name);
  remove_unwritten(out.dir, out.previous, may_write, written);
}

}  // namespace

void write_report(ReportOutputs& out, const ReportInputs& in) {
  const Json build = build_provenance();
  const Json machine = machine_provenance();
  std::vector<Section> secs{report::provenance(in, build, machine)};
  for (const BenchFile& f : in.bench_files)  // the first file's backends: the backends section's
    secs.push_back(report::bench_file_provenance(f, &f == &in.bench_files.front()));
  secs.push_back(report::backends_section(in));
  if (!in.check.is_null()) secs.push_back(report::conformance(in.check, in.check_command));
  const bool several = report::several_machines(in, machine);
  if (!in.bench.is_null()) add_bench_sections(in, several, secs);
  Json comparison;
  if (in.bench_files.size() >= 2) comparison = add_comparison_sections(in, several, secs);
  if (!in.accuracy.empty()) secs.push_back(report::accuracy(in));
  Json commands{{"report", in.report_command},
                {"check", in.check_command.empty() ? Json() : Json(in.check_command)},
                {"bench", in.bench_command.empty() ? Json() : Json(in.bench_command)},
                {"accuracy", in.accuracy_command.empty() ? Json() : Json(in.accuracy_command)}};
  Json results = results_json(in, build, machine, comparison);
  for (const auto& s : in.sections) {  // a family's (the GAP8 model beside the paper's tables)
    for (std::size_t i = 0; i < s.tables.size(); ++i) {
      const auto& t = s.tables[i];
      secs.push_back(
          {s.key + "-" + std::to_string(i + 1), t.title, t.text, t.header, t.rows, t.charts, {}});
    }
    commands[s.key] = s.command;
    results[s.key] = s.data;
  }
  results["commands"] = commands;
  results["sections"] = Json::array();
  for (const auto& s : secs) results["sections"].push_back(section_json(s));
  write_report_files(out, in, secs, results);
}

}  // namespace pxflow
