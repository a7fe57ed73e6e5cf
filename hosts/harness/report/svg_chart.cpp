#include "svg_chart.hpp"

#include <algorithm>
#include <cmath>

#include "number_text.hpp"

namespace pxflow {
namespace {

// Nine well-separated hues (tab10 without its grey, which reference lines use), then two groups
// of four strong colours that differ from those nine and among themselves (navy, dark orange,
// lime, violet; black, gold, teal, magenta), then three light ones. In this build's registry
// order the nine CPU rows take the hues, the four GAP8 rows (charted together, by their own
// clock) the first group, OpenCL and Vulkan the second: every backend has a colour of its own.
const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                          "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#000080",
                          "#b35900", "#7fbf00", "#8000ff", "#000000", "#f3c300",
                          "#008080", "#ff00ff", "#9c9ede", "#e7969c", "#8ca252"};
const char* kMarkers[] = {"circle", "square", "triangle", "diamond", "down", "cross", "plus"};

// A tick label: 3 significant digits at most, with k/M/G (0.5, 2, 50, 200, 5k, 1.2M).
std::string si(double v) {
  const char* units[] = {"", "k", "M", "G", "T"};
  int u = 0;
  while (std::fabs(v) >= 1000 && u < 4) v /= 1000, ++u;
  std::string s = formatted("%.3g", v);
  return s + units[u];
}

// The 1-2-5 value at or below (down) / at or above v > 0.
double nice(double v, bool down) {
  const double decade = std::pow(10, std::floor(std::log10(v)));
  const double steps[] = {1, 2, 5, 10};
  if (down) {
    for (int i = 3; i >= 0; --i)
      if (steps[i] * decade <= v * (1 + 1e-9)) return steps[i] * decade;
    return decade;
  }
  for (double s : steps)
    if (s * decade >= v * (1 - 1e-9)) return s * decade;
  return 10 * decade;
}

// A linear axis's step: 1, 2 or 5 times a power of ten, giving 4 to 10 ticks.
double linear_step(double span, bool integer) {
  const double step = span > 0 ? nice(span / 6, false) : 1;
  return integer ? std::max(1.0, step) : step;
}

std::string marker_svg(const std::string& marker, double x, double y, const std::string& c) {
  auto pts = [&](std::initializer_list<std::pair<double, double>> offsets) {
    std::string p;
    for (auto [dx, dy] : offsets) p += formatted("%.1f,", x + dx) + formatted("%.1f ", y + dy);
    return "<polygon points='" + p + "' fill='" + c + "'/>";
  };
  auto stroke = [&](double x1, double y1, double x2, double y2) {
    return "<line x1='" + formatted("%.1f", x + x1) + "' y1='" + formatted("%.1f", y + y1) +
           "' x2='" + formatted("%.1f", x + x2) + "' y2='" + formatted("%.1f", y + y2) +
           "' stroke='" + c + "' stroke-width='2'/>";
  };
  if (marker == "square")
    return "<rect x='" + formatted("%.1f", x - 3.5) + "' y='" + formatted("%.1f", y - 3.5) +
           "' width='7' height='7' fill='" + c + "'/>";
  if (marker == "triangle") return pts({{0, -4.5}, {4, 3}, {-4, 3}});
  if (marker == "down") return pts({{0, 4.5}, {4, -3}, {-4, -3}});
  if (marker == "diamond") return pts({{0, -5}, {4, 0}, {0, 5}, {-4, 0}});
  if (marker == "cross") return stroke(-4, -4, 4, 4) + stroke(-4, 4, 4, -4);
  if (marker == "plus") return stroke(-5, 0, 5, 0) + stroke(0, -5, 0, 5);
  if (marker.empty()) return "";
  return "<circle cx='" + formatted("%.1f", x) + "' cy='" + formatted("%.1f", y) +
         "' r='3.5' fill='" + c + "'/>";
}

std::string text(double x, double y, const std::string& s, const char* extra = "") {
  return "<text x='" + formatted("%.1f", x) + "' y='" + formatted("%.1f", y) + "' font-size='11' " +
         extra + ">" + html_escape(s) + "</text>";
}

// About how many pixels `s` takes at `font_px` (sans-serif): code points, not UTF-8 bytes.
int text_px(const std::string& s, double font_px) {
  int chars = 0;
  for (char ch : s) chars += (static_cast<unsigned char>(ch) & 0xc0) != 0x80;
  return static_cast<int>(chars * font_px * 0.56) + 1;
}

// Room for the longest of `names` at 12 px, at least `least` pixels.
template <class Items, class Name>
int room_for(const Items& items, Name name, int least) {
  int px = least;
  for (const auto& item : items) px = std::max(px, text_px(name(item), 12) + 46);
  return px;
}

// The chart's SVG element, at least as wide as its title; it scales down to the page's width
// (viewBox), so that a long legend (a series per machine) never runs off the page.
std::string open_svg(const Chart& c, int width, int height) {
  width = std::max(width, text_px(c.title, 14) + 20);
  const std::string w = std::to_string(width), h = std::to_string(height);
  return "<svg xmlns='http://www.w3.org/2000/svg' width='" + w + "' height='" + h +
         "' viewBox='0 0 " + w + " " + h +
         "' style='max-width:100%;height:auto' role='img'><title>" + html_escape(c.title) +
         "</title><text x='10' y='20' font-weight='bold' font-size='14'>" + html_escape(c.title) +
         "</text>";
}

// Maps a value onto [p0, p1] pixels of an axis showing [lo, hi].
struct Scale {
  double lo, hi, p0, p1;
  bool log;
  double operator()(double v) const {
    const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                         : (v - lo) / (hi - lo);
    return p0 + t * (p1 - p0);
  }
};

// `chart` with each log axis whose values include one a log scale cannot place (0 or less)
// drawn linear instead.
Chart drawable(const Chart& chart) {
  Chart c = chart;
  for (const Bar& b : c.bars) c.x.log = c.x.log && b.value > 0;
  for (const auto& se : c.series)
    for (auto [x, y] : se.points) c.x.log = c.x.log && x > 0, c.y.log = c.y.log && y > 0;
  return c;
}

std::string bar_chart(const Chart& chart) {
  const Chart c = drawable(chart);
  const int left = room_for(
                       c.bars, [](const Bar& b) { return b.label; }, 184) -
                   34;
  const int width = 620, bar_h = 22, top = 40;
  const int height = top + static_cast<int>(c.bars.size()) * bar_h + 45;
  std::string s = open_svg(c, left + width + 120, height);
  double lo = 1e300, hi = 0;
  for (const Bar& b : c.bars) lo = std::min(lo, b.value), hi = std::max(hi, b.value);
  const auto [a, b] = axis_range(c.x.log ? lo : 0, hi, c.x.log, c.x.integer);
  const Scale X{a, b, double(left), double(left + width), c.x.log};
  const int axis_y = height - 40;
  for (double t : axis_ticks(a, b, c.x.log, c.x.integer))
    s += "<line x1='" + formatted("%.1f", X(t)) + "' y1='" + std::to_string(top - 5) + "' x2='" +
         formatted("%.1f", X(t)) + "' y2='" + std::to_string(axis_y) + "' stroke='#ddd'/>" +
         text(X(t), axis_y + 14, si(t), "text-anchor='middle'");
  s += text(left + width / 2.0, axis_y + 30, c.x.label, "text-anchor='middle' font-size='12'");
  for (std::size_t i = 0; i < c.bars.size(); ++i) {
    const Bar& bar = c.bars[i];
    const int y = top + static_cast<int>(i) * bar_h;
    const double w = std::max(1.0, X(bar.value) - left);
    s += text(left - 6, y + 15, bar.label, "text-anchor='end' font-size='12'") + "<rect x='" +
         std::to_string(left) + "' y='" + std::to_string(y + 3) + "' width='" +
         formatted("%.1f", w) + "' height='" + std::to_string(bar_h - 6) + "' fill='" +
         bar.style.colour + "'/>" +
         marker_svg(bar.style.marker, left + w + 7, y + 11, bar.style.colour) +
         text(left + w + 15, y + 15, si(bar.value) + " " + c.unit);
  }
  return s + "</svg>";
}

std::string line_chart(const Chart& chart) {
  const Chart c = drawable(chart);
  const int left = 70, top = 40, w = 540, h = 300;
  const int legend = room_for(
      c.series, [](const Series& se) { return se.name; }, 190);
  std::string s = open_svg(c, left + w + legend, top + h + 50);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& se : c.series)
    for (auto [x, y] : se.points)
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  const auto [xa, xb] = axis_range(x0, x1, c.x.log, c.x.integer);
  const auto [ya, yb] = axis_range(y0, y1, c.y.log, c.y.integer);
  const Scale X{xa, xb, double(left), double(left + w), c.x.log};
  const Scale Y{ya, yb, double(top + h), double(top), c.y.log};
  for (double t : axis_ticks(xa, xb, c.x.log, c.x.integer))
    s += "<line x1='" + formatted("%.1f", X(t)) + "' y1='" + std::to_string(top) + "' x2='" +
         formatted("%.1f", X(t)) + "' y2='" + std::to_string(top + h) + "' stroke='#ddd'/>" +
         text(X(t), top + h + 15, si(t), "text-anchor='middle'");
  for (double t : axis_ticks(ya, yb, c.y.log, c.y.integer))
    s += "<line x1='" + std::to_string(left) + "' y1='" + formatted("%.1f", Y(t)) + "' x2='" +
         std::to_string(left + w) + "' y2='" + formatted("%.1f", Y(t)) + "' stroke='#ddd'/>" +
         text(left - 5, Y(t) + 4, si(t), "text-anchor='end'");
  s += "<rect x='" + std::to_string(left) + "' y='" + std::to_string(top) + "' width='" +
       std::to_string(w) + "' height='" + std::to_string(h) + "' fill='none' stroke='#999'/>";
  s += text(left + w / 2.0, top + h + 35, c.x.label, "text-anchor='middle' font-size='12'");
  s += "<text x='14' y='" + std::to_string(top + h / 2) +
       "' font-size='12' transform='rotate(-90 14 " + std::to_string(top + h / 2) +
       ")' text-anchor='middle'>" + html_escape(c.y.label) + "</text>";
  for (std::size_t i = 0; i < c.series.size(); ++i) {
    const Series& se = c.series[i];
    auto sorted = se.points;
    std::sort(sorted.begin(), sorted.end());
    std::string pts;
    for (auto [x, y] : sorted) pts += formatted("%.1f,", X(x)) + formatted("%.1f ", Y(y));
    const std::string& col = se.style.colour;
    const std::string dash = se.style.dashed ? "' stroke-dasharray='6 4" : "";
    s += "<polyline fill='none' stroke='" + col + "' stroke-width='2" + dash + "' points='" + pts +
         "'/>";
    for (auto [x, y] : sorted) s += marker_svg(se.style.marker, X(x), Y(y), col);
    const double ly = top + 10 + static_cast<double>(i) * 18;
    const int lx = left + w + 12;
    s += "<line x1='" + std::to_string(lx) + "' y1='" + formatted("%.1f", ly) + "' x2='" +
         std::to_string(lx + 22) + "' y2='" + formatted("%.1f", ly) + "' stroke='" + col +
         "' stroke-width='2" + dash + "'/>" + marker_svg(se.style.marker, lx + 11, ly, col) +
         text(lx + 28, ly + 4, se.name, "font-size='12'");
  }
  return s + "</svg>";
}

}  // namespace

