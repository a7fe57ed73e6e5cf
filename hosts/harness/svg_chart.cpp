#include "svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pxflow {
namespace {

const char* kColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                          "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#393b79", "#637939"};

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string si(double v) {
  const char* units[] = {"", "k", "M", "G"};
  int u = 0;
  while (std::fabs(v) >= 1000 && u < 3) v /= 1000, ++u;
  return fmt(v < 10 ? "%.2g" : "%.0f", v) + units[u];
}

// Log-scale range covering [lo, hi], widened to whole decades.
std::pair<double, double> decades(double lo, double hi) {
  return {std::floor(std::log10(lo)),
          std::max(std::ceil(std::log10(hi)), std::floor(std::log10(lo)) + 1)};
}

}  // namespace

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

std::string svg_bar_chart(const std::string& title,
                          const std::vector<std::pair<std::string, double>>& bars,
                          const std::string& unit) {
  const int left = 150, width = 700, bar_h = 22, top = 40;
  const int height = top + static_cast<int>(bars.size()) * bar_h + 40;
  std::string s = "<svg xmlns='http://www.w3.org/2000/svg' width='" +
                  std::to_string(left + width + 90) + "' height='" + std::to_string(height) +
                  "' role='img'><title>" + html_escape(title) + "</title>";
  s += "<text x='10' y='20' font-weight='bold'>" + html_escape(title) + "</text>";
  if (bars.empty()) return s + "<text x='10' y='50'>no data</text></svg>";
  double lo = 1e300, hi = 0;
  for (const auto& [_, v] : bars) lo = std::min(lo, v), hi = std::max(hi, v);
  const auto [d0, d1] = decades(lo, hi);
  auto xpos = [&](double v) { return left + (std::log10(v) - d0) / (d1 - d0) * width; };
  for (double d = d0; d <= d1; ++d) {
    const double x = xpos(std::pow(10, d));
    s += "<line x1='" + fmt("%.1f", x) + "' y1='" + std::to_string(top - 5) + "' x2='" +
         fmt("%.1f", x) + "' y2='" + std::to_string(height - 30) + "' stroke='#ddd'/><text x='" +
         fmt("%.1f", x) + "' y='" + std::to_string(height - 15) +
         "' font-size='11' text-anchor='middle'>" + si(std::pow(10, d)) + "</text>";
  }
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const int y = top + static_cast<int>(i) * bar_h;
    const double w = std::max(1.0, xpos(bars[i].second) - left);
    s += "<text x='" + std::to_string(left - 6) + "' y='" + std::to_string(y + 15) +
         "' font-size='12' text-anchor='end'>" + html_escape(bars[i].first) + "</text><rect x='" +
         std::to_string(left) + "' y='" + std::to_string(y + 3) + "' width='" + fmt("%.1f", w) +
         "' height='" + std::to_string(bar_h - 6) + "' fill='" + kColours[i % 12] + "'/><text x='" +
         fmt("%.1f", left + w + 4) + "' y='" + std::to_string(y + 15) + "' font-size='11'>" +
         si(bars[i].second) + " " + html_escape(unit) + "</text>";
  }
  return s + "</svg>";
}

std::string svg_line_chart(const std::string& title, const std::vector<Series>& series,
                           const std::string& x_label, const std::string& y_label) {
  const int left = 70, top = 40, w = 560, h = 300, legend = 170;
  std::string s = "<svg xmlns='http://www.w3.org/2000/svg' width='" +
                  std::to_string(left + w + legend) + "' height='" + std::to_string(top + h + 50) +
                  "' role='img'><title>" + html_escape(title) + "</title>";
  s += "<text x='10' y='20' font-weight='bold'>" + html_escape(title) + "</text>";
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (const auto& se : series)
    for (auto [x, y] : se.points)
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  if (x1 <= 0 || y1 <= 0) return s + "<text x='10' y='50'>no data</text></svg>";
  const auto [dx0, dx1] = decades(x0, x1);
  const auto [dy0, dy1] = decades(y0, y1);
  auto X = [&](double x) { return left + (std::log10(x) - dx0) / (dx1 - dx0) * w; };
  auto Y = [&](double y) { return top + h - (std::log10(y) - dy0) / (dy1 - dy0) * h; };
  for (double d = dx0; d <= dx1; ++d)
    s += "<line x1='" + fmt("%.1f", X(std::pow(10, d))) + "' y1='" + std::to_string(top) +
         "' x2='" + fmt("%.1f", X(std::pow(10, d))) + "' y2='" + std::to_string(top + h) +
         "' stroke='#ddd'/><text x='" + fmt("%.1f", X(std::pow(10, d))) + "' y='" +
         std::to_string(top + h + 15) + "' font-size='11' text-anchor='middle'>" +
         si(std::pow(10, d)) + "</text>";
  for (double d = dy0; d <= dy1; ++d)
    s += "<line x1='" + std::to_string(left) + "' y1='" + fmt("%.1f", Y(std::pow(10, d))) +
         "' x2='" + std::to_string(left + w) + "' y2='" + fmt("%.1f", Y(std::pow(10, d))) +
         "' stroke='#ddd'/><text x='" + std::to_string(left - 5) + "' y='" +
         fmt("%.1f", Y(std::pow(10, d)) + 4) + "' font-size='11' text-anchor='end'>" +
         si(std::pow(10, d)) + "</text>";
  s += "<text x='" + std::to_string(left + w / 2) + "' y='" + std::to_string(top + h + 35) +
       "' font-size='12' text-anchor='middle'>" + html_escape(x_label) + "</text><text x='12' y='" +
       std::to_string(top + h / 2) + "' font-size='12' transform='rotate(-90 12 " +
       std::to_string(top + h / 2) + ")' text-anchor='middle'>" + html_escape(y_label) + "</text>";
  for (std::size_t i = 0; i < series.size(); ++i) {
    std::string pts;
    auto sorted = series[i].points;
    std::sort(sorted.begin(), sorted.end());
    for (auto [x, y] : sorted) pts += fmt("%.1f,", X(x)) + fmt("%.1f ", Y(y));
    const std::string c = kColours[i % 12];
    s += "<polyline fill='none' stroke='" + c + "' stroke-width='2' points='" + pts + "'/>";
    for (auto [x, y] : sorted)
      s += "<circle cx='" + fmt("%.1f", X(x)) + "' cy='" + fmt("%.1f", Y(y)) + "' r='3' fill='" +
           c + "'/>";
    const int ly = top + 10 + static_cast<int>(i) * 18;
    s += "<rect x='" + std::to_string(left + w + 15) + "' y='" + std::to_string(ly - 9) +
         "' width='12' height='12' fill='" + c + "'/><text x='" + std::to_string(left + w + 32) +
         "' y='" + std::to_string(ly + 1) + "' font-size='12'>" + html_escape(series[i].name) +
         "</text>";
  }
  return s + "</svg>";
}

}  // namespace pxflow
