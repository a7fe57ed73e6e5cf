// The dummy family's rows: ref-original's kernel under the name dummy-original.
#include "backend.hpp"
#include "grid.hpp"
#include "kernel.hpp"

namespace pxflow {
namespace {

class DummyBackend final : public Backend {
 public:
  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override {
    const std::size_t per = poi_count(p);
    for (std::size_t n = 0; n < pairs.size(); ++n)
      reference_flow(RefVariant::kOriginal, pairs[n], p, out.subspan(n * per, per), counts);
  }
};

}  // namespace

BackendFamily dummy_family() {
  BackendRow row{"dummy-original", "nothing (test family)", [] { return std::string(); },
                 [](const BackendOptions&) { return std::make_unique<DummyBackend>(); }};
  row.counts_like = RefVariant::kOriginal;
  return {"dummy", {row}, {}, {}};
}

}  // namespace pxflow
