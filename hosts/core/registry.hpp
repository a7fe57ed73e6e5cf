// The registry: one row per backend compiled into this binary, reference variants first.
#pragma once
#include <string_view>
#include <vector>

#include "backend.hpp"

namespace pxflow {

const std::vector<BackendRow>& backend_rows();

// Appends a row. For test programs that need a backend the product does not ship (e.g. a
// deliberately broken one). Call it before anything looks rows up: it may move the table.
void add_backend_row(BackendRow row);

// The row named `name`; throws InputError listing the known names when there is none.
const BackendRow& find_backend(std::string_view name);

// Checks that `out` and every frame of `pairs` fit `p`; throws InputError otherwise. The entry
// points (CLI, harness) call it once so that backends can trust their inputs.
void check_batch(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out);

}  // namespace pxflow
