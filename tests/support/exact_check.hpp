// The harness's exactness check as a Catch2 assertion: the batch runs into sentinel-filled
// records, is compared with ref-original by check_exact() (hosts/harness/common/exactness.hpp), and
// a failure shows the same mismatch lines as `pxflow check`.
#pragma once
#include <catch2/catch.hpp>
#include <span>
#include <string>
#include <vector>

#include "exactness.hpp"
#include "synthetic.hpp"

namespace pxflow::test {

inline void require_exact(const CaseLabel& label, std::span<const OwnedPair> pairs, const Params& p,
                          const BatchRun& run) {
  std::vector<FramePair> views;
  std::vector<std::string> names;
  for (const OwnedPair& o : pairs) views.push_back(o.view()), names.push_back(o.name);
  const Comparison c = check_exact(label, views, names, p, run);
  INFO(c.text());
  REQUIRE(c.ok());
}

// A BatchRun of any backend-like object with run(pairs, params, out, counts).
template <typename B>
BatchRun batch_run_of(B& backend) {
  return [&backend](std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out) {
    OpCounts counts;
    backend.run(pairs, p, out, counts);
  };
}

}  // namespace pxflow::test
