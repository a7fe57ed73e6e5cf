// Minimal inline-SVG charts for the self-contained HTML report: no scripts, no network.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace pxflow {

struct Series {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), y > 0
};

// Horizontal bars, one per label, on a log scale (values span orders of magnitude).
std::string svg_bar_chart(const std::string& title,
                          const std::vector<std::pair<std::string, double>>& bars,
                          const std::string& unit);

// Lines on log-log axes.
std::string svg_line_chart(const std::string& title, const std::vector<Series>& series,
                           const std::string& x_label, const std::string& y_label);

// Escapes &, <, > and quotes for HTML/SVG text.
std::string html_escape(const std::string& s);

}  // namespace pxflow
