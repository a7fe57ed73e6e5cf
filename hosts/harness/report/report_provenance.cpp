// The report's provenance: its own run, with this machine shown only for what the run measured
// itself; then one block per bench file, from the file's own provenance. A file's figures are
// named by the machine and build that measured them, never by the machine that wrote the report.
#include <set>

#include "counted.hpp"
#include "machine_state.hpp"
#include "provenance.hpp"
#include "report_rows.hpp"
#include "report_sections.hpp"

namespace pxflow::report {
namespace {

const Json& object_at(const Json& j, const char* key) {
  static const Json none = Json::object();
  return j.is_object() && j.contains(key) && j[key].is_object() ? j[key] : none;
}

std::string build_line(const Json& build) {
  return str(build, "version") + ", commit " + str(build, "commit") +
         (build.value("dirty", false) ? " (dirty: uncommitted changes)" : " (clean)");
}

void add_build_rows(Section& s, const Json& build) {
  s.rows.push_back({"pxflow", build_line(build)});
  s.rows.push_back({"compiler", str(build, "compiler") + ", " + str(build, "build_type") + ": " +
                                    str(build, "cxx_flags")});
}

void add_machine_rows(Section& s, const Json& machine) {
  s.rows.push_back(
      {"CPU", str(machine, "cpu") + ", " + counted(machine.value("cores", 0), "core")});
  s.rows.push_back({"system", str(machine, "os") + ", " + str(machine, "kernel") + ", host " +
                                  str(machine, "host") + ", " + str(machine, "date")});
}

// "host (CPU)", as file_machine() names a bench file's machine.
std::string machine_name(const Json& machine) {
  return str(machine, "host") + " (" + str(machine, "cpu") + ")";
}

// The bench's load row, and the warning for a disturbed machine or noisy rows ("" when none).
std::string add_load_row(Section& s, const Json& bench) {
  if (!bench.is_object() || !bench.contains("machine") || !bench["machine"].is_object()) return "";
  const MachineLoad m = machine_from_json(bench["machine"]);
  s.rows.push_back({"bench machine", machine_line(m)});
  long noisy = 0, timed_rows = 0;
  for (const auto& r : bench["rows"])
    if (timed(r)) ++timed_rows, noisy += r.value("noisy", false) ? 1 : 0;
  if (m.disturbed.empty() && noisy == 0) return "";
  return "**Warning: " +
         (m.disturbed.empty() ? std::string()
                              : "the bench ran on a disturbed machine (" + m.disturbed + "). ") +
         (noisy > 0
              ? counted(noisy, "timed row") + " of " + std::to_string(timed_rows) + " are noisy. "
              : "") +
         "Its figures may be slower and more scattered than the machine is: rerun the bench "
         "command on a quiet machine.** ";
}

std::string comma_list(const std::vector<std::string>& parts) {
  std::string s;
  for (const std::string& p : parts) s += (s.empty() ? "" : ", ") + p;
  return s;
}

}  // namespace

Section provenance(const ReportInputs& in, const Json& build, const Json& machine) {
  Section s{"provenance",
            "Provenance",
            "Where these results come from: the pxflow that wrote this report, and this machine "
            "for what the report measured itself (measured here); each bench file read has a "
            "block of its own below, from the file. Raw data: results.json (schema: "
            "docs/report-schema.md) and the CSV files beside this page.",
            {"what", "value"},
            {},
            {},
            {}};
  add_build_rows(s, build);
  if (in.measured_here.empty()) {
    s.rows.push_back({"measured here", "nothing: every result was read from a file"});
    s.rows.push_back({"written", str(machine, "date")});
  } else {
    s.rows.push_back({"measured here", comma_list(in.measured_here) + " (on this machine)"});
    add_machine_rows(s, machine);
  }
  s.rows.push_back({"report", in.report_command});
  if (!in.check_command.empty()) s.rows.push_back({"check", in.check_command});
  if (!in.bench_command.empty()) s.rows.push_back({"bench", in.bench_command});
  if (!in.accuracy_command.empty()) s.rows.push_back({"accuracy", in.accuracy_command});
  for (const auto& sec : in.sections) s.rows.push_back({sec.key, sec.command});
  if (in.bench_files.empty()) s.text = add_load_row(s, in.bench) + s.text;
  return s;
}

Section bench_file_provenance(const BenchFile& f, bool backends_shown) {
  const Json& p = object_at(f.bench, "provenance");
  const Json& build = object_at(p, "build");
  const Json& machine = object_at(p, "machine");
  std::string key = "provenance-" + f.label;  // section keys are lower case
  key.back() = static_cast<char>(key.back() - 'A' + 'a');
  Section s{key,
            "Bench file " + f.label + ": " + f.path + ", " + file_machine(f),
            "Where the figures of bench file " + f.label +
                " were measured: the machine and build the file records (its own provenance), "
                "not the machine that wrote this report.",
            {"what", "value"},
            {},
            {},
            {}};
  s.rows.push_back({"file", f.path + " (" + f.label + ")"});
  const Json& command = f.bench.contains("command") ? f.bench["command"] : Json();
  s.rows.push_back(
      {"bench", command.is_string() ? command.get<std::string>() : "not recorded in the file"});
  if (!build.empty()) {
    add_build_rows(s, build);
  } else {
    const Json& px = object_at(f.bench, "pxflow");
    s.rows.push_back({"pxflow", px.empty() ? "not recorded in the file"
                                           : str(px, "version") + ", commit " + str(px, "commit")});
  }
  if (!machine.empty())
    add_machine_rows(s, machine);
  else
    s.rows.push_back({"machine",
                      "not recorded in the file (written before pxflow recorded it): unknown, "
                      "and not this report's"});
  const std::string warning = add_load_row(s, f.bench);
  if (f.bench.contains("points_total")) {
    const std::string stopped = stopped_after(f.bench);
    s.rows.push_back(
        {"points", stopped.empty()
                       ? "complete: all " + std::to_string(f.bench.value("points_total", 0L)) +
                             " points measured"
                       : "incomplete: " + stopped + "; the report shows the rows it measured"});
    if (!stopped.empty()) s.text += " **Incomplete: " + stopped + ".**";
  }
  s.text = warning + s.text;
  if (backends_shown) return s;
  const Json backends = f.bench.value("backends", Json::array());
  for (const Json* b : in_registry_order(backends))
    if (const std::string line = description_line(*b); !line.empty())
      s.rows.push_back({"backend " + str(*b, "backend"), line});
  return s;
}

Json bench_files_json(std::span<const BenchFile> files) {
  Json out = Json::array();
  for (const BenchFile& f : files) {
    const Json& p = object_at(f.bench, "provenance");
    auto or_null = [](const Json& j) { return j.empty() ? Json() : j; };
    Json j{{"label", f.label},
           {"path", f.path},
           {"command", f.bench.contains("command") ? f.bench["command"] : Json()},
           {"build", or_null(object_at(p, "build"))},
           {"machine", or_null(object_at(p, "machine"))},
           {"machine_state", or_null(object_at(f.bench, "machine"))},
           {"complete", f.bench.value("complete", true)}};
    for (const char* key : {"points_done", "points_total"})
      if (f.bench.contains(key)) j[key] = f.bench[key];
    out.push_back(j);
  }
  return out;
}

bool several_machines(const ReportInputs& in, const Json& machine) {
  std::set<std::string> machines;
  for (const BenchFile& f : in.bench_files)  // an unrecorded machine: one of its own
    machines.insert(object_at(object_at(f.bench, "provenance"), "machine").empty()
                        ? "?" + f.path
                        : file_machine(f));
  if (!in.measured_here.empty()) machines.insert(machine_name(machine));
  return machines.size() > 1;
}

}  // namespace pxflow::report
