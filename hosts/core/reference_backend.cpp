// The reference variants as registry rows: single-threaded, always available, the yardstick
// every other backend is checked against.
#include "backend.hpp"
#include "grid.hpp"
#include "kernel.hpp"

namespace pxflow {
namespace {

class ReferenceBackend final : public Backend {
 public:
  explicit ReferenceBackend(RefVariant v) : variant_(v) {}

  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override {
    const std::size_t per_pair = poi_count(p);
    for (std::size_t n = 0; n < pairs.size(); ++n)
      reference_flow(variant_, pairs[n], p, out.subspan(n * per_pair, per_pair), counts);
  }

  // The file that holds the variant's own step ("ref-original" -> reference/kernel_original.cpp);
  // one thread always, so there is no thread count to say.
  Description describe() const override {
    std::string_view name = ref_variant_name(variant_);
    name.remove_prefix(name.find('-') + 1);
    return {"reference/kernel_" + std::string(name) + ".cpp (scalar C++)", {}, {}};
  }

 private:
  RefVariant variant_;
};

}  // namespace

BackendFamily reference_family() {
  BackendFamily family;
  family.name = "reference";
  auto& rows = family.rows;
  for (RefVariant v : kRefVariants) {
    BackendRow& row = rows.emplace_back(
        std::string(ref_variant_name(v)), "nothing (portable scalar C++)",
        [] { return std::string(); },
        [v](const BackendOptions&) { return std::make_unique<ReferenceBackend>(v); });
    row.counts_like = v;  // each variant counts by its own rules
  }
  return family;
}

}  // namespace pxflow
