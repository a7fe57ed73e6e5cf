// `pxflow merge`: the results of a campaign's shards (check --shard K/M) combined into the one
// result the unsharded run would have given: the same totals, the same states, the same failure
// lines in the same order (docs/ci-campaigns.md, "Campaigns over a CI matrix").
#pragma once
#include <string>
#include <vector>

#include "check.hpp"

namespace pxflow {

struct ShardFile {
  std::string file;  // the name errors and merged_from use
  CheckReport report;
};

// Throws InputError, one line naming the file and the field, when the files are not shards of
// one campaign: a different pxflow commit or version, seed, campaign (kind, --cases, corpus
// version or fingerprint, settings, backends, --require), shard count; a shard given twice; a
// merged file. Missing shards are no error here: the result is "incomplete" and lists them.
CheckReport merge_shards(const std::vector<ShardFile>& shards);

}  // namespace pxflow
