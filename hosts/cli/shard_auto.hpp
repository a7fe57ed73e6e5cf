// `pxflow check --shard auto`: K and M from the variables the CI engine running the check sets
// for each job of a matrix, so that one job definition serves every shard (docs/ci-campaigns.md,
// "Campaigns over a CI matrix").
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "backend.hpp"
#include "check_campaign.hpp"

namespace pxflow::cli {

// K/M and where they came from, for the banner ("GitLab CI_NODE_INDEX=2 CI_NODE_TOTAL=4").
struct AutoShard {
  Shard shard;
  std::string source;
};

// A variable's value, or null when it is not set (std::getenv's contract).
using Environment = std::function<const char*(const char*)>;

// The first engine whose variables are set, in this order: GitLab (CI_NODE_INDEX, 1-based, and
// CI_NODE_TOTAL), a Kubernetes Indexed Job (JOB_COMPLETION_INDEX, 0-based, and
// PXFLOW_SHARD_TOTAL, which the manifest sets from the Job's completions), a Slurm array
// (SLURM_ARRAY_TASK_ID from SLURM_ARRAY_TASK_MIN in steps of SLURM_ARRAY_TASK_STEP, and
// SLURM_ARRAY_TASK_COUNT). Throws InputError, one line naming the variables, when none is set or
// the values are not one shard of a matrix. An empty variable counts as not set; GitLab's
// CI_NODE_TOTAL=1 without CI_NODE_INDEX (every job without parallel:) is no matrix.
AutoShard shard_from_environment(const Environment& env);
AutoShard shard_from_environment();  // from this process's environment

// The variables it reads, for --help's Environment section.
std::vector<EnvironmentVariable> shard_environment();

}  // namespace pxflow::cli
