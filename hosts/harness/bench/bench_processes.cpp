#include "bench_processes.hpp"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <map>
#include <ostream>

#include "bench_bound.hpp"
#include "bench_stats.hpp"
#include "guarded_child.hpp"
#include "interrupt.hpp"
#include "machine_state.hpp"
#include "registry.hpp"
#include "result_fields_json.hpp"

namespace pxflow {
namespace {

// Appends what `fd` has to `into`; false at its end (or an error).
bool drain(int fd, std::string& into) {
  char buf[65536];
  const ssize_t n = ::read(fd, buf, sizeof buf);
  if (n > 0) into.append(buf, static_cast<std::size_t>(n));
  return n > 0 || (n < 0 && (errno == EINTR || errno == EAGAIN));
}

std::string last_line(const std::string& text) {
  std::size_t end = text.find_last_not_of("\n\r ");
  if (end == std::string::npos) return "";
  const std::size_t start = text.rfind('\n', end);
  return text.substr(start == std::string::npos ? 0 : start + 1,
                     end - (start == std::string::npos ? 0 : start + 1) + 1);
}

// The rows of one point and clock are the same row in every process.
std::string row_key(const BenchRow& r) {
  return r.backend + '\n' + r.sweep + '\n' + r.setting + '\n' + r.params.dump() + '\n' +
         std::to_string(r.width) + 'x' + std::to_string(r.height) + " S" +
         std::to_string(r.search_radius) + " b" + std::to_string(r.batch) + " t" +
         std::to_string(r.threads) + '\n' + r.source;
}

std::string without_noisy_note(std::string note) {
  for (const std::string& cut : {std::string("; ") + kNoisyNote, std::string(kNoisyNote)})
    if (const auto at = note.find(cut); at != std::string::npos) note.erase(at, cut.size());
  return note;
}

double median_of_positive(const std::vector<const BenchRow*>& rows, double BenchRow::*field) {
  std::vector<double> v;
  for (const BenchRow* r : rows)
    if (r->*field > 0) v.push_back(r->*field);
  return v.empty() ? 0 : median_of(v);
}

// One row from the same row of several processes (each timed).
BenchRow combined_row(const std::vector<const BenchRow*>& rows, std::size_t processes) {
  BenchRow c = *rows.front();
  if (c.exact_clock) return c;  // one deterministic count: the first process's
  c.processes = static_cast<int>(rows.size());
  c.samples_ns_per_frame.clear(), c.samples_per_process.clear();
  c.process_medians_ns_per_frame.clear();
  c.measured_s = 0;
  for (const BenchRow* r : rows) {
    c.samples_ns_per_frame.insert(c.samples_ns_per_frame.end(), r->samples_ns_per_frame.begin(),
                                  r->samples_ns_per_frame.end());
    c.samples_per_process.push_back(static_cast<int>(r->samples_ns_per_frame.size()));
    c.process_medians_ns_per_frame.push_back(r->median_ns_per_frame);
    c.measured_s += r->measured_s;
  }
  const std::vector<double>& medians = c.process_medians_ns_per_frame;
  c.repeats = static_cast<int>(c.samples_ns_per_frame.size());
  c.median_ns_per_frame = median_of(medians);
  std::tie(c.median_ci_low_ns, c.median_ci_high_ns) = median_ci95(medians);
  c.min_ns_per_frame =
      *std::min_element(c.samples_ns_per_frame.begin(), c.samples_ns_per_frame.end());
  c.max_ns_per_frame =
      *std::max_element(c.samples_ns_per_frame.begin(), c.samples_ns_per_frame.end());
  c.noisy = is_noisy(c.median_ns_per_frame, c.median_ci_low_ns, c.median_ci_high_ns,
                     *std::min_element(medians.begin(), medians.end()));
  c.frames_per_s = 1e9 / c.median_ns_per_frame;
  c.ns_per_poi = c.median_ns_per_frame / static_cast<double>(std::max(1L, c.pois_per_frame));
  c.cycles_per_frame = median_of_positive(rows, &BenchRow::cycles_per_frame);
  c.instructions_per_frame = median_of_positive(rows, &BenchRow::instructions_per_frame);
  // Only the first process measures the bound (the others run with --no-bound): the row keeps
  // the bound a process gave it, held to the combined median.
  for (const BenchRow* r : rows)
    if (r->bound_per_frame > 0) {
      c.bound = r->bound, c.bound_unit = r->bound_unit, c.bound_per_frame = r->bound_per_frame;
      break;
    }
  refresh_bound_fraction(c);
  c.note = without_noisy_note(c.note);
  if (rows.size() < processes)
    c.note += (c.note.empty() ? "" : "; ") + std::string("timed in ") +
              std::to_string(rows.size()) + " of " + std::to_string(processes) + " processes";
  if (c.noisy) c.note += (c.note.empty() ? "" : "; ") + std::string(kNoisyNote);
  return c;
}

}  // namespace

BenchProcess run_bench_process(const std::vector<std::string>& argv) {
  PipedChild c = start_piped_child(argv, true);
  ::close(c.to_child);
  struct Fds {
    int out, err;
    ~Fds() { ::close(out), ::close(err); }
  } fds{c.from_child, c.errors_from_child};
  std::string out, err;
  bool out_open = true, err_open = true;
  while (out_open || err_open) {
    stop_if_interrupted_while("waiting for a bench process");
    pollfd p[2] = {{out_open ? fds.out : -1, POLLIN, 0}, {err_open ? fds.err : -1, POLLIN, 0}};
    if (::poll(p, 2, 500) <= 0) continue;  // a signal (EINTR) or a quiet half second
    if (p[0].revents) out_open = drain(fds.out, out);
    if (p[1].revents) err_open = drain(fds.err, err);
  }
  while (!c.child->exited(std::chrono::milliseconds(200)))
    stop_if_interrupted_while("waiting for a bench process to end");
  BenchProcess r;
  const int st = c.child->status();
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
  r.last_error_line = last_line(err);
  if (r.last_error_line.empty() && r.status != 0) r.last_error_line = ended_text(st);
  try {
    if (!out.empty()) r.bench = Json::parse(out);
  } catch (const std::exception&) {
    r.bench = nullptr;
  }
  return r;
}

BenchReport bench_report_from_json(const Json& j) {
  BenchReport r;
  for (const Json& row : j.at("rows")) {
    BenchRow b;
    fields_from_json(bench_row_fields(), row, b);
    if (!row.contains("processes")) b.processes = 1;
    r.rows.push_back(std::move(b));
  }
  if (j.contains("skipped")) r.skipped = j["skipped"].get<std::vector<std::string>>();
  if (j.contains("backends")) r.backends = j["backends"];
  if (j.contains("machine")) r.machine = machine_from_json(j["machine"]);
  if (j.contains("provenance")) r.provenance = j["provenance"];
  r.command = j.value("command", "");
  r.complete = j.value("complete", true);
  r.points_done = j.value("points_done", std::size_t{0});
  r.points_total = j.value("points_total", std::size_t{0});
  if (j.contains("bound") && j["bound"].is_object()) {
    const Json& b = j["bound"];
    r.bound_name = b.value("name", ""), r.bound_clock = b.value("clock", "");
    r.bound_bytes_per_cycle = b.value("bytes_per_cycle", 0.0);
    r.tsc_hz = b.value("tsc_hz", 0.0);
    for (const Json& t : b.value("by_threads", Json::array()))
      r.bound_by_threads.push_back({t.value("threads", 0), t.value("bytes_per_cycle", 0.0)});
  }
  return r;
}

BenchReport combine_processes(std::span<const BenchReport> runs) {
  BenchReport c = runs.front();
  c.rows.clear();
  c.processes = static_cast<int>(runs.size());
  // Rows in the first process's order; each key's rows of every process that timed it.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const BenchRow*>> timed, any;
  for (const BenchReport& run : runs)
    for (const BenchRow& row : run.rows) {
      const std::string key = row_key(row);
      if (!any.contains(key)) order.push_back(key);
      any[key].push_back(&row);
      if (!row.samples_ns_per_frame.empty()) timed[key].push_back(&row);
    }
  for (const std::string& key : order)
    c.rows.push_back(timed.contains(key) ? combined_row(timed[key], runs.size())
                                         : *any[key].front());
  // Speed-ups again, from the combined medians (ref-original's row of the same point and clock).
  for (BenchRow& r : c.rows) {
    if (r.samples_ns_per_frame.empty() || r.backend == kReferenceBackend) continue;
    r.speedup_vs_reference = 0;
    for (const BenchRow& ref : c.rows)
      if (ref.backend == kReferenceBackend && ref.source == r.source && ref.sweep == r.sweep &&
          ref.params == r.params && ref.batch == r.batch && ref.threads == r.threads &&
          ref.median_ns_per_frame > 0)
        r.speedup_vs_reference = ref.median_ns_per_frame / r.median_ns_per_frame;
  }
  // The machine: the shares of other processes and of the hypervisor over all the processes'
  // measuring, each weighted by the seconds it measured (a process of a few milliseconds sees a
  // few clock ticks of /proc/stat: alone, one tick of another process is 25 %).
  double weight = 0, others = 0, steal = 0;
  bool known = true;
  for (const BenchReport& run : runs) {
    double seconds = 0;
    for (const BenchRow& row : run.rows) seconds += row.measured_s;
    seconds = std::max(seconds, 1e-3);
    known = known && run.machine.others_cpu_share >= 0 && run.machine.steal_share >= 0;
    weight += seconds;
    others += seconds * std::max(0.0, run.machine.others_cpu_share);
    steal += seconds * std::max(0.0, run.machine.steal_share);
    c.complete = c.complete && run.complete;
  }
  c.machine.disturbed.clear();
  c.machine.others_cpu_share = known ? others / weight : -1;
  c.machine.steal_share = known ? steal / weight : -1;
  if (known && c.machine.others_cpu_share + c.machine.steal_share > kDisturbedShare) {
    char why[240];
    std::snprintf(why, sizeof why,
                  "other processes took %.0f %% and the hypervisor %.0f %% of the CPUs' time while "
                  "its %zu processes measured (weighted by their seconds)",
                  100 * c.machine.others_cpu_share, 100 * c.machine.steal_share, runs.size());
    c.machine.disturbed = why;
  }
  c.machine.after = runs.back().machine.after;
  return c;
}

void print_bench_rows(const BenchReport& r, std::ostream& out) {
  std::size_t width = 7;
  for (const BenchRow& row : r.rows) width = std::max(width, row.backend.size());
  out << bench_header_line(width) << "\n";
  std::string point;
  for (const BenchRow& row : r.rows) {
    const std::string here =
        row.setting + " " + std::to_string(row.width) + "x" + std::to_string(row.height) +
        " S=" + std::to_string(row.search_radius) + " batch=" + std::to_string(row.batch) +
        " threads=" + (row.threads_requested ? std::to_string(row.threads) : "all");
    if (here != point) out << "-- " << (point = here) << "\n";
    out << bench_row_line(row, width) << "\n";
  }
}

}  // namespace pxflow
