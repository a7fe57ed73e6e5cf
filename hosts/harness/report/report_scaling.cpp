// The report's scaling sections: one sweep of the bench (batch, frame size, search radius,
// threads) as a table with a column per value and charts by clock.
#include <algorithm>
#include <map>
#include <set>

#include "report_rows.hpp"
#include "report_sections.hpp"

namespace pxflow::report {
namespace {

// What a sweep varies, how its x is named, and the figure it plots.
struct SweepInfo {
  const char* name;
  const char* title;
  const char* x_label;
  bool x_log;
  bool per_poi;  // ns per POI (frame size) instead of frames per second
};
constexpr SweepInfo kSweeps[] = {
    {"batch", "Scaling with batch size", "batch size (frame pairs per run)", true, false},
    {"size", "Scaling with frame size", "frame size (pixels)", true, true},
    {"radius", "Scaling with search radius", "search radius S (pixels)", false, false},
    {"threads", "Scaling with threads", "host threads (the model clock does not depend on them)",
     false, false},
};

double sweep_x(const SweepInfo& s, const Json& r) {
  const std::string n = s.name;
  if (n == "batch") return r["batch"].get<double>();
  if (n == "size") return r["width"].get<double>() * r["height"].get<double>();
  if (n == "radius") return r["search_radius"].get<double>();
  return r["threads"].get<double>();
}

std::string sweep_column(const SweepInfo& s, const Json& r) {
  const std::string n = s.name;
  if (n == "batch") return "batch " + std::to_string(r["batch"].get<int>());
  if (n == "size")
    return std::to_string(r["width"].get<int>()) + "x" + std::to_string(r["height"].get<int>());
  if (n == "radius") return "S=" + std::to_string(r["search_radius"].get<int>());
  return threads_text(r["threads"].get<int>());
}

// A row of the batch sweep that is the sweep's point at its default value (e.g. batch 256 at
// all cores, 64x64, S=4 for the radius sweep): the same problem but the swept parameter.
// For an exact-clock backend (`any_batch`), whose large batches are not simulated, any batch.
bool anchors(const SweepInfo& s, const Json& first, const Json& r, bool any_batch) {
  const std::string n = s.name;
  if (n == "batch" || r["sweep"] != "batch" || (!any_batch && r["batch"] != first["batch"]))
    return false;
  const bool size = r["width"] == first["width"] && r["height"] == first["height"];
  const bool radius = r["search_radius"] == first["search_radius"];
  const bool threads = r["threads"] == first["threads"];
  if (n == "size") return radius && threads;
  if (n == "radius") return size && threads;
  return size && radius;  // threads
}

// The point a sweep holds fixed, without the swept value.
std::string fixed_part(const SweepInfo& s, const Json& r) {
  const std::string n = s.name;
  std::string out = str(r, "profile");
  if (n != "size")
    out += ", " + std::to_string(r.value("width", 0)) + "x" + std::to_string(r.value("height", 0));
  if (n != "radius") out += ", S=" + std::to_string(r.value("search_radius", 0));
  if (n != "batch") out += ", batch " + std::to_string(r.value("batch", 0));
  if (n != "threads") out += ", " + threads_text(r.value("threads", 0));
  return out;
}

// The parameters that take more than one value among `rows`.
std::vector<const SweepInfo*> varied(const std::vector<const Json*>& rows) {
  std::vector<const SweepInfo*> out;
  for (const SweepInfo& s : kSweeps) {
    std::set<std::string> values;
    for (const Json* r : rows) values.insert(sweep_column(s, *r));
    if (values.size() > 1) out.push_back(&s);
  }
  return out;
}

// Whether each value of the parameter has an x of its own (two frame sizes of one area do not).
bool distinct_x(const SweepInfo& s, const std::vector<const Json*>& rows) {
  std::set<double> xs;
  std::set<std::string> values;
  for (const Json* r : rows) xs.insert(sweep_x(s, *r)), values.insert(sweep_column(s, *r));
  return xs.size() == values.size();
}

// A row per point and backend, in the bench's order (point by point, registry order within).
void points_table(Section& s, const Json& bench, const std::vector<const Json*>& rows) {
  s.header = {"backend", "point", "clock", "ns/frame (median)", "frames/s", "ns/POI", "note"};
  for (const Json* r : rows) {
    std::vector<std::string> row{str(*r, "backend"), point_name(*r), str(*r, "source")};
    if (!timed(*r))
      row.insert(row.end(), {"-", "-", "-"});
    else if (counts_instructions(bench, str(*r, "backend")))
      row.insert(row.end(), {instructions_cell(*r), "-", "-"});
    else
      row.insert(row.end(), {num((*r)["median_ns_per_frame"], "%.0f") +
                                 ((*r).value("noisy", false) ? " (noisy)" : ""),
                             num((*r)["frames_per_s"]), num((*r)["ns_per_poi"])});
    row.push_back(str(*r, "note"));
    s.rows.push_back(std::move(row));
  }
}

const SweepInfo* find_sweep(const std::string& name) {
  for (const SweepInfo& s : kSweeps)
    if (name == s.name) return &s;
  return nullptr;
}

// The backends with an exact clock: their untimed rows are charted with them too.
std::set<std::string> model_backends(const Json& bench) {
  std::set<std::string> models;
  for (const auto& r : bench["rows"])
    if (exact_clock(r)) models.insert(str(r, "backend"));
  return models;
}

// The sweep's point at its default value, from the batch sweep (`first`: the sweep's first
// row); for an exact-clock backend the largest batch it simulated there (its cycles per frame
// do not depend on the batch).
void add_anchor_rows(std::vector<const Json*>& rows, const Json& bench, const SweepInfo& info,
                     const Json& first, const std::set<std::string>& models) {
  std::map<std::string, const Json*> model_anchor;
  for (const auto& r : bench["rows"]) {
    const bool model = models.count(str(r, "backend")) > 0;
    if (!model && anchors(info, first, r, false)) rows.push_back(&r);
    if (model && timed(r) && anchors(info, first, r, true)) {
      const Json*& best = model_anchor[str(r, "backend")];
      if (!best || r["batch"].get<int>() > (*best)["batch"].get<int>()) best = &r;
    }
  }
  for (const auto& [_, r] : model_anchor) rows.push_back(r);
}

// One table row per backend and clock kind (device-clock rows time the kernel only: left to
// the CSV); one column per x.
struct Line {
  std::string label;
  bool model = false;
  bool charted = true;
  std::map<double, std::string> cells;
  std::set<std::string> notes;
  Series series;
  // The 95 % interval of each timed point's median, in ns per frame (or per POI): adjacent
  // points whose intervals overlap draw no trend (scaling_text says so).
  std::map<double, std::pair<double, double>> intervals;
};
struct SweepTable {
  std::map<double, std::string> columns;                      // by x: its header
  std::map<std::pair<std::size_t, std::string>, Line> lines;  // by registry rank and label
  bool any_uncharted() const {
    return std::any_of(lines.begin(), lines.end(),
                       [](const auto& kv) { return !kv.second.charted; });
  }
};

// Puts row `r` in its line's cell at its x: the figure, the instruction count, or why not timed.
void add_row(SweepTable& t, const SweepInfo& info, const Json& bench, const Json& r, bool model) {
  if (timed(r) && !model && !host_clock(r)) return;
  const std::string backend = str(r, "backend");
  const double x = sweep_x(info, r);
  t.columns[x] = sweep_column(info, r);
  const bool instructions = counts_instructions(bench, backend);
  const std::string label = backend + (instructions ? " (instruction count)"
                                       : model      ? " (model clock)"
                                                    : "");
  Line& l = t.lines[{registry_rank(backend), label}];
  l.label = label;
  l.model = model;
  l.charted = !instructions;
  l.series.name = backend;
  l.series.style = style_of(backend);
  if (!timed(r)) {
    const std::string note = str(r, "note");
    l.cells[x] = note.substr(0, note.find(':'));
    l.notes.insert(note);
    return;
  }
  if (instructions) {
    l.cells[x] = instructions_cell(r);
    return;
  }
  const double y = info.per_poi ? r["ns_per_poi"].get<double>() : r["frames_per_s"].get<double>();
  l.cells[x] = num(y) + (r.value("noisy", false) ? " (noisy)" : "");
  l.series.points.push_back({x, y});
  if (r.contains("median_ci_low_ns") && !model) {
    const double per = info.per_poi ? r["pois_per_frame"].get<double>() : 1.0;
    l.intervals[x] = {r["median_ci_low_ns"].get<double>() / per,
                      r["median_ci_high_ns"].get<double>() / per};
  }
}

// The header (a column per x, then the notes) and a row per line, "-" where it has no cell.
void put_table(Section& s, const SweepTable& t) {
  for (const auto& [_, name] : t.columns) s.header.push_back(name);
  s.header.push_back("note");
  for (const auto& [_, l] : t.lines) {
    std::vector<std::string> row{l.label};
    for (const auto& [x, __] : t.columns) row.push_back(l.cells.count(x) ? l.cells.at(x) : "-");
    std::string notes;
    for (const auto& n : l.notes) notes += (notes.empty() ? "" : "; ") + n;
    row.push_back(notes);
    s.rows.push_back(row);
  }
}

// The host clock's chart and the exact model clock's, apart; a chart without series is left out.
void put_charts(Section& s, const SweepInfo& info, const SweepTable& t, const MachineTag& tag) {
  const std::string y_label = info.per_poi ? "ns per POI (log scale)" : "frames/s (log scale)";
  Chart host, model;
  host.title = std::string(info.title) + ", host clock" + tag.title;
  model.title = std::string(info.title) + ", exact model clock (not the host)" + tag.title;
  for (Chart* c : {&host, &model}) {
    c->x = {info.x_label, info.x_log, !info.x_log};  // S and threads are whole numbers
    c->y = {y_label, true};
  }
  for (const auto& [_, l] : t.lines) {
    if (!l.charted || l.series.points.empty()) continue;
    Series series = l.series;
    series.name += tag.series;
    (l.model ? model : host).series.push_back(std::move(series));
  }
  if (!host.series.empty()) s.charts.push_back(host);
  if (!model.series.empty()) s.charts.push_back(model);
}

std::string scaling_text(const SweepInfo& info, const Json& first, const SweepTable& t) {
  std::string text =
      std::string(info.per_poi ? "Nanoseconds per POI" : "Frames per second") + " by " +
      info.x_label + ", at " + fixed_part(info, first) +
      "; the same inputs for every backend. Exact-clock rows (a deterministic cycle model) "
      "are charted "
      "apart, by the model's clock, from the pairs their note names. Cells that are not "
      "numbers say why (n/a: outside the backend's limits; not run: the note says how to run "
      "it).";
  if (t.any_uncharted()) text += kInstructionNote;
  // Which lines' neighbouring points cannot be told apart: their intervals overlap.
  std::string flat;
  for (const auto& [_, l] : t.lines) {
    for (auto it = l.intervals.begin();
         it != l.intervals.end() && std::next(it) != l.intervals.end(); ++it) {
      const auto& [lo1, hi1] = it->second;
      const auto& [lo2, hi2] = std::next(it)->second;
      if (std::max(lo1, lo2) > std::min(hi1, hi2)) continue;
      flat += (flat.empty() ? "" : ", ") + l.label + " (" + t.columns.at(it->first) + " to " +
              t.columns.at(std::next(it)->first) + ")";
    }
  }
  if (!flat.empty())
    text += " The 95 % intervals of the medians overlap between neighbouring points of " + flat +
            ": no trend can be read there, the difference is within the run's noise. Cells "
            "marked (noisy) had a wide spread (docs/harness.md, \"Statistics\").";
  return text;
}

}  // namespace

Section scaling(const Json& bench, const std::string& sweep, const MachineTag& tag) {
  const SweepInfo* info = find_sweep(sweep);
  Section s{
      "scaling-" + sweep, (info ? info->title : sweep) + tag.title, "", {"backend"}, {}, {}, {}};
  if (!info) return s;
  std::vector<const Json*> rows;
  for (const auto& r : bench["rows"])
    if (r["sweep"] == sweep) rows.push_back(&r);
  if (rows.empty()) {
    s.text = "Not part of this bench run: its command (see Provenance) left this sweep out.";
    return s;
  }
  const Json& first = *rows.front();
  const std::set<std::string> models = model_backends(bench);
  add_anchor_rows(rows, bench, *info, first, models);
  SweepTable table;
  for (const Json* r : rows) add_row(table, *info, bench, *r, models.count(str(*r, "backend")) > 0);
  put_table(s, table);
  s.text = scaling_text(*info, first, table);
  put_charts(s, *info, table, tag);
  return s;
}

bool has_sweep(const Json& bench, const std::string& sweep) {
  return std::any_of(bench["rows"].begin(), bench["rows"].end(),
                     [&](const Json& r) { return r["sweep"] == sweep; });
}

std::vector<Section> custom_points(const Json& bench, const MachineTag& tag) {
  std::vector<const Json*> rows;
  for (const auto& r : bench["rows"])
    if (r["sweep"] == "custom") rows.push_back(&r);
  const std::vector<const SweepInfo*> vary = varied(rows);
  std::set<std::string> points;
  for (const Json* r : rows) points.insert(point_name(*r));
  if (points.size() < 2) return {};  // one point: the throughput section shows it whole
  Section s{"scaling-custom", "The bench's points" + tag.title, "", {}, {}, {}, {}};
  const std::string intro =
      "Every point this bench measured, as its own command asked (bench --batch, --sizes, "
      "--radius, --thread-sweep; see Provenance): ";
  if (vary.size() != 1 || !distinct_x(*vary.front(), rows)) {
    points_table(s, bench, rows);
    std::string names;
    for (const SweepInfo* v : vary) names += (names.empty() ? "" : ", ") + std::string(v->name);
    s.text = intro + std::to_string(points.size()) + " points, over " + names +
             ": a row per point and backend, as a chart shows one varying parameter." +
             (std::any_of(rows.begin(), rows.end(),
                          [](const Json* r) { return counts_instructions(*r); })
                  ? kInstructionNote
                  : "");
    return {s};
  }
  const SweepInfo& info = *vary.front();
  const std::set<std::string> models = model_backends(bench);
  SweepTable table;
  for (const Json* r : rows) add_row(table, info, bench, *r, models.count(str(*r, "backend")) > 0);
  s.header = {"backend"};
  put_table(s, table);
  s.text = intro + scaling_text(info, *rows.front(), table);
  put_charts(s, info, table, tag);
  return {s};
}

}  // namespace pxflow::report
