#include "kernel.hpp"

#include "kernel_variants.hpp"

namespace pxflow {

std::string_view ref_variant_name(RefVariant v) {
  switch (v) {
    case RefVariant::kOriginal:
      return "ref-original";
    case RefVariant::kLocal:
      return "ref-local";
    case RefVariant::kGlobal:
      return "ref-global";
  }
  return "ref-?";
}

void reference_flow(RefVariant v, const FramePair& pair, const Params& p, std::span<PoiRecord> out,
                    OpCounts& counts) {
  counts.counted = true;
  switch (v) {
    case RefVariant::kOriginal:
      ref::run_original(pair, p, out, counts);
      break;
    case RefVariant::kLocal:
      ref::run_local(pair, p, out, counts);
      break;
    case RefVariant::kGlobal:
      ref::run_global(pair, p, out, counts);
      break;
  }
}

}  // namespace pxflow
