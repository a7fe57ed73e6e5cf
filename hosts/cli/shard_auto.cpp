#include "shard_auto.hpp"

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <string_view>

#include "errors.hpp"

namespace pxflow::cli {
namespace {

constexpr const char* kShardAutoHelp = " (see pxflow check --help)";
constexpr long kMaxShardCount = 100000;  // parse_shard's limit
constexpr long kMaxVariable = 1000000000;

// One engine that runs a matrix of jobs: the variable that numbers this job, the one that counts
// the jobs, and the first job's number.
struct ShardEngine {
  const char* name;
  const char* index;
  const char* total;
  int first;                // 1 or 0; kFromArrayMin: SLURM_ARRAY_TASK_MIN, in steps
  const char* alone_total;  // the total in a job outside any matrix (null: the engine sets none)
  const char* index_help;
  const char* total_help;
};
constexpr int kFromArrayMin = -1;

// In precedence order: the first engine whose variables are set gives K/M.
constexpr ShardEngine kShardEngines[] = {
    // GitLab sets CI_NODE_TOTAL=1 in every job without parallel:, CI_NODE_INDEX only with it.
    {"GitLab", "CI_NODE_INDEX", "CI_NODE_TOTAL", 1, "1",
     "check --shard auto: K in a GitLab job with parallel: M (it counts from 1)",
     "check --shard auto: M in a GitLab job with parallel: M"},
    // Kubernetes gives an Indexed Job's pods their index but not the Job's completions.
    {"Kubernetes", "JOB_COMPLETION_INDEX", "PXFLOW_SHARD_TOTAL", 0, nullptr,
     "check --shard auto: K - 1 in a Kubernetes Indexed Job's pod (it counts from 0)",
     "check --shard auto: M in a Kubernetes Indexed Job: its manifest sets it to the Job's "
     "completions (docs/ci-examples/)"},
    // Slurm numbers an array's tasks as --array says: --array=5-8 is 5, 6, 7, 8.
    {"Slurm", "SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT", kFromArrayMin, nullptr,
     "check --shard auto: K in a Slurm array task, counted from SLURM_ARRAY_TASK_MIN in steps "
     "of SLURM_ARRAY_TASK_STEP (--array=5-8: task 6 is shard 2/4)",
     "check --shard auto: M in a Slurm array task"},
};

constexpr const char* kArrayMin = "SLURM_ARRAY_TASK_MIN";
constexpr const char* kArrayStep = "SLURM_ARRAY_TASK_STEP";
constexpr const char* kArrayMax = "SLURM_ARRAY_TASK_MAX";

[[noreturn]] void refuse(const std::string& what) {
  throw InputError("--shard auto: " + what + kShardAutoHelp);
}

// The value of `name`, or null when it is not set or empty.
const char* value(const Environment& env, const char* name) {
  const char* v = env(name);
  return v && *v ? v : nullptr;
}

// The value of the set variable `name` as a whole number, or refused naming it.
long number(const Environment& env, const char* engine, const char* name) {
  const std::string_view v = value(env, name);
  long n = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (!std::isdigit(static_cast<unsigned char>(v[0])) || ec != std::errc() ||
      end != v.data() + v.size() || n > kMaxVariable)
    refuse(std::string(engine) + " " + name + "='" + std::string(v) +
           "': not a whole number from 0 to " + std::to_string(kMaxVariable));
  return n;
}

// K of a Slurm array task `id`: its place among MIN, MIN + STEP, ... MAX. An array that is not
// one range with one step (--array=1,2,5) has no K/M.
long slurm_position(const Environment& env, long id, long count, std::string& source) {
  const char* min_text = value(env, kArrayMin);
  if (!min_text)
    refuse(source + ": " + kArrayMin + " is not set (Slurm sets it in every array task; " +
           "task ids need not start at 0 or 1)");
  const long min = number(env, "Slurm", kArrayMin);
  source += std::string(" ") + kArrayMin + "=" + min_text;
  long step = 1;
  if (const char* step_text = value(env, kArrayStep)) {
    step = number(env, "Slurm", kArrayStep);
    if (step != 1) source += std::string(" ") + kArrayStep + "=" + step_text;
  }
  if (step < 1) refuse(source + ": " + kArrayStep + " must be 1 or more");
  if (const char* max_text = value(env, kArrayMax);
      max_text && number(env, "Slurm", kArrayMax) != min + step * (count - 1))
    refuse(source + " " + kArrayMax + "=" + max_text + ": the array's task ids are not one " +
           "range with one step (a list such as --array=1,2,5), so they are not shards 1..M: " +
           "submit --array=1-M");
  if (id < min || (id - min) % step != 0 || (id - min) / step >= count)
    refuse(source + ": SLURM_ARRAY_TASK_ID is not one of " + std::to_string(min) + ", " +
           std::to_string(min + step) + " .. " + std::to_string(min + step * (count - 1)));
  return (id - min) / step + 1;
}

}  // namespace

AutoShard shard_from_environment(const Environment& env) {
  std::string alone;  // the variables of an engine running no matrix, for the refusal
  for (const ShardEngine& e : kShardEngines) {
    const char* index = value(env, e.index);
    const char* total = value(env, e.total);
    if (!index && total && e.alone_total && std::string_view(total) == e.alone_total) {
      alone = std::string("; ") + e.total + "=" + total + " without " + e.index + " is a " +
              e.name + " job outside a matrix";
      continue;
    }
    if (!index && !total) continue;
    if (!index || !total)
      refuse(std::string(e.name) + " " + (index ? e.index : e.total) + "=" +
             (index ? index : total) + " is set but " + (index ? e.total : e.index) +
             " is not: both are needed");
    const long i = number(env, e.name, e.index), m = number(env, e.name, e.total);
    std::string source =
        std::string(e.name) + " " + e.index + "=" + index + " " + e.total + "=" + total;
    if (m < 1 || m > kMaxShardCount)
      refuse(source + ": " + e.total + " must be 1 to " + std::to_string(kMaxShardCount));
    long k = 0;
    if (e.first == kFromArrayMin) {
      k = slurm_position(env, i, m, source);
    } else {
      k = i - e.first + 1;
      if (k < 1 || k > m)
        refuse(source + ": " + e.index + " must be " + std::to_string(e.first) + " to " +
               std::to_string(e.first + m - 1) + " (it counts from " + std::to_string(e.first) +
               ")");
    }
    return {Shard{static_cast<int>(k), static_cast<int>(m)}, source};
  }
  std::string looked;
  for (const ShardEngine& e : kShardEngines)
    looked += std::string(looked.empty() ? "" : ", ") + e.name + " " + e.index + "/" + e.total;
  refuse("no CI engine's shard variables are set (looked for " + looked + ")" + alone +
         "; where the engine sets none, as in a GitHub Actions matrix, give --shard K/M");
}

AutoShard shard_from_environment() {
  return shard_from_environment([](const char* name) -> const char* { return std::getenv(name); });
}

std::vector<EnvironmentVariable> shard_environment() {
  std::vector<EnvironmentVariable> v;
  for (const ShardEngine& e : kShardEngines) {
    v.push_back({e.index, e.index_help});
    v.push_back({e.total, e.total_help});
  }
  v.push_back({kArrayMin, "check --shard auto: the first task id of a Slurm array"});
  v.push_back({kArrayStep, "check --shard auto: the step between a Slurm array's task ids"});
  v.push_back({kArrayMax, "check --shard auto: the last task id of a Slurm array (checked)"});
  return v;
}

}  // namespace pxflow::cli
