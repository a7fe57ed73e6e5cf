#include "check.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstring>
#include <functional>
#include <memory>
#include <ostream>
#include <sstream>

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
  std::unique_ptr<Backend> backend;  // null when skipped
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
  for (auto& c : out) {
    c.outcome.name = c.row->name;
    if (c.row->name == kReferenceBackend) {
      // The answer every other backend is checked against is not checked against itself.
      c.outcome.state = BackendState::kReference;
      continue;
    }
    OpenedBackend opened = open_backend(*c.row, o.backend_options);
    c.backend = std::move(opened.backend);
    const std::string why = opened.why_not;
    if (!why.empty()) {
      const bool required =
          all || std::find(o.require.begin(), o.require.end(), c.row->name) != o.require.end();
      c.outcome.state = required ? BackendState::kFailed : BackendState::kSkipped;
      c.outcome.reason = why;
      if (required)
        c.outcome.failures.push_back("FAIL " + c.row->name + ": required but cannot run: " + why);
    }
  }
  return out;
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
  Checker(const CheckOptions& o, std::ostream& out) : o_(o), out_(out) {}

  // Runs one case on one contender; returns false when it failed.
  bool run_case(Contender& k, const CheckCase& c, const ReferenceAnswer& e) {
    if (const std::string why = k.backend->unsupported(c.params); !why.empty()) {
      ++k.outcome.not_applicable;
      return true;
    }
    std::vector<FramePair> views;
    std::vector<std::string> names;
    for (const auto& p : c.pairs) views.push_back(p.view()), names.push_back(p.name);
    std::vector<PoiRecord> got = sentinel_records(e.records.size());
    OpCounts counts;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      k.backend->run(views, c.params, got, counts);
    } catch (const std::exception& ex) {
      return fail(k, c, std::string("error: ") + ex.what());
    }
    k.outcome.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    k.outcome.pairs += static_cast<long>(c.pairs.size());
    RecordDetail detail;
    if (o_.verbose)
      detail = [&](std::size_t pair, const PoiRecord& want) { return blocks(c.pairs[pair], want); };
    const Comparison cmp =
        compare_with_reference(label(k, c), names, c.params, e, got, o_.max_lines_per_case, detail);
    for (const std::string& line : cmp.lines) emit(k, line);
    if (cmp.ok()) {
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
  }
  return "?";
}

CheckReport run_check(const CheckOptions& o, std::ostream& out) {
  CheckReport report;
  report.seed = o.corpus.seed;
  std::vector<Contender> contenders = select_backends(o);
  if (!o.banner.empty()) out << o.banner << "\n";
  Checker checker(o, out);

  // The cases come from the fixed corpus or, for a fuzz campaign, are made batch by batch so
  // that 100,000 pairs never sit in memory at once.
  std::function<bool(CheckCase&)> next_case;
  std::vector<CheckCase> corpus;
  std::size_t corpus_at = 0;
  long fuzz_done = 0;
  const auto settings = check_settings();
  if (o.fuzz_pairs > 0) {
    next_case = [&](CheckCase& c) {
      if (fuzz_done >= o.fuzz_pairs) return false;
      const int n = static_cast<int>(std::min<long>(256, o.fuzz_pairs - fuzz_done));
      const auto& [setting, p] =
          settings[(fuzz_done / 256) % 2];  // alternate the two 64x64 profiles
      c = fuzz_case(setting, p,
                    o.corpus.seed * 1000000007ull + static_cast<std::uint64_t>(fuzz_done), n);
      c.name = "fuzz";
      fuzz_done += n;
      return true;
    };
  } else {
    corpus = build_check_corpus(o.corpus);
    next_case = [&](CheckCase& c) {
      if (corpus_at >= corpus.size()) return false;
      c = std::move(corpus[corpus_at++]);
      return true;
    };
  }
  for (auto& k : contenders) {
    if (k.backend || k.outcome.state == BackendState::kReference) continue;
    if (k.outcome.state == BackendState::kFailed)
      out << k.outcome.failures.front() << "\n";
    else
      out << "skip " << k.row->name << " (" << k.outcome.reason << ")\n";
  }

  CheckCase c;
  while (next_case(c)) {
    stop_if_interrupted(std::to_string(report.cases) + " finished cases");
    ++report.cases;
    report.pairs += static_cast<long>(c.pairs.size());
    progress("check: " + std::to_string(report.cases) + " cases, " + std::to_string(report.pairs) +
             (o.fuzz_pairs > 0 ? " of " + std::to_string(o.fuzz_pairs) : std::string()) + " pairs");
    std::vector<FramePair> views;
    for (const auto& p : c.pairs) views.push_back(p.view());
    const ReferenceAnswer e = reference_answer(views, c.params);
    for (auto& k : contenders)
      if (k.backend) checker.run_case(k, c, e);
  }
  progress("");  // clears the live line

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
    }
    report.backends.push_back(b);
  }
  return report;
}

Json check_json(const CheckReport& r) {
  Json j;
  j["seed"] = r.seed;
  j["cases"] = r.cases;
  j["pairs"] = r.pairs;
  j["passed"] = r.passed;
  j["failed"] = r.failed;
  j["skipped"] = r.skipped;
  j["not_applicable"] = r.not_applicable;
  j["compared"] = r.compared;
  j["backends"] = Json::array();
  for (const auto& b : r.backends)
    j["backends"].push_back({{"name", b.name},
                             {"state", state_name(b.state)},
                             {"reason", b.reason},
                             {"passed", b.passed},
                             {"failed", b.failed},
                             {"not_applicable", b.not_applicable},
                             {"pairs", b.pairs},
                             {"seconds", b.seconds},
                             {"failures", b.failures}});
  return j;
}

}  // namespace pxflow
