#include "check.hpp"

#include <unistd.h>

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
#include "grid.hpp"
#include "record_diff.hpp"
#include "registry.hpp"

namespace pxflow {
namespace {

constexpr unsigned char kSentinel = 0xA5;

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
  for (const auto& name : o.require)
    if (name != "all") find_backend(name);  // unknown names are bad input
  for (auto& c : out) {
    c.outcome.name = c.row->name;
    std::string why = c.row->probe();
    if (why.empty()) {
      try {
        c.backend = c.row->create(o.backend_options);
      } catch (const std::exception& e) {
        why = std::string("set-up failed: ") + e.what();
      }
    }
    if (!why.empty()) {
      const bool required = all || std::find(o.require.begin(), o.require.end(), c.row->name) != o.require.end();
      c.outcome.state = required ? "failed" : "skipped";
      c.outcome.reason = why;
      if (required) c.outcome.failures.push_back("FAIL " + c.row->name + ": required but cannot run: " + why);
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
      s << ' ' << ((xx >= 0 && yy >= 0 && xx < f.width && yy < f.height) ? std::to_string(f.at(xx, yy)) : "--");
    }
    s << '\n';
  }
  return s.str();
}

struct Expected {
  std::vector<PoiRecord> records;
  std::vector<FrameResult> results;
};

Expected reference_answer(const CheckCase& c) {
  Expected e;
  const std::size_t per = poi_count(c.params);
  std::vector<FramePair> views;
  for (const auto& p : c.pairs) views.push_back(p.view());
  e.records.resize(per * views.size());
  OpCounts counts;
  find_backend("ref-original").create({})->run(views, c.params, e.records, counts);
  for (std::size_t n = 0; n < views.size(); ++n)
    e.results.push_back(estimate_flow(std::span(e.records).subspan(n * per, per), c.params));
  return e;
}

class Checker {
 public:
  Checker(const CheckOptions& o, std::ostream& out) : o_(o), out_(out) {}

  // Runs one case on one contender; returns false when it failed.
  bool run_case(Contender& k, const CheckCase& c, const Expected& e) {
    if (const std::string why = k.backend->unsupported(c.params); !why.empty()) {
      ++k.outcome.not_applicable;
      return true;
    }
    const std::size_t per = poi_count(c.params);
    std::vector<FramePair> views;
    for (const auto& p : c.pairs) views.push_back(p.view());
    std::vector<PoiRecord> got(e.records.size());
    std::memset(got.data(), kSentinel, got.size() * sizeof(PoiRecord));
    OpCounts counts;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      k.backend->run(views, c.params, got, counts);
    } catch (const std::exception& ex) {
      return fail(k, c, std::string("error: ") + ex.what());
    }
    k.outcome.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    k.outcome.pairs += static_cast<long>(c.pairs.size());
    int lines = 0, mismatches = 0;
    for (std::size_t pair = 0; pair < c.pairs.size(); ++pair) {
      const std::string where = prefix(k, c) + " pair=" + c.pairs[pair].name;
      for (std::size_t n = 0; n < per; ++n) {
        const PoiRecord& want = e.records[pair * per + n];
        const PoiRecord& have = got[pair * per + n];
        std::optional<FieldDiff> d = untouched(have, kSentinel)
                                         ? FieldDiff{"record", "written", "never written (sentinel intact)"}
                                         : first_difference(want, have);
        if (!d) continue;
        if (++mismatches > o_.max_lines_per_case) continue;
        std::string line = where + " poi=" + std::to_string(n) + " (x=" + std::to_string(want.x) +
                           ",y=" + std::to_string(want.y) + ") field=" + d->field + " expected=" + d->expected +
                           " got=" + d->got;
        if (o_.verbose) line += "\n" + blocks(c.pairs[pair], want);
        lines += emit(k, line);
      }
      const FrameResult r = estimate_flow(std::span(got).subspan(pair * per, per), c.params);
      for (auto [field, want, have] : {std::tuple{"flow_x", e.results[pair].flow_x, r.flow_x},
                                       std::tuple{"flow_y", e.results[pair].flow_y, r.flow_y}})
        if (std::bit_cast<std::uint32_t>(want) != std::bit_cast<std::uint32_t>(have) &&
            ++mismatches <= o_.max_lines_per_case)
          lines += emit(k, where + " field=" + field + " expected=" + float_bits_hex(want) +
                              " got=" + float_bits_hex(have));
    }
    if (mismatches > o_.max_lines_per_case)
      emit(k, prefix(k, c) + " ... and " + std::to_string(mismatches - o_.max_lines_per_case) + " more mismatches");
    if (mismatches == 0) {
      ++k.outcome.passed;
      return true;
    }
    ++k.outcome.failed;
    k.outcome.state = "failed";
    return false;
  }

 private:
  static std::string prefix(const Contender& k, const CheckCase& c) {
    return "FAIL " + k.row->name + " case=" + c.name + "[" + c.setting + "]";
  }
  bool fail(Contender& k, const CheckCase& c, const std::string& what) {
    emit(k, prefix(k, c) + " " + what);
    ++k.outcome.failed;
    k.outcome.state = "failed";
    return false;
  }
  int emit(Contender& k, const std::string& line) {
    out_ << line << '\n' << std::flush;
    k.outcome.failures.push_back(line);
    return 1;
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

void progress(const std::string& text) {
  static const bool tty = isatty(2);
  if (tty) std::fprintf(stderr, "\r\033[K%s", text.c_str());
}

}  // namespace

CheckReport run_check(const CheckOptions& o, std::ostream& out) {
  CheckReport report;
  report.seed = o.corpus.seed;
  std::vector<Contender> contenders = select_backends(o);
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
      const auto& [setting, p] = settings[(fuzz_done / 256) % 2];  // alternate the two 64x64 profiles
      c = fuzz_case(setting, p, o.corpus.seed * 1000000007ull + static_cast<std::uint64_t>(fuzz_done), n);
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
    if (k.backend) continue;
    if (k.outcome.state == "failed")
      out << k.outcome.failures.front() << "\n";
    else
      out << "skip " << k.row->name << " (" << k.outcome.reason << ")\n";
  }

  CheckCase c;
  while (next_case(c)) {
    ++report.cases;
    report.pairs += static_cast<long>(c.pairs.size());
    progress("check: " + std::to_string(report.cases) + " cases, " + std::to_string(report.pairs) +
             (o.fuzz_pairs > 0 ? " of " + std::to_string(o.fuzz_pairs) : std::string()) + " pairs");
    const Expected e = reference_answer(c);
    for (auto& k : contenders)
      if (k.backend) checker.run_case(k, c, e);
  }
  progress("");  // clears the live line

  for (auto& k : contenders) {
    BackendOutcome& b = k.outcome;
    if (!k.backend) {
      (b.state == "failed" ? report.failed : report.skipped) += report.cases;
    } else {
      report.passed += b.passed;
      report.failed += b.failed;
      report.not_applicable += b.not_applicable;
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
  j["backends"] = Json::array();
  for (const auto& b : r.backends)
    j["backends"].push_back({{"name", b.name}, {"state", b.state}, {"reason", b.reason},
                             {"passed", b.passed}, {"failed", b.failed}, {"not_applicable", b.not_applicable},
                             {"pairs", b.pairs}, {"seconds", b.seconds}, {"failures", b.failures}});
  return j;
}

}  // namespace pxflow
