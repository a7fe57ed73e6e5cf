// A check campaign: the cases `pxflow check` runs, numbered in a fixed order, and the part of
// them one shard of a CI matrix runs (`--shard K/M`). The unit of a shard is a case, one batch
// of one run() call: the fixed corpus's cases, or a fuzz campaign's batches of 256 random pairs.
// Shard K of M runs the contiguous cases [floor((K-1)C/M), floor(KC/M)) of the C cases, so the
// M shards are disjoint, together they are the whole campaign, and each shard's failure lines
// are the unsharded run's lines of those cases, in the same order (docs/ci-campaigns.md).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "check_corpus.hpp"
#include "check_limits.hpp"

namespace pxflow {

// K/M, 1 <= K <= M.
struct Shard {
  int index = 1, count = 1;
  std::string text() const;  // "K/M"
};

// "K/M" -> Shard; throws InputError in the CLI's style naming `option` when the text is not one.
Shard parse_shard(const std::string& option, const std::string& text);

// The cases [first, end) of a campaign.
struct CaseRange {
  long first = 0, end = 0;
  long size() const { return end - first; }
};
CaseRange shard_range(long cases, const Shard& s);

struct CampaignOptions {
  long fuzz_pairs = 0;  // > 0: a fuzz campaign of that many random pairs; 0: the fixed corpus
  CorpusOptions corpus;
  // The selected rows whose limits the fixed corpus adds cases for (check_limits.hpp).
  std::vector<LimitRow> limit_rows;
};

class Campaign {
 public:
  // Builds the fixed corpus (real frames read, synthetic motion made) or plans the fuzz
  // batches. Throws InputError when a real frame cannot be read.
  explicit Campaign(const CampaignOptions& o);

  const char* kind() const { return fuzz() ? "fuzz" : "fixed-corpus"; }
  long cases() const { return cases_; }  // of the whole campaign
  long pairs() const;                    // of the whole campaign
  long pairs_in(const CaseRange& r) const;
  // The parameter settings the campaign's cases use, in first-use order.
  const std::vector<std::string>& settings() const { return settings_; }
  // FNV-1a 64 (hex) over every case of the fixed corpus (names, parameters, pair names and
  // pixels), or over the first batch of each setting of a fuzz campaign: shards made on machines
  // whose OpenCV decodes or warps differently do not have the same inputs, and merge refuses
  // them.
  const std::string& fingerprint() const { return fingerprint_; }
  // The settings --profile/--set left out, each with its reason (CorpusOptions::params).
  const std::vector<std::string>& dropped() const { return dropped_; }

  // Case `index` (0-based). For the fixed corpus the case is moved out: call it once per index.
  CheckCase take(long index);

 private:
  bool fuzz() const { return fuzz_pairs_ > 0; }
  CheckCase fuzz_batch(long index) const;

  long fuzz_pairs_ = 0;
  std::uint64_t seed_ = 0;
  long cases_ = 0;
  std::vector<CheckCase> corpus_;
  std::vector<long> corpus_pairs_;  // pairs per fixed-corpus case (its pairs may be moved out)
  std::vector<std::string> settings_, dropped_;
  std::vector<std::pair<std::string, Params>> fuzz_settings_;  // the two 64x64 profiles'
  std::string fingerprint_;
};

}  // namespace pxflow
