#include "report.hpp"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "errors.hpp"
#include "output_file.hpp"
#include "svg_chart.hpp"

namespace pxflow {
namespace {

// A report is a list of sections, rendered once as Markdown and once as HTML.
struct Section {
  std::string title, text;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::string svg;  // HTML only
  std::vector<ReportInputs::Picture> pictures;
};

std::string first_line_of(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key, 0) == 0) {
      auto v = line.substr(line.find_first_of(":=") + 1);
      v.erase(0, v.find_first_not_of(" \t\""));
      if (!v.empty() && v.back() == '"') v.pop_back();
      return v;
    }
  return "unknown";
}

Json machine() {
  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  return Json{{"cpu", first_line_of("/proc/cpuinfo", "model name")},
              {"cores", std::thread::hardware_concurrency()},
              {"os", first_line_of("/etc/os-release", "PRETTY_NAME")},
              {"host", host},
              {"date", date}};
}

std::string num(double v, const char* f = "%.1f") {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

Section conformance(const Json& check, const std::string& cmd) {
  Section s{"Conformance",
            "Every backend against `ref-original`, records byte for byte and flow by bits, on " +
                std::to_string(check.value("cases", 0)) + " cases (" +
                std::to_string(check.value("pairs", 0)) + " frame pairs), seed " +
                std::to_string(check.value("seed", 0)) + ". Command: `" + cmd + "`.",
            {"backend", "result", "cases passed", "cases failed", "n/a", "pairs", "note"},
            {},
            "",
            {}};
  for (const auto& b : check["backends"])
    s.rows.push_back({b["name"], b["state"], std::to_string(b["passed"].get<long>()),
                      std::to_string(b["failed"].get<long>()),
                      std::to_string(b["not_applicable"].get<long>()),
                      std::to_string(b["pairs"].get<long>()), b["reason"]});
  s.text += " Totals: " + std::to_string(check.value("passed", 0)) + " passed, " +
            std::to_string(check.value("failed", 0)) + " failed, " +
            std::to_string(check.value("skipped", 0)) + " skipped.";
  return s;
}

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

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

Section accuracy_section(const ReportInputs& in) {
  Section s{
      "Accuracy",
      "Frame flow against known motion (synthetic pairs) and agreement with OpenCV's DIS on real "
      "video, beside OpenCV's pyramidal Lucas-Kanade and DIS, timed in the same run. Command: `" +
          in.accuracy_command + "`; method details in docs/accuracy.md.",
      in.accuracy.front(),
      {in.accuracy.begin() + 1, in.accuracy.end()},
      "",
      in.pictures};
  return s;
}

bool timed(const Json& r) { return r.value("median_ns_per_frame", 0.0) > 0; }

Section throughput(const Json& bench, const std::string& cmd) {
  // The headline point: the batch sweep at 256 pairs, or the first point measured.
  const Json* pick = nullptr;
  for (const auto& r : bench["rows"])
    if (timed(r) && r["sweep"] == "batch" && r["batch"] == 256) pick = &r;
  if (!pick)
    for (const auto& r : bench["rows"])
      if (timed(r)) {
        pick = &r;
        break;
      }
  Section s{"Throughput",
            "",
            {"backend", "clock", "ns/frame (median)", "min..max", "frames/s", "ns/POI",
             "cycles/frame", "x bound", "vs ref-original"},
            {},
            "",
            {}};
  if (!pick) return s.text = "No timed rows.", s;
  auto same_point = [&](const Json& r) {
    return timed(r) && r["sweep"] == (*pick)["sweep"] && r["batch"] == (*pick)["batch"] &&
           r["width"] == (*pick)["width"] && r["search_radius"] == (*pick)["search_radius"] &&
           r["threads"] == (*pick)["threads"];
  };
  std::vector<std::pair<std::string, double>> bars;
  for (const auto& r : bench["rows"]) {
    if (!same_point(r)) continue;
    s.rows.push_back(
        {r["backend"], r["source"], num(r["median_ns_per_frame"], "%.0f"),
         num(r["min_ns_per_frame"], "%.0f") + ".." + num(r["max_ns_per_frame"], "%.0f"),
         num(r["frames_per_s"]), num(r["ns_per_poi"]),
         r.contains("cycles_per_frame") ? num(r["cycles_per_frame"], "%.0f") : "-",
         r.contains("bound_ratio") ? num(r["bound_ratio"], "%.2f") : "-",
         r.contains("speedup_vs_ref_original") ? num(r["speedup_vs_ref_original"], "%.2fx") : "-"});
    if (r["source"].get<std::string>().rfind("host", 0) == 0)
      bars.push_back({r["backend"], r["frames_per_s"]});
  }
  const std::string point = (*pick)["profile"].get<std::string>() + ", " +
                            std::to_string((*pick)["width"].get<int>()) + "x" +
                            std::to_string((*pick)["height"].get<int>()) + ", batch " +
                            std::to_string((*pick)["batch"].get<int>()) + ", " +
                            std::to_string((*pick)["threads"].get<int>()) + " threads";
  s.title += " (" + point + ")";
  s.text =
      "Median of repeated runs after a warm-up run whose records matched ref-original. Speed-ups "
      "compare rows of "
      "the same clock only. Command: `" +
      cmd + "`.";
  s.svg = svg_bar_chart("Frames per second, host clock (" + point + ")", bars, "frames/s");
  return s;
}

Section scaling(const Json& bench, const std::string& sweep, const std::string& title) {
  // One row per backend, one column per measured x (batch size or frame size).
  const bool by_batch = sweep == "batch";
  std::map<std::string, Series> by_backend;
  std::map<std::string, std::map<double, std::string>> cells;
  std::map<double, std::string> columns;
  for (const auto& r : bench["rows"]) {
    if (!timed(r) || r["sweep"] != sweep || r["source"].get<std::string>().rfind("host", 0) != 0)
      continue;
    const double x =
        by_batch ? r["batch"].get<double>() : r["width"].get<double>() * r["height"].get<double>();
    columns[x] = by_batch ? std::to_string(r["batch"].get<int>())
                          : std::to_string(r["width"].get<int>()) + "x" +
                                std::to_string(r["height"].get<int>());
    const double y = by_batch ? r["frames_per_s"].get<double>() : r["ns_per_poi"].get<double>();
    auto& se = by_backend[r["backend"]];
    se.name = r["backend"];
    se.points.push_back({x, y});
    cells[r["backend"]][x] = num(y);
  }
  Section s{title, "", {"backend"}, {}, "", {}};
  if (cells.empty()) return s.text = "Not measured in this run.", s;
  for (const auto& [_, name] : columns) s.header.push_back((by_batch ? "batch " : "") + name);
  for (const auto& [backend, row] : cells) {
    std::vector<std::string> r{backend};
    for (const auto& [x, _] : columns) r.push_back(row.count(x) ? row.at(x) : "-");
    s.rows.push_back(r);
  }
  std::vector<Series> series;
  for (auto& [_, se] : by_backend) series.push_back(se);
  s.text = by_batch
               ? "Frames per second by batch size (host clock, same inputs for every backend)."
               : "Nanoseconds per POI by frame size (host clock, same inputs for every backend).";
  s.svg = by_batch ? svg_line_chart(title, series, "batch size (frame pairs per run)", "frames/s")
                   : svg_line_chart(title, series, "frame size (pixels)", "ns per POI");
  return s;
}

std::string render_md(const std::vector<Section>& secs, const std::string& intro) {
  std::ostringstream o;
  o << "# pxflow report\n\n" << intro << "\n";
  for (const auto& s : secs) {
    o << "\n## " << s.title << "\n\n" << s.text << "\n";
    for (const auto& p : s.pictures) o << "\n![" << p.caption << "](" << p.file << ")\n";
    if (s.rows.empty()) continue;
    o << "\n|";
    for (const auto& h : s.header) o << " " << h << " |";
    o << "\n|";
    for (std::size_t i = 0; i < s.header.size(); ++i) o << "---|";
    for (const auto& r : s.rows) {
      o << "\n|";
      for (const auto& c : r) o << " " << c << " |";
    }
    o << "\n";
  }
  return o.str();
}

std::string render_html(const std::vector<Section>& secs, const std::string& intro,
                        const std::filesystem::path& dir) {
  std::ostringstream o;
  o << "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>pxflow "
       "report</title><style>"
       "body{font-family:sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;color:#222}"
       "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px "
       "8px;font-size:13px}"
       "th{background:#f0f0f0}code{background:#f4f4f4;padding:1px "
       "4px}td.failed{color:#b00;font-weight:bold}"
       "td.passed{color:#070}</style></head><body><h1>pxflow report</h1><p>"
    << html_escape(intro) << "</p>";
  for (const auto& s : secs) {
    o << "<h2>" << html_escape(s.title) << "</h2><p>" << html_escape(s.text) << "</p>" << s.svg;
    for (const auto& p : s.pictures)  // inlined, so the page stays one self-contained file
      o << "<figure><img alt='" << html_escape(p.caption)
        << "' style='max-width:100%' src='data:image/png;base64," << base64(slurp(dir / p.file))
        << "'><figcaption>" << html_escape(p.caption) << "</figcaption></figure>";
    if (s.rows.empty()) continue;
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
  }
  o << "</body></html>\n";
  return o.str();
}

std::string csv(const Json& bench) {
  const char* cols[] = {"backend",
                        "sweep",
                        "profile",
                        "width",
                        "height",
                        "search_radius",
                        "batch",
                        "threads",
                        "source",
                        "repeats",
                        "median_ns_per_frame",
                        "min_ns_per_frame",
                        "max_ns_per_frame",
                        "frames_per_s",
                        "ns_per_poi",
                        "cycles_per_frame",
                        "bound_ratio",
                        "speedup_vs_ref_original",
                        "note"};
  std::ostringstream o;
  for (std::size_t i = 0; i < std::size(cols); ++i) o << (i ? "," : "") << cols[i];
  o << "\n";
  if (bench.is_null()) return o.str();
  for (const auto& r : bench["rows"]) {
    for (std::size_t i = 0; i < std::size(cols); ++i) {
      o << (i ? "," : "");
      if (!r.contains(cols[i])) continue;
      const auto& v = r[cols[i]];
      o << (v.is_string() ? "\"" + v.get<std::string>() + "\"" : v.dump());
    }
    o << "\n";
  }
  return o.str();
}

void write_file(const std::filesystem::path& p, const std::string& text) {
  write_output_file(p.string(), text);
}

}  // namespace

