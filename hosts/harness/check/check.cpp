#include "check.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <ostream>
#include <sstream>

#include "check_counts.hpp"
#include "check_resume.hpp"
#include "counted.hpp"
#include "errors.hpp"
#include "estimate.hpp"
#include "exactness.hpp"
#include "grid.hpp"
#include "interrupt.hpp"
#include "progress.hpp"
#include "registry.hpp"

namespace pxflow {
namespace {

struct Contender {
  const BackendRow* row;
  std::unique_ptr<IsolatedRow> backend;  // its worker; null when skipped or the reference
  BackendOutcome outcome;
};

std::vector<Contender> select_backends(const CheckOptions& o) {
  std::vector<Contender> out;
  if (o.backends.empty())
    for (const auto& row : backend_rows()) out.push_back({&row, nullptr, {}});
  else
    for (const auto& name : o.backends) out.push_back({&find_backend(name), nullptr, {}});
  const bool all = std::find(o.require.begin(), o.require.end(), "all") != o.require.end();
  for (const auto& name : o.require) {
    if (name == "all") continue;
    find_backend(name);  // unknown names are bad input
    if (std::none_of(out.begin(), out.end(),
                     [&](const Contender& c) { return c.row->name == name; }))
      throw InputError("--require " + name +
                       ": not among the backends of this run (add it to --backends)");
  }
  std::vector<const BackendRow*> rows;
  for (const auto& c : out) rows.push_back(c.row);
  check_device_option(rows, o.backend_options.device);
  // Every worker starts before any is waited for: the backends open side by side.
  for (auto& c : out) {
    c.outcome.name = c.row->name;
    if (c.row->name == kReferenceBackend) {
      // The answer every other backend is checked against is not checked against itself.
      c.outcome.state = BackendState::kReference;
      continue;
    }
    c.backend = std::make_unique<IsolatedRow>(c.row->name, o.isolation);
    c.backend->start();
  }
  for (auto& c : out) {
    if (!c.backend) continue;
    const IsolatedRow::Opened opened = c.backend->opened();
    if (opened.ok) {  // what runs behind the row (Backend::describe(), in the worker)
      c.outcome.implementation = opened.implementation;
      c.outcome.device = opened.device;
      continue;
    }
    c.backend.reset();
    const bool named =
        std::find(o.require.begin(), o.require.end(), c.row->name) != o.require.end();
    const bool required =
        opened.failed || named || (all && !(c.row->host_lacks && c.row->host_lacks()));
    c.outcome.state = required ? BackendState::kFailed : BackendState::kSkipped;
    c.outcome.reason = opened.why;
    if (opened.failed)
      c.outcome.failures.push_back("FAIL " + c.row->name + ": " + opened.why);
    else if (required)
      c.outcome.failures.push_back("FAIL " + c.row->name +
                                   ": required but cannot run: " + opened.why);
  }
  return out;
}

// The reproducer's runs of a row, in its worker (a crash there ends the shrinking, not the check).
PairRunner worker_runner(IsolatedRow& row) {
  return [&row](std::span<const FramePair> pairs, const Params& p) {
    IsolatedRow::PairsRun r = row.run_pairs(pairs, p);
    return RunOutcome{std::move(r.records), std::move(r.error)};
  };
}

// The opened rows' predicates, whose limits the fixed corpus adds cases for.
std::vector<LimitRow> limit_rows(const std::vector<Contender>& contenders) {
  std::vector<LimitRow> rows;
  for (const Contender& k : contenders)
    if (k.backend)
      rows.push_back(
          {k.row->name, [b = k.backend.get()](const Params& p) { return b->unsupported(p); }});
  return rows;
}

std::string block_dump(const FrameView& f, int x, int y) {
  std::ostringstream s;
  for (int r = 0; r < 8; ++r) {
    s << "      ";
    for (int c = 0; c < 8; ++c) {
      const int xx = x + c, yy = y + r;
      s << ' '
        << ((xx >= 0 && yy >= 0 && xx < f.width && yy < f.height) ? std::to_string(f.at(xx, yy))
                                                                  : "--");
    }
    s << '\n';
  }
  return s.str();
}

class Checker {
 public:
  Checker(const CheckOptions& o, std::ostream& out) : o_(o), out_(out), explainer_(o.repro) {}

