#include "check_counts.hpp"

#include <cstdint>

#include "counted.hpp"
#include "counting_model.hpp"

namespace pxflow {

std::string counts_verdict(const CaseLabel& label, std::optional<RefVariant> model,
                           const OpCounts& got, std::span<const PoiRecord> want, const Params& p,
                           std::size_t pairs) {
  if (!got.counted) return {};
  if (!model)
    return label.prefix() +
           " counts its work but its row names no counting model (BackendRow::counts_like)";
  const OpCounts expected = model_counts(*model, want, p, pairs);
  std::string diffs;
  auto field = [&](const char* name, std::uint64_t g, std::uint64_t e) {
    if (g == e) return;
    diffs +=
        (diffs.empty() ? " " : ", ") + std::string(name) + " " + grouped(g) + " vs " + grouped(e);
  };
  field("sad_ops", got.sad_ops, expected.sad_ops);
  field("interpolations", got.interpolations, expected.interpolations);
  if (diffs.empty()) return {};
  return label.prefix() + " counts differ from " + std::string(ref_variant_name(*model)) +
         "'s:" + diffs + " (got vs its counting model, docs/counting.md)";
}

}  // namespace pxflow
