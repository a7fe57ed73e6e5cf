// The GAP8 kernel's records are ref-original's, byte for byte, on random, hostile and real pairs
// at px4flow-64 and px4flow-head, on 1 and 8 cores, in every variant; and on a larger frame that
// still fits L1.
#include <catch2/catch.hpp>

#include "exact_check.hpp"
#include "gap8_backend.hpp"
#include "gap8_test_util.hpp"
#include "grid.hpp"

namespace pxflow::test {
namespace {

// The whole corpus as one batch (run() also checks the kernel's own estimate).
void check_variant(const Gap8VariantInfo& v, int cores, const std::string& setting, const Params& p,
                   int n_random, std::uint64_t seed) {
  Gap8Backend backend(v.id, gap8_host::RunOptions{cores, true, false});
  REQUIRE(backend.unsupported(p).empty());
  const std::string who = std::string("gap8-") + v.name + " on " + std::to_string(cores) + " cores";
  require_exact({who, "gap8 corpus", setting}, gap8_corpus(p, n_random, seed), p,
                batch_run_of(backend));
}

}  // namespace

TEST_CASE("gap8 variants are bit-exact at both profiles on 1 and 8 cores", "[gap8][no-sanitizer]") {
  for (const char* profile_name : {"px4flow-64", "px4flow-head"}) {
    const Params p = profile(profile_name);
    for (const Gap8VariantInfo& v : gap8_variants())
      for (int cores : {1, 8}) check_variant(v, cores, profile_name, p, 6, 1000 + cores);
  }
}

TEST_CASE("gap8 is bit-exact on a larger frame that fits L1, odd width included",
          "[gap8][no-sanitizer]") {
  Params p = profile("px4flow-64");
  p.width = 101;  // not a multiple of 4: the global planes' row tails are computed bytewise
  p.height = 72;
  p.search_radius = 7;
  p.blocks = 6;
  p.hist_filter = false;
  validate(p);
  for (const Gap8VariantInfo& v : gap8_variants())
    check_variant(v, 8, "101x72 S=7 B=6", p, 3, 3000);
}

}  // namespace pxflow::test