  // Runs one case on one contender; returns false when it failed. `index`: the case's number
  // in the campaign; `reference_seconds`: ref-original's time on it (the hang allowance).
  bool run_case(Contender& k, const CheckCase& c, const ReferenceAnswer& e, long index,
                double reference_seconds) {
    IsolatedRow::CaseRun run = k.backend->run(c, index, reference_seconds);
    k.outcome.build_seconds += run.build_seconds;
    if (run.not_applicable) {
      ++k.outcome.not_applicable;
      return true;
    }
    if (is_limit_case(c)) k.outcome.limits.push_back(limit_entry(c, k.row->name));
    if (!run.failure.empty()) return fail(k, c, run.failure);
    if (run.not_run) return true;
    std::vector<std::string> names;
    for (const auto& p : c.pairs) names.push_back(p.name);
    const std::vector<PoiRecord>& got = run.records;
    k.outcome.seconds += run.seconds;
    k.outcome.pairs += static_cast<long>(c.pairs.size());
    RecordDetail detail;
    if (o_.verbose)
      detail = [&](std::size_t pair, const PoiRecord& want) { return blocks(c.pairs[pair], want); };
    const Comparison cmp =
        compare_with_reference(label(k, c), names, c.params, e, got, o_.max_lines_per_case, detail);
    for (const std::string& line : cmp.lines) emit(k, line);
    if (!cmp.ok()) {
      const Explanation why = explainer_.explain(label(k, c), c, e, got, worker_runner(*k.backend));
      emit(k, why.stage);
      for (const std::string& line : why.reproducer) out_ << line << '\n' << std::flush;
    }
    const std::string counts_line = counts_verdict(label(k, c), k.row->counts_like, run.counts,
                                                   e.records, c.params, c.pairs.size());
    if (!counts_line.empty()) emit(k, counts_line);
    if (cmp.ok() && counts_line.empty()) {
      ++k.outcome.passed;
      return true;
    }
    ++k.outcome.failed;
    k.outcome.state = BackendState::kFailed;
    return false;
  }

 private:
  static CaseLabel label(const Contender& k, const CheckCase& c) {
    return {k.row->name, c.name, c.setting};
  }
  bool fail(Contender& k, const CheckCase& c, const std::string& what) {
    emit(k, label(k, c).prefix() + " " + what);
    ++k.outcome.failed;
    k.outcome.state = BackendState::kFailed;
    return false;
  }
  void emit(Contender& k, const std::string& line) {
    out_ << line << '\n' << std::flush;
    k.outcome.failures.push_back(line);
  }
  static std::string blocks(const OwnedPair& p, const PoiRecord& r) {
    const FramePair f = p.view();
    return "    prev block at (" + std::to_string(r.x) + "," + std::to_string(r.y) + "):\n" +
           block_dump(f.prev, r.x, r.y) + "    next block at the expected match (" +
           std::to_string(r.x + r.dx) + "," + std::to_string(r.y + r.dy) + "), with its border:\n" +
           block_dump(f.next, r.x + r.dx - 1, r.y + r.dy - 1);
  }

