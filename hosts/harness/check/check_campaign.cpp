#include "check_campaign.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "errors.hpp"
#include "fnv1a.hpp"
#include "result_json.hpp"

namespace pxflow {
namespace {

// A fuzz campaign's batch: 256 pairs, the last one what is left.
constexpr long kFuzzBatch = 256;

// A fingerprint of the inputs (fnv1a.hpp).
class CaseFingerprint : public Fnv1a {
 public:
  using Fnv1a::add;
  void add(const std::string& s) { add(s.data(), s.size() + 1); }  // with its '\0'
  void add(const CheckCase& c) {
    add(c.name), add(c.setting), add(params_json(c.params).dump());
    for (const std::string& row : c.rows) add(row);
    for (const OwnedPair& p : c.pairs) {
      add(p.name), add(std::to_string(p.width) + "x" + std::to_string(p.height));
      add(p.prev.data(), p.prev.size()), add(p.next.data(), p.next.size());
    }
  }
};

void note_setting(std::vector<std::string>& settings, const std::string& s) {
  if (std::find(settings.begin(), settings.end(), s) == settings.end()) settings.push_back(s);
}

}  // namespace

std::string Shard::text() const { return std::to_string(index) + "/" + std::to_string(count); }

Shard parse_shard(const std::string& option, const std::string& text) {
  auto number = [](std::string_view s, int& v) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size() && !s.empty() && s[0] != '+';
  };
  const auto slash = text.find('/');
  Shard s;
  if (slash == std::string::npos || !number(std::string_view(text).substr(0, slash), s.index) ||
      !number(std::string_view(text).substr(slash + 1), s.count) || s.count < 1 ||
      s.count > 100000 || s.index < 1 || s.index > s.count)
    throw InputError(option + ": '" + text +
                     "': K/M with 1 <= K <= M <= 100000, e.g. 2/4 for the second of four shards "
                     "(see pxflow check --help)");
  return s;
}

CaseRange shard_range(long cases, const Shard& s) {
  return {(s.index - 1) * cases / s.count, s.index * cases / s.count};
}

Campaign::Campaign(const CampaignOptions& o) : fuzz_pairs_(o.fuzz_pairs), seed_(o.corpus.seed) {
  CaseFingerprint h;
  if (fuzz()) {
    fuzz_settings_ = check_settings(o.corpus.params, &dropped_);
    fuzz_settings_.resize(std::min<std::size_t>(fuzz_settings_.size(), 2));
    if (fuzz_settings_.size() < 2 || fuzz_settings_[1].second.width != 64)
      throw InputError("--cases: the fuzz campaign's 64x64 pairs cannot run at" +
                       o.corpus.params.options() + " (" + dropped_.front() + ")");
    cases_ = (fuzz_pairs_ + kFuzzBatch - 1) / kFuzzBatch;
    for (long b = 0; b < std::min(cases_, 2L); ++b) {
      const CheckCase c = fuzz_batch(b);
      h.add(c);
      settings_.push_back(c.setting);
    }
  } else {
    if (!o.corpus.limits_only) corpus_ = build_check_corpus(o.corpus, &dropped_);
    for (CheckCase& c : limit_cases(o.limit_rows, seed_)) corpus_.push_back(std::move(c));
    cases_ = static_cast<long>(corpus_.size());
    for (const CheckCase& c : corpus_) {
      h.add(c);
      corpus_pairs_.push_back(static_cast<long>(c.pairs.size()));
      note_setting(settings_, c.setting);
    }
  }
  fingerprint_ = h.hex();
}

long Campaign::pairs() const { return pairs_in({0, cases_}); }

long Campaign::pairs_in(const CaseRange& r) const {
  if (!fuzz()) {
    long n = 0;
    for (long i = r.first; i < r.end; ++i) n += corpus_pairs_[static_cast<std::size_t>(i)];
    return n;
  }
  return std::min(r.end * kFuzzBatch, fuzz_pairs_) - std::min(r.first * kFuzzBatch, fuzz_pairs_);
}

CheckCase Campaign::take(long index) {
  if (fuzz()) return fuzz_batch(index);
  return std::move(corpus_[static_cast<std::size_t>(index)]);
}

// Batch b holds pairs [256b, 256b + n) with seeds from seed * 1000000007 + 256b, alternating the
// two 64x64 profiles, so any batch is made without the ones before it.
CheckCase Campaign::fuzz_batch(long index) const {
  const auto& settings = fuzz_settings_;
  const long done = index * kFuzzBatch;
  const int n = static_cast<int>(std::min(kFuzzBatch, fuzz_pairs_ - done));
  const auto& [setting, p] = settings[static_cast<std::size_t>(index % 2)];
  CheckCase c = fuzz_case(setting, p, seed_ * 1000000007ull + static_cast<std::uint64_t>(done), n);
  c.name = "fuzz";
  return c;
}

}  // namespace pxflow
