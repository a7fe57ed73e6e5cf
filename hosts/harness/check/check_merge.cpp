#include "check_merge.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "errors.hpp"

namespace pxflow {
namespace {

constexpr const char* kHelp = " (see pxflow merge --help)";

std::string joined(const std::vector<std::string>& items) {
  if (items.empty()) return "(none)";
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ",") + i;
  return s;
}

// What must be equal in every shard of one campaign, each with the name a user knows it by.
std::vector<std::pair<std::string, std::string>> identity(const CheckReport& r) {
  const CampaignInfo& c = r.campaign;
  return {{"pxflow commit", r.pxflow_commit},
          {"pxflow version", r.pxflow_version},
          {"seed", std::to_string(r.seed)},
          {"campaign", c.kind},
          {"--cases", std::to_string(c.fuzz_pairs)},
          {"--generated-only", c.generated_only ? "yes" : "no"},
          {"corpus version", std::to_string(c.corpus_version)},
          // Before the fingerprint: the limit cases come from the selected rows, so other rows
          // mean other inputs too, and the rows are what the user changed.
          {"backends", joined(c.backends)},
          {"corpus fingerprint", c.fingerprint},
          {"settings", joined(c.settings)},
          {"--require", joined(c.require)},
          {"campaign cases", std::to_string(c.cases)},
          {"shard count", std::to_string(r.shard.count)}};
}

// A file must be what pxflow check wrote for its shard: the range of its K/M, its backends.
void check_consistent(const ShardFile& f) {
  const CheckReport& r = f.report;
  if (!r.merged_from.empty())
    throw InputError(f.file + ": a merged file: give the shard files themselves" +
                     std::string(kHelp));
  if (!r.complete)
    throw InputError(f.file + ": a stopped check (" + std::to_string(r.cases) + " of " +
                     std::to_string(r.cases_total()) + " cases): finish it first with pxflow " +
                     "check --resume " + f.file + kHelp);
  const CaseRange want = shard_range(r.campaign.cases, r.shard);
  bool ok = r.shard.index >= 1 && r.shard.index <= r.shard.count && r.range.first == want.first &&
            r.range.end == want.end && r.cases == want.size() &&
            r.backends.size() == r.campaign.backends.size();
  for (std::size_t i = 0; ok && i < r.backends.size(); ++i)
    ok = r.backends[i].name == r.campaign.backends[i];
  if (!ok)
    throw InputError(f.file + ": shard " + r.shard.text() + " does not hold the cases and " +
                     "backends of its shard: only files pxflow check --shard wrote merge" + kHelp);
}

// A backend merged over the shards, in shard order (the failure lines then come in the
// unsharded run's order, the shards being contiguous ranges of cases).
BackendOutcome merge_backend(const std::vector<const BackendOutcome*>& parts,
                             const std::vector<Shard>& shards, bool complete) {
  BackendOutcome m;
  m.name = parts.front()->name;
  bool any_failed = false, any_skipped = false, reference = false, reasons_differ = false;
  std::vector<std::string> implementations, devices, reasons;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const BackendOutcome& b = *parts[i];
    any_failed |= b.state == BackendState::kFailed;
    any_skipped |= b.state == BackendState::kSkipped;
    reference |= b.state == BackendState::kReference;
    m.passed += b.passed, m.failed += b.failed, m.not_applicable += b.not_applicable;
    m.pairs += b.pairs, m.seconds += b.seconds;
    m.limits.insert(m.limits.end(), b.limits.begin(), b.limits.end());  // shards: disjoint cases
    auto add = [](std::vector<std::string>& to, const std::string& v) {
      if (!v.empty() && std::find(to.begin(), to.end(), v) == to.end()) to.push_back(v);
    };
    add(implementations, b.implementation), add(devices, b.device);
    reasons_differ |= b.reason != parts.front()->reason;
    if (!b.reason.empty()) reasons.push_back("shard " + shards[i].text() + ": " + b.reason);
    // A backend that could not be opened has one line, "required but cannot run", in every
    // shard; the unsharded run printed it once.
    const bool unopened = b.implementation.empty() && b.state != BackendState::kReference;
    for (const std::string& line : b.failures)
      if (!unopened || std::find(m.failures.begin(), m.failures.end(), line) == m.failures.end())
        m.failures.push_back(line);
  }
  m.state = reference     ? BackendState::kReference
            : any_failed  ? BackendState::kFailed
            : any_skipped ? BackendState::kSkipped
            : complete    ? BackendState::kPassed
                          : BackendState::kIncomplete;
  auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
  };
  m.implementation = list(implementations);  // several: the shards' machines differed
  m.device = list(devices);
  m.reason = reasons_differ ? list(reasons) : parts.front()->reason;
  return m;
}

}  // namespace

CheckReport merge_shards(const std::vector<ShardFile>& files) {
  if (files.empty()) throw InputError(std::string("no shard files given") + kHelp);
  for (const ShardFile& f : files) check_consistent(f);
  const ShardFile& first = files.front();
  const auto want = identity(first.report);
  std::map<int, const ShardFile*> by_index;
  for (const ShardFile& f : files) {
    const auto got = identity(f.report);
    for (std::size_t i = 0; i < want.size(); ++i)
      if (got[i].second != want[i].second)
        throw InputError(f.file + ": " + got[i].first + " " + got[i].second + " (" + first.file +
                         ": " + want[i].second +
                         "): only shards of one campaign merge (one pxflow " +
                         "build, one check command but for --shard)" + kHelp);
    const auto [at, fresh] = by_index.emplace(f.report.shard.index, &f);
    if (!fresh)
      throw InputError(f.file + ": shard " + f.report.shard.text() + " again (also " +
                       at->second->file + "): each shard once" + kHelp);
  }

  CheckReport m;
  const CheckReport& r0 = first.report;
  m.seed = r0.seed;
  m.pxflow_version = r0.pxflow_version, m.pxflow_commit = r0.pxflow_commit;
  m.campaign = r0.campaign;
  const int count = r0.shard.count;
  for (int k = 1; k <= count; ++k)
    if (!by_index.contains(k)) m.missing_shards.push_back(k);
  std::vector<Shard> shards;
  for (const auto& [index, f] : by_index) {
    const CheckReport& r = f->report;
    m.merged_from.push_back({f->file, r.shard, r.range, r.pairs, r.seconds});
    shards.push_back(r.shard);
    m.cases += r.cases, m.pairs += r.pairs;
    m.passed += r.passed, m.failed += r.failed, m.skipped += r.skipped;
    m.not_applicable += r.not_applicable, m.compared += r.compared;
    m.seconds += r.seconds;
  }
  for (std::size_t b = 0; b < r0.backends.size(); ++b) {
    std::vector<const BackendOutcome*> parts;
    for (const auto& [index, f] : by_index) parts.push_back(&f->report.backends[b]);
    m.backends.push_back(merge_backend(parts, shards, m.missing_shards.empty()));
  }
  return m;
}

}  // namespace pxflow