  const CheckOptions& o_;
  std::ostream& out_;
  MismatchExplainer explainer_;
};

}  // namespace

const char* state_name(BackendState s) {
  switch (s) {
    case BackendState::kPassed:
      return "passed";
    case BackendState::kFailed:
      return "failed";
    case BackendState::kSkipped:
      return "skipped";
    case BackendState::kReference:
      return "reference";
    case BackendState::kIncomplete:
      return "incomplete";
  }
  return "?";
}

BackendState state_from_name(const std::string& name) {
  for (BackendState s : {BackendState::kPassed, BackendState::kFailed, BackendState::kSkipped,
                         BackendState::kReference, BackendState::kIncomplete})
    if (name == state_name(s)) return s;
  throw std::invalid_argument("unknown backend state '" + name + "'");
}

std::string CheckReport::verdict() const {
  if (!complete) return "incomplete";
  if (failed > 0) return "failed";
  if (!missing_shards.empty()) return "incomplete";
  if (compared == 0) return "nothing-checked";
  return "passed";
}

namespace {

// A contender's tallies before a case, to undo a case a signal cut short: the file then holds
// whole cases only, and a resumed run checks that case again from its start.
struct Mark {
  BackendState state;
  long passed, failed, not_applicable, pairs;
  double seconds;
  std::size_t failures, limits;
};

Mark mark(const BackendOutcome& b) {
  return {b.state, b.passed,  b.failed,          b.not_applicable,
          b.pairs, b.seconds, b.failures.size(), b.limits.size()};
}

void undo(BackendOutcome& b, const Mark& m) {
  b.state = m.state, b.passed = m.passed, b.failed = m.failed;
  b.not_applicable = m.not_applicable, b.pairs = m.pairs, b.seconds = m.seconds;
  b.failures.resize(m.failures), b.limits.resize(m.limits);
}

std::string cases_done(const CheckReport& r) {
  return std::to_string(r.cases) + " of " + counted(r.range.size(), "case");
}

// Whether some opened contender runs case `c`; when none does, each that would have counts it
// n/a, and ref-original need not answer it (the largest limit cases are often n/a for a row).
bool anyone_runs(std::vector<Contender>& contenders, const CheckCase& c) {
  std::vector<Contender*> outside;
  for (auto& k : contenders) {
    if (!k.backend || !c.for_row(k.row->name)) continue;
    if (!k.backend->outside_limits(c.params)) return true;
    outside.push_back(&k);
  }
  for (Contender* k : outside) ++k->outcome.not_applicable;
  return false;
}

// One case: ref-original's answer and its own counts, then every opened contender against it.
// Returns 1 when ref-original miscounts (a failure no backend's tally holds), else 0.
long check_case(Checker& checker, std::vector<Contender>& contenders, const CheckCase& c,
                long index, std::ostream& out) {
  if (!anyone_runs(contenders, c)) return 0;
  std::vector<FramePair> views;
  for (const auto& p : c.pairs) views.push_back(p.view());
  const auto r0 = std::chrono::steady_clock::now();
  const ReferenceAnswer e = reference_answer(views, c.params);
  const double reference_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - r0).count();
  // The answer's own counts: a miscounting ref-original would hold every row to wrong counts.
  const std::string reference_counts =
      counts_verdict({"ref-original", c.name, c.setting}, RefVariant::kOriginal, e.counts,
                     e.records, c.params, c.pairs.size());
  if (!reference_counts.empty()) out << reference_counts << '\n' << std::flush;
  for (auto& k : contenders)
    if (k.backend && c.for_row(k.row->name)) checker.run_case(k, c, e, index, reference_seconds);
  return reference_counts.empty() ? 0 : 1;
}

// PXFLOW_TEST_STOP_AFTER_CASES=N, a test-only knob (docs/harness.md, "Stopping and resuming a
// campaign"): after N cases of this run the check raises SIGINT on itself, exactly as a Ctrl-C
// there would, so that tests stop a campaign at a known case. 0 (unset): never.
long test_stop_after_cases() {
  const char* n = std::getenv("PXFLOW_TEST_STOP_AFTER_CASES");
  return n ? std::strtol(n, nullptr, 10) : 0;
}

// Runs the cases of the range not done yet, in order; a signal stops it between cases (a case
// it cut short is undone) and throws Interrupted.
void run_cases(const CheckOptions& o, Campaign& campaign, std::vector<Contender>& contenders,
               CheckReport& report, long& reference_failures, std::ostream& out) {
  Checker checker(o, out);
  // Totals on the live line for the fixed corpus as for a fuzz campaign: this run's share.
  const std::string of_cases = " of " + counted(report.range.size(), "case") + ", ";
  const std::string of_pairs = " of " + counted(campaign.pairs_in(report.range), "pair");
  const long stop_after = test_stop_after_cases(), first = report.range.first + report.cases;
  for (long index = first; index < report.range.end; ++index) {
    stop_if_interrupted(cases_done(report));
    const CheckCase c = campaign.take(index);
    progress("check: " + std::to_string(report.cases + 1) + of_cases +
             std::to_string(report.pairs + static_cast<long>(c.pairs.size())) + of_pairs);
    std::vector<Mark> marks;
    for (const Contender& k : contenders) marks.push_back(mark(k.outcome));
    try {
      reference_failures += check_case(checker, contenders, c, index, out);
    } catch (const Interrupted&) {
      for (std::size_t i = 0; i < contenders.size(); ++i) undo(contenders[i].outcome, marks[i]);
      throw;
    }
    ++report.cases;
    report.pairs += static_cast<long>(c.pairs.size());
    if (index + 1 - first == stop_after) std::raise(SIGINT);
  }
}

void describe_campaign(CheckReport& report, const Campaign& campaign, const CheckOptions& o,
                       const std::vector<Contender>& contenders) {
  CampaignInfo& info = report.campaign;
  info.kind = campaign.kind();
  info.fuzz_pairs = o.fuzz_pairs;
  info.generated_only = !o.corpus.real;
  info.fingerprint = campaign.fingerprint();
  info.settings = campaign.settings();
  for (const auto& k : contenders) info.backends.push_back(k.row->name);
  info.require = o.require;
  info.cases = campaign.cases();
  info.pairs = campaign.pairs();
  report.options = {o.corpus.data_dir,    o.backend_options.device,  o.global_options,
                    o.corpus.limits_only, o.backend_options.threads, o.isolation.case_timeout,
                    o.corpus.params};
}

// Takes over the stopped run `o.resume`: its cases done, its tallies and failure lines. Returns
// its failures no backend's tally holds.
long take_over(const CheckOptions& o, CheckReport& report, std::vector<Contender>& contenders) {
  const CheckReport& before = *o.resume;
  const std::string label = "--resume " + o.resume_file;
  check_same_campaign(label, before, report);
  for (std::size_t i = 0; i < contenders.size(); ++i) {
    Contender& k = contenders[i];
    check_same_backend(label, before.backends[i], k.outcome, k.backend != nullptr);
    k.outcome = before.backends[i];
    if (k.outcome.state == BackendState::kIncomplete) k.outcome.state = BackendState::kPassed;
  }
  report.cases = before.cases;
  report.pairs = before.pairs;
  return reference_count_failures(before);
}

// The totals over the backends; a stopped run's backends that failed nothing yet are incomplete.
void tally(CheckReport& report, std::vector<Contender>& contenders, long reference_failures) {
  report.failed = reference_failures;
  for (auto& k : contenders) {
    BackendOutcome& b = k.outcome;
    if (b.state == BackendState::kReference) {
      b.reason = "the answer the others are checked against";
    } else if (!k.backend) {
      (b.state == BackendState::kFailed ? report.failed : report.skipped) += report.cases;
    } else {
      report.passed += b.passed;
      report.failed += b.failed;
      report.not_applicable += b.not_applicable;
      report.compared += b.passed + b.failed;
      if (!report.complete && b.state == BackendState::kPassed) b.state = BackendState::kIncomplete;
    }
    report.backends.push_back(b);
  }
}

}  // namespace

