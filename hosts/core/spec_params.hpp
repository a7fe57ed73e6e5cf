// Params (reference/params.hpp, readable C++) as the spec core's parameter block, the form every
// freestanding kernel takes (spec/include/pxflow_spec/params.h). Included by the families whose
// kernels are freestanding (dut, gap8): their targets bring spec/include.
#pragma once
#include <cstdint>

#include "params.hpp"
#include "pxflow_spec/spec.h"

namespace pxflow {

inline pxflow_param_block spec_params(const Params& p) {
  auto u = [](int v) { return static_cast<std::uint32_t>(v); };
  return {u(p.width),         u(p.height),
          u(p.search_radius), u(p.tile),
          u(p.blocks),        u(p.feature_threshold),
          u(p.sad_threshold), p.hist_filter ? 1u : 0u,
          u(p.min_count),     p.gyro_comp ? 1u : 0u};
}

}  // namespace pxflow
