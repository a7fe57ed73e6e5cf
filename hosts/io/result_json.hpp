// Results out as JSON (nlohmann::json): the frame estimate, the counts and the records.
// Declarations only need the type's name: the header includes <nlohmann/json_fwd.hpp>, and a file
// that builds, reads or copies a Json includes <nlohmann/json.hpp> itself.
#pragma once
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>

#include "params.hpp"
#include "record.hpp"

namespace pxflow {

using Json = nlohmann::ordered_json;

// The IEEE-754 bits of f as 8 lowercase hex digits, e.g. 1.5f -> "3fc00000".
std::string float_bits_hex(float f);

Json record_json(const PoiRecord& r);
Json params_json(const Params& p);

// The object `pxflow flow --json` prints: flow_x, flow_y, their bits, quality, meancount,
// histx, histy, counts (only the counts the backend keeps) and pois.
Json flow_result_json(const FrameResult& result, std::span<const PoiRecord> records,
                      const OpCounts& counts);

}  // namespace pxflow