CheckReport run_check(const CheckOptions& o, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  CheckReport report;
  report.seed = o.corpus.seed;
  report.command = o.command;
  report.pxflow_version = o.pxflow_version;
  report.pxflow_commit = o.pxflow_commit;
  report.shard = o.shard;
  std::vector<Contender> contenders = select_backends(o);

  // The fixed corpus is built whole in every shard (its fingerprint covers every case); a fuzz
  // campaign's batches are made one at a time, so that 100,000 pairs never sit in memory.
  Campaign campaign({o.fuzz_pairs, o.corpus, limit_rows(contenders)});
  if (o.shard.count > campaign.cases())
    throw InputError("--shard " + o.shard.text() + ": the campaign has " +
                     counted(campaign.cases(), "case") + " (" +
                     (o.fuzz_pairs > 0 ? "batches of 256 pairs" : "the fixed corpus") +
                     "): at most that many shards (see pxflow check --help)");
  report.range = shard_range(campaign.cases(), o.shard);
  describe_campaign(report, campaign, o, contenders);
  long reference_failures = o.resume ? take_over(o, report, contenders) : 0;

  if (!o.banner.empty()) out << o.banner << "\n";
  for (const std::string& why : campaign.dropped())
    out << "left out at" << o.corpus.params.options() << ": " << why << "\n";
  for (auto& k : contenders) {
    if (k.backend || k.outcome.state == BackendState::kReference) continue;
    if (k.outcome.state == BackendState::kFailed)
      out << k.outcome.failures.front() << "\n";
    else
      out << "skip " << k.row->name << " (" << k.outcome.reason << ")\n";
  }
  try {
    run_cases(o, campaign, contenders, report, reference_failures, out);
  } catch (const Interrupted& e) {
    report.complete = false;
    report.stop =
        Interrupted(e.signal, std::string(signal_name(e.signal)) + " after " + cases_done(report));
  }
  progress("");  // clears the live line
  tally(report, contenders, reference_failures);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() +
                   (o.resume ? o.resume->seconds : 0);
  return report;
}

}  // namespace pxflow
