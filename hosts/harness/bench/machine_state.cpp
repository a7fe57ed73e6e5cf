#include "machine_state.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <thread>

#include "system_files.hpp"

namespace pxflow {

MachineState read_machine_state() {
  MachineState s;
  s.cpus = static_cast<int>(std::thread::hardware_concurrency());
  std::istringstream(read_system_file("/proc/loadavg")) >> s.load_1min;
  std::istringstream info(read_system_file("/proc/cpuinfo"));
  double sum = 0;
  int n = 0;
  for (std::string line; std::getline(info, line);)
    if (line.rfind("cpu MHz", 0) == 0)
      if (const auto colon = line.find(':'); colon != std::string::npos) {
        sum += std::stod(line.substr(colon + 1));
        ++n;
      }
  if (n > 0) s.cpu_mhz = sum / n;
  return s;
}

CpuTimes read_cpu_times() {
  CpuTimes t;
  std::istringstream stat(read_system_file("/proc/stat"));
  std::string cpu;
  std::uint64_t v[8] = {};  // user nice system idle iowait irq softirq steal
  if (!(stat >> cpu) || cpu != "cpu") return t;
  for (auto& x : v) stat >> x;
  if (!stat) return t;
  for (auto x : v) t.total += x;
  t.idle = v[3] + v[4];
  t.steal = v[7];
  // /proc/self/stat: fields 14 and 15 (utime, stime) follow the command name in parentheses.
  std::istringstream self(read_system_file("/proc/self/stat"));
  std::string line;
  std::getline(self, line);
  const auto close = line.rfind(')');
  if (close == std::string::npos) return t;
  std::istringstream rest(line.substr(close + 2));
  std::string field;
  for (int i = 3; i <= 13; ++i) rest >> field;
  std::uint64_t utime = 0, stime = 0;
  if (!(rest >> utime >> stime)) return t;
  t.own = utime + stime;
  t.known = true;
  return t;
}

MachineLoad machine_load(const MachineState& before, const CpuTimes& t0, const MachineState& after,
                         const CpuTimes& t1) {
  MachineLoad m{before, after, -1, -1, {}};
  if (!t0.known || !t1.known || t1.total <= t0.total) return m;
  const double total = static_cast<double>(t1.total - t0.total);
  const double busy = total - static_cast<double>(t1.idle - t0.idle);
  const double steal = static_cast<double>(t1.steal - t0.steal);
  const double own = static_cast<double>(t1.own - t0.own);
  m.steal_share = steal / total;
  m.others_cpu_share = std::max(0.0, (busy - steal - own) / total);
  char why[200];
  if (m.others_cpu_share + m.steal_share > kDisturbedShare) {
    std::snprintf(why, sizeof why,
                  "other processes took %.0f %% and the hypervisor %.0f %% of the CPUs' time "
                  "while it ran (load average %.2f before, %.2f after, %d CPUs)",
                  100 * m.others_cpu_share, 100 * m.steal_share, before.load_1min, after.load_1min,
                  before.cpus);
    m.disturbed = why;
  }
  return m;
}

std::string machine_line(const MachineLoad& m) {
  char b[320];
  if (!m.disturbed.empty()) {
    std::snprintf(b, sizeof b, "machine: DISTURBED: %s; rerun on a quiet machine",
                  m.disturbed.c_str());
    return b;
  }
  if (m.others_cpu_share < 0)
    return "machine: load unknown (/proc/stat unreadable): quiet or not, nobody can tell";
  std::snprintf(b, sizeof b,
                "machine: quiet (other processes %.0f %%, hypervisor %.0f %% of the CPUs' time; "
                "load average %.2f before, %.2f after, %d CPUs)",
                100 * m.others_cpu_share, 100 * m.steal_share, m.before.load_1min,
                m.after.load_1min, m.before.cpus);
  return b;
}

namespace {

Json state_json(const MachineState& s) {
  return {{"load_1min", s.load_1min}, {"cpu_mhz", s.cpu_mhz}, {"cpus", s.cpus}};
}

MachineState state_from_json(const Json& j) {
  return {j.at("load_1min").get<double>(), j.at("cpu_mhz").get<double>(), j.at("cpus").get<int>()};
}

}  // namespace

Json machine_json(const MachineLoad& m) {
  return {{"before", state_json(m.before)},
          {"after", state_json(m.after)},
          {"others_cpu_share", m.others_cpu_share},
          {"steal_share", m.steal_share},
          {"disturbed", m.disturbed}};
}

MachineLoad machine_from_json(const Json& j) {
  return {state_from_json(j.at("before")), state_from_json(j.at("after")),
          j.at("others_cpu_share").get<double>(), j.at("steal_share").get<double>(),
          j.at("disturbed").get<std::string>()};
}

}  // namespace pxflow
