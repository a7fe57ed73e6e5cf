#include "help_sections.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include "registry.hpp"
#include "shard_auto.hpp"

namespace pxflow::cli {

namespace {

// The variables read outside any family (hosts/io/opencv_module.cpp, hosts/core/interrupt.cpp;
// check --shard auto's are shard_auto.cpp's).
const std::vector<EnvironmentVariable> kCoreEnvironment = {
    {"PXFLOW_OPENCV_MODULE",
     "The OpenCV module to load (libpxflow_opencv.so, needed to decode images and video) "
     "instead of the one beside pxflow or in ../lib/pxflow"},
    {"PXFLOW_BENCH_PLANTED_SLOWDOWN",
     "A whole percent P in 1..100: bench runs P % more batches than it counts (known work per "
     "frame, never a sleep): the planted slowdown of the gate's A/B experiment "
     "(ci/gate_error_rates.py)"},
    {"PXFLOW_STOP_GRACE_MS",
     "Milliseconds after a first SIGINT, SIGTERM or SIGHUP in which another is the same stop "
     "(default 1000); a later one ends the run at once, keeping the streams' whole records; 0: "
     "any second signal does"}};

constexpr std::size_t kWidth = 100;

// "  TERM  text..." with the text wrapped at kWidth, its lines aligned under the first one
// (help2man reads the indented lines as one paragraph).
std::string term_paragraph(const std::string& term, std::size_t term_width,
                           const std::string& text) {
  const std::size_t indent = 2 + term_width + 2;
  std::string out = "  " + term + std::string(term_width - term.size() + 2, ' ');
  std::size_t column = indent;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (column > indent && column + 1 + word.size() > kWidth) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    } else if (column > indent) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    start = end + 1;
  }
  return out + "\n";
}

// Every variable once, in name order; a variable read by several families gets every use.
std::vector<EnvironmentVariable> environment() {
  std::vector<EnvironmentVariable> all = kCoreEnvironment;
  for (EnvironmentVariable& v : shard_environment()) all.push_back(std::move(v));
  for (const BackendFamily& f : backend_families())
    for (const EnvironmentVariable& v : f.environment) {
      auto same =
          std::find_if(all.begin(), all.end(), [&](const auto& a) { return a.name == v.name; });
      if (same == all.end())
        all.push_back(v);
      else  // "A; b": the second use continues the sentence
        same->help +=
            "; " + std::string(1, static_cast<char>(std::tolower(v.help[0]))) + v.help.substr(1);
    }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return all;
}

}  // namespace

std::string help_sections(const std::vector<std::string>& examples) {
  std::string text =
      "Exit status:\n" + term_paragraph("0", 3, "Success") +
      term_paragraph("1", 3,
                     "A check failed (or compared nothing but the reference), a backend or a "
                     "device failed, a bench timed nothing or found records that differ, compare "
                     "compared nothing or --fail-above found a slowdown, or a result could not be "
                     "written") +
      term_paragraph("2", 3,
                     "Bad input: one line on stderr names the file, option, key or backend; "
                     "found before any work, nothing is written (a bad frame in the middle of a "
                     "sequence stops it as below)") +
      term_paragraph("3", 3,
                     "compare --fail-above could not decide: no row failed, and a row's interval "
                     "held the threshold, or its files had one process or a disturbed machine") +
      term_paragraph("129", 3, "Stopped by SIGHUP (the terminal closed)") +
      term_paragraph("130", 3, "Stopped by SIGINT (Ctrl-C)") +
      term_paragraph("141", 3,
                     "Stopped by SIGPIPE: the reader of standard output went away (`| head`)") +
      term_paragraph("143", 3, "Stopped by SIGTERM") + "\n" +
      "After a stop no file is left half written: a whole file (--json, a report's) keeps its\n"
      "previous version; a sequence keeps its completed records in --jsonl and --csv, each file\n"
      "ending in an incomplete marker line (see pxflow flow --help). A second signal during the\n"
      "stop ends pxflow at once, keeping the same.\n\n";
  const auto variables = environment();
  std::size_t width = 0;
  for (const auto& v : variables) width = std::max(width, v.name.size());
  text += "Environment:\n";
  for (const auto& v : variables) text += term_paragraph(v.name, width, v.help);
  if (!examples.empty()) {
    text += "\nExamples:\n";
    for (const std::string& e : examples) text += "  $ pxflow " + e + "\n";
  }
  return text;
}

std::vector<std::string> first_examples(const std::vector<Command>& commands) {
  std::vector<std::string> examples;
  for (const Command& c : commands)
    if (!c.examples.empty()) examples.push_back(c.examples.front());
  return examples;
}

}  // namespace pxflow::cli
