// Field-level comparison of two records, for mismatch lines a human can act on.
#pragma once
#include <optional>
#include <string>

#include "record.hpp"

namespace pxflow {

struct FieldDiff {
  std::string field;  // "sub[3]", "dir", "pad0", or "record" when it was never written
  std::string expected, got;
};

// The first field in which `got` differs from `expected`, or nothing when the 32 bytes agree.
std::optional<FieldDiff> first_difference(const PoiRecord& expected, const PoiRecord& got);

// True when every byte of r is `sentinel`: the backend never wrote this record.
bool untouched(const PoiRecord& r, unsigned char sentinel);

}  // namespace pxflow