ChartStyle backend_style(std::size_t index) {
  const std::size_t colours = std::size(kColours);
  // Past the palette the colours repeat with the marker shifted, so the pair stays unique.
  return {kColours[index % colours], kMarkers[(index + index / colours) % std::size(kMarkers)],
          false};
}

ChartStyle reference_style() { return {"#888888", "", true}; }

std::pair<double, double> axis_range(double lo, double hi, bool log, bool integer) {
  if (log) {
    double a = nice(lo, true), b = nice(hi, false);
    if (a == b) a = nice(a * 0.99, true), b = nice(b * 1.01, false);
    return {a, b};
  }
  if (hi <= lo) lo -= 1, hi += 1;
  const double step = linear_step(hi - lo, integer);
  // From 0 when the data start within a third of their span of it (speed-ups, frames/s), else
  // from the step below the data (search radius 2..8, threads 1..2).
  const double a = lo >= 0 && lo <= (hi - lo) / 3 ? 0.0 : std::floor(lo / step) * step;
  return {a, std::ceil(hi / step) * step};
}

std::vector<double> axis_ticks(double lo, double hi, bool log, bool integer) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) return {lo};
  // A log axis needs lo > 0 (its decades start at 10^floor(log10(lo))): a zero or negative
  // value, which a log scale cannot place, gets the linear ticks instead of an endless loop.
  if (log && lo > 0) {
    const bool fine = std::log10(hi / lo) <= 3.01;
    for (double decade = std::pow(10, std::floor(std::log10(lo))); decade <= hi * (1 + 1e-9);
         decade *= 10)
      for (double m : {1.0, 2.0, 5.0}) {
        const double t = m * decade;
        if ((fine || m == 1.0) && t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) ticks.push_back(t);
      }
    return ticks;
  }
  const double step = linear_step(hi - lo, integer);
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step)
    ticks.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
  return ticks;
}

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
      case '\'':
        o += "&#39;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

std::string svg_chart(const Chart& c) {
  if (c.empty())
    return open_svg(c, 400, 60) + "<text x='10' y='45' font-size='12'>no data</text></svg>";
  return c.bars.empty() ? line_chart(c) : bar_chart(c);
}

}  // namespace pxflow
