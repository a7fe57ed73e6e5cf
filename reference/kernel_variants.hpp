// Internal: the three variant entry points behind reference_flow().
#pragma once
#include <span>

#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow::ref {

void run_original(const FramePair& f, const Params& p, std::span<PoiRecord> out, OpCounts& c);
void run_local(const FramePair& f, const Params& p, std::span<PoiRecord> out, OpCounts& c);
void run_global(const FramePair& f, const Params& p, std::span<PoiRecord> out, OpCounts& c);

}  // namespace pxflow::ref
