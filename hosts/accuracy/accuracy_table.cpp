// The accuracy report as text: a Markdown table that reads as well on a terminal as in docs/.
#include <cstdio>

#include "accuracy_run.hpp"
#include "counted.hpp"

namespace pxflow::accuracy {
namespace {

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string pad(std::string s, std::size_t width) {
  // Count UTF-8 code points, not bytes, so that "µs" columns line up.
  std::size_t shown = 0;
  for (unsigned char c : s) shown += (c & 0xC0) != 0x80;
  if (shown < width) s.append(width - shown, ' ');
  return s;
}

std::string table_row(const std::vector<std::string>& cells,
                      const std::vector<std::size_t>& widths) {
  std::string line = "|";
  for (std::size_t i = 0; i < cells.size(); ++i) {
    line += ' ';
    line += pad(cells[i], widths[i]);
    line += " |";
  }
  line += '\n';
  return line;
}

}  // namespace

std::string format_accuracy(const AccuracyReport& r, const AccuracyOptions& o) {
  std::string images;
  for (const auto& name : r.images) images += (images.empty() ? "" : ", ") + name;
  std::string out = "pxflow accuracy: backend " + o.backend + ", seed " + std::to_string(o.seed) +
                    ", " + counted(o.threads, "thread") + " for OpenCV and the backend\n";
  out += "synthetic pairs from " + images + " (opencv-doc)\n";
  out +=
      "error = |estimated frame flow - reference| in pixels (Euclidean); time = median per frame, "
      "std::chrono::steady_clock, the three methods timed pair by pair in this run\n\n";
  const std::vector<std::string> head = {"pairs",         "pxflow setting", "against",
                                         "method",        "frames",         "with flow",
                                         "mean error px", "p95 error px",   "median µs/frame"};
  std::vector<std::vector<std::string>> rows;
  for (const auto& set : r.sets)
    for (const auto& m : set.rows)
      rows.push_back(
          {set.set, set.setting, set.against, m.method, std::to_string(m.frames),
           std::to_string(m.valid), m.has_error ? format("%.3f", m.mean_error) : "(reference)",
           m.has_error ? format("%.3f", m.p95_error) : "(reference)", format("%.0f", m.median_us)});
  std::vector<std::size_t> widths(head.size());
  for (std::size_t i = 0; i < head.size(); ++i) {
    widths[i] = head[i].size();
    for (const auto& row : rows) widths[i] = std::max(widths[i], row[i].size());
  }
  out += table_row(head, widths);
  std::vector<std::string> rule;
  for (auto w : widths) rule.push_back(std::string(w, '-'));
  out += table_row(rule, widths);
  for (const auto& row : rows) out += table_row(row, widths);
  return out;
}

}  // namespace pxflow::accuracy
