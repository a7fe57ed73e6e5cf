// Minimal inline-SVG charts for the self-contained HTML report: no scripts, no network. Every
// series has a colour and a marker of its own (backend_style: one per registry row, the same in
// every chart), and every axis is labelled at enough ticks to read a value off it.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace pxflow {

struct ChartStyle {
  std::string colour;  // "#rrggbb"
  std::string marker;  // "circle", "square", "triangle", "diamond", "down", "cross", "plus"
  bool dashed = false;
};

// The style of the index-th registry row: its own colour (a 20-colour palette of high mutual
// contrast) and marker; indices past the palette reuse colours with another marker.
ChartStyle backend_style(std::size_t index);

// A reference line (the ideal, a bound): grey, dashed, no marker.
ChartStyle reference_style();

struct Series {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y); a 0 or less makes its log axis linear
  ChartStyle style;
};

struct Bar {
  std::string label;
  double value = 0;  // a 0 or less makes the log axis linear
  ChartStyle style;
};

struct Axis {
  std::string label;
  bool log = true;       // log10 scale, else linear
  bool integer = false;  // linear: whole-number ticks only (cores, threads, S)
};

// A line chart (series) or a horizontal bar chart (bars; x is the value axis), never both.
struct Chart {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  std::vector<Bar> bars;
  std::string unit;  // the bars' values, e.g. "frames/s"
  bool empty() const { return series.empty() && bars.empty(); }
};

std::string svg_chart(const Chart& chart);

// Tick values for an axis spanning [lo, hi]: decades with 2 and 5 between them on a log axis
// spanning up to three decades (1, 2, 5, 10, 20, ...), every decade beyond; 1-2-5 steps on a
// linear one (at least 1 when `integer`). Exposed for the tests.
std::vector<double> axis_ticks(double lo, double hi, bool log, bool integer = false);

// The range an axis shows for data in [lo, hi]: the 1-2-5 ticks around it on a log axis; on a
// linear one the step multiples around it, from 0 when lo >= 0 and the data start near 0.
std::pair<double, double> axis_range(double lo, double hi, bool log, bool integer = false);

// Escapes &, <, > and quotes for HTML/SVG text.
std::string html_escape(const std::string& s);

}  // namespace pxflow