constexpr const char* kManifest = ".pxflow-report";

void prepare_report_dir(const std::string& out_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir))
    throw InputError("--out " + out_dir + ": cannot create the folder");
}

void remove_previous_report(const std::string& out_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::ifstream manifest(fs::path(out_dir) / kManifest);
  for (std::string name; std::getline(manifest, name);) {
    // Only plain file names the report itself writes: never a path, never anything else.
    if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..")
      continue;
    const fs::path f = fs::path(out_dir) / name;
    if (fs::is_regular_file(fs::symlink_status(f, ec))) fs::remove(f, ec);
  }
}

void write_report(const std::string& out_dir, const ReportInputs& in) {
  std::error_code ec;
  if (!std::filesystem::is_directory(out_dir, ec))
    throw InputError("--out " + out_dir + ": no such folder (prepare_report_dir first)");
  const Json m = machine();
  const std::string intro = "Made by `" + in.report_command + "` on " +
                            m["host"].get<std::string>() + " (" + m["cpu"].get<std::string>() +
                            ", " + std::to_string(m["cores"].get<unsigned>()) + " cores, " +
                            m["os"].get<std::string>() + ") at " + m["date"].get<std::string>() +
                            ". Raw data: results.json and results.csv beside this file.";
  std::vector<Section> secs;
  if (!in.check.is_null()) secs.push_back(conformance(in.check, in.check_command));
  if (!in.bench.is_null()) {
    secs.push_back(throughput(in.bench, in.bench_command));
    secs.push_back(scaling(in.bench, "batch", "Scaling with batch size"));
    secs.push_back(scaling(in.bench, "size", "Scaling with frame size"));
  }
  if (!in.accuracy.empty()) secs.push_back(accuracy_section(in));
  Json commands{
      {"check", in.check_command}, {"bench", in.bench_command}, {"report", in.report_command}};
  Json results{{"machine", m}, {"commands", nullptr}, {"check", in.check}, {"bench", in.bench}};
  for (const auto& s : in.sections) {
    for (const auto& t : s.tables) secs.push_back({t.title, t.text, t.header, t.rows, t.svg, {}});
    commands[s.key] = s.command;
    results[s.key] = s.data;
  }
  results["commands"] = commands;
  const std::filesystem::path dir(out_dir);
  write_file(dir / "report.md", render_md(secs, intro));
  write_file(dir / "report.html", render_html(secs, intro, dir));
  write_file(dir / "results.json", results.dump(2) + "\n");
  write_file(dir / "results.csv", csv(in.bench));
  std::string manifest = "report.md\nreport.html\nresults.json\nresults.csv\n";
  for (const auto& p : in.pictures) manifest += p.file + "\n";
  write_file(dir / kManifest, manifest);
}

}  // namespace pxflow
