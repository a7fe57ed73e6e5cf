#include "check_resume.hpp"

#include <utility>
#include <vector>

#include "errors.hpp"

namespace pxflow {
namespace {

constexpr const char* kResumeHelp = " (see pxflow check --help)";

std::string comma_list(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ",") + i;
  return s.empty() ? "(none)" : s;
}

// What must be equal for the rest of a campaign to be the same campaign, each with the name a
// user knows it by.
std::vector<std::pair<std::string, std::string>> resume_identity(const CheckReport& r) {
  const CampaignInfo& c = r.campaign;
  return {
      {"campaign", c.kind},
      {"--cases", std::to_string(c.fuzz_pairs)},
      {"--generated-only", c.generated_only ? "yes" : "no"},
      {"corpus version", std::to_string(c.corpus_version)},
      {"backends", comma_list(c.backends)},
      {"corpus fingerprint", c.fingerprint},
      {"settings", comma_list(c.settings)},
      {"--require", comma_list(c.require)},
      {"campaign cases", std::to_string(c.cases)},
      {"campaign pairs", std::to_string(c.pairs)},
      {"shard", r.shard.text()},
      {"cases of the shard", std::to_string(r.range.first) + ".." + std::to_string(r.range.end)}};
}

bool opened_in(const BackendOutcome& b) {
  return !b.implementation.empty() && b.state != BackendState::kReference;
}

}  // namespace

void check_resumable(const std::string& label, const CheckReport& r, const std::string& version,
                     const std::string& commit) {
  if (!r.merged_from.empty())
    throw InputError(label + ": a merged file: resume the stopped shard's own file" + kResumeHelp);
  if (r.complete)
    throw InputError(label + ": the check is complete (verdict " + r.verdict() +
                     "): nothing to resume" + kResumeHelp);
  if (r.pxflow_version != version || r.pxflow_commit != commit)
    throw InputError(label + ": written by pxflow " + r.pxflow_version + " (" + r.pxflow_commit +
                     "), this is " + version + " (" + commit +
                     "): only the build that started a campaign finishes it" + kResumeHelp);
  const bool consistent = r.range.first >= 0 && r.range.first <= r.range.end && r.cases >= 0 &&
                          r.cases <= r.range.size() &&
                          r.backends.size() == r.campaign.backends.size();
  if (!consistent)
    throw InputError(label + ": its cases done (" + std::to_string(r.cases) + "), range and " +
                     "backends disagree: only a file pxflow check wrote resumes" + kResumeHelp);
}

void check_same_campaign(const std::string& label, const CheckReport& before,
                         const CheckReport& now) {
  const auto want = resume_identity(before), got = resume_identity(now);
  for (std::size_t i = 0; i < want.size(); ++i)
    if (got[i].second != want[i].second)
      throw InputError(label + ": " + want[i].first + " " + want[i].second + ", here " +
                       got[i].second + ": not the campaign the file began (another corpus, " +
                       "data folder or build of OpenCV?)" + kResumeHelp);
}

void check_same_backend(const std::string& label, const BackendOutcome& before,
                        const BackendOutcome& now, bool opened_now) {
  if (before.name != now.name)
    throw InputError(label + ": backend " + before.name + " where this run has " + now.name +
                     kResumeHelp);
  if (opened_in(before) && !opened_now)
    throw InputError(label + ": " + before.name + " ran in the stopped run but cannot run now (" +
                     now.reason + "): its remaining cases would go unchecked" + kResumeHelp);
  if (!opened_in(before) && opened_now && before.state != BackendState::kReference)
    throw InputError(label + ": " + before.name + " did not run in the stopped run (" +
                     before.reason + ") but runs now: its cases so far would go unchecked" +
                     kResumeHelp);
  if (opened_now && (before.implementation != now.implementation || before.device != now.device))
    throw InputError(label + ": " + before.name + " ran as " + before.implementation + " on " +
                     before.device + ", now as " + now.implementation + " on " + now.device +
                     ": one campaign, one implementation" + kResumeHelp);
}

long reference_count_failures(const CheckReport& before) {
  long n = before.failed;
  for (const BackendOutcome& b : before.backends)
    if (opened_in(b))
      n -= b.failed;
    else if (b.state == BackendState::kFailed)
      n -= before.cases;
  return n;
}

}  // namespace pxflow
