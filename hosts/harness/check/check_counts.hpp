// Counts are part of the check: a backend that counts its work (OpCounts::counted) must give what
// its row's counting model (BackendRow::counts_like, docs/counting.md) gives on the reference's
// records. A difference fails the case like a record difference.
#pragma once
#include <optional>
#include <span>
#include <string>

#include "exactness.hpp"
#include "kernel.hpp"

namespace pxflow {

// Empty when `got` is not counted or equals the model's counts for `want` (ref-original's
// records of `pairs` pairs); otherwise the one failure line, e.g. "FAIL swar case=random[...]
// counts differ from ref-original's: sad_ops 92,032 vs 91,520 (got vs model)". A row that
// counts without a model fails too.
std::string counts_verdict(const CaseLabel& label, std::optional<RefVariant> model,
                           const OpCounts& got, std::span<const PoiRecord> want, const Params& p,
                           std::size_t pairs);

}  // namespace pxflow
