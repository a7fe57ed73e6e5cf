// The human summary of a check or a merge of check shards.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>

#include "check.hpp"
#include "counted.hpp"

namespace pxflow {
namespace {

std::string format(const char* f, auto... args) {
  char b[512];
  std::snprintf(b, sizeof b, f, args...);
  return b;
}

// What ran behind the row ("avx512bw", "opencl-item on <device>"), or why it did not.
std::string note(const BackendOutcome& b) {
  std::string s;
  if (!b.implementation.empty() && b.implementation != b.name) s = b.implementation;
  if (!b.device.empty() && b.device != "host") s += (s.empty() ? "on " : " on ") + b.device;
  if (!b.reason.empty()) s += (s.empty() ? "" : "; ") + b.reason;
  // Kernels built before the cases ran (a driver's compile), outside the run time.
  if (b.build_seconds >= 0.05)
    s += (s.empty() ? "" : "; ") + format("kernels built in %.2f s", b.build_seconds);
  return s;
}

std::string shard_list(const std::vector<Shard>& shards) {
  std::string s;
  for (const Shard& k : shards) s += (s.empty() ? "" : ", ") + k.text();
  return s;
}

// Where the figures come from: this shard, the whole campaign, or the shards merged.
std::string scope(const CheckReport& r) {
  const std::string ran = counted(r.cases, "case") + ", " + counted(r.pairs, "pair");
  if (!r.merged_from.empty()) {
    std::vector<Shard> given;
    for (const MergedShard& m : r.merged_from) given.push_back(m.shard);
    std::string s = "merged shard" + std::string(given.size() > 1 ? "s " : " ") +
                    shard_list(given) + ": " + ran + " (the campaign has " +
                    counted(r.campaign.cases, "case") + "), " +
                    format("%.2f s summed over the shards", r.seconds);
    if (!r.missing_shards.empty())
      s += "\nincomplete: " + missing_shards_text(r.missing_shards, given.front().count);
    return s;
  }
  const std::string stopped =
      r.complete ? ""
                 : "\nincomplete: stopped after " + counted(r.cases, "case") + " of " +
                       std::to_string(r.cases_total()) + " (pxflow check --resume FILE goes on)";
  if (r.shard.count > 1)
    return "shard " + r.shard.text() + ": " + ran + " (cases " + std::to_string(r.range.first) +
           ".." + std::to_string(r.range.end - 1) + " of the campaign's " +
           std::to_string(r.campaign.cases) + ")" + format(" in %.2f s", r.seconds) + stopped;
  return ran + format(" in %.2f s", r.seconds) + stopped;
}

// "limits/KIND of ROW SETTING": the entries found from this row's own predicate, short; the radius
// sweep as one entry, "radius-sweep S=1..31".
std::string own_limits(const BackendOutcome& b) {
  std::string s;
  const std::string of = " of " + b.name + " ";
  int sweep_lo = 0, sweep_hi = 0;
  for (const std::string& e : b.limits) {
    const auto at = e.find(of);
    if (at == std::string::npos) continue;
    const std::string kind = e.substr(7, at - 7), setting = e.substr(at + of.size());
    if (kind == "radius-sweep") {
      const auto S = setting.find(" S=");
      const int radius = S == std::string::npos ? 0 : std::atoi(setting.c_str() + S + 3);
      sweep_lo = sweep_lo ? std::min(sweep_lo, radius) : radius;
      sweep_hi = std::max(sweep_hi, radius);
      continue;
    }
    s += (s.empty() ? "" : "; ") + kind + " " + setting;
  }
  if (sweep_hi)
    s += (s.empty() ? "" : "; ") + std::string("radius-sweep S=") + std::to_string(sweep_lo) +
         ".." + std::to_string(sweep_hi);
  return s;
}

// Which limit cases each row ran (check_limits.hpp); the check file lists them all.
void print_limits(const CheckReport& r, std::ostream& out) {
  bool any = false;
  for (const auto& b : r.backends) any |= !b.limits.empty();
  if (!any) return;
  out << "limit cases run (n/a ones not; its own: found from the row's unsupported()):\n";
  for (const auto& b : r.backends) {
    if (b.limits.empty()) continue;
    const std::string own = own_limits(b);
    out << "  " << b.name << ": " << b.limits.size() << (own.empty() ? "" : ", its own: " + own)
        << "\n";
  }
}

}  // namespace

std::string missing_shards_text(const std::vector<int>& missing, int count) {
  std::vector<Shard> shards;
  for (int k : missing) shards.push_back({k, count});
  return missing.size() == 1
             ? "shard " + shard_list(shards) + " not given: its cases were not checked"
             : "shards " + shard_list(shards) + " not given: their cases were not checked";
}

void print_check_summary(const CheckReport& r, std::ostream& out) {
  out << format("\n%-14s %-10s %7s %7s %5s %9s  %s\n", "backend", "result", "cases", "pairs", "n/a",
                "run time", "runs as / note");
  for (const auto& b : r.backends) {
    const std::string n = note(b);
    out << format("%-14s %-10s %7ld %7ld %5ld %8.2fs", b.name.c_str(), state_name(b.state),
                  b.passed + b.failed, b.pairs, b.not_applicable, b.seconds)
        << (n.empty() ? "" : "  " + n) << "\n";
  }
  print_limits(r, out);
  out << scope(r) << "\n";
  out << r.passed << " passed, " << r.failed << " failed, " << r.skipped << " skipped\n";
  if (r.compared == 0)
    out << "nothing was checked: no backend but the reference ran a case (see the skips above)\n";
}

}  // namespace pxflow
