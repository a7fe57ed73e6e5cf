// Kernel parameters and named profiles (SPEC §1). Validation lives here so that every entry
// point (CLI, harness, tests) rejects the same bad combinations with the same message.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pxflow {

struct Params {
  int width = 64;              // W, pixels; the row stride of a packed frame
  int height = 64;             // H
  int search_radius = 4;       // S, whole pixels, 1..31
  int tile = 8;                // T, always 8 (the kernel's 8x8 block)
  int blocks = 8;              // B, grid points per axis (upper bound)
  int feature_threshold = 40;  // FT, a POI is dropped when feature < FT
  int sad_threshold = 5000;    // VT, a match is accepted when best SAD < VT
  bool hist_filter = true;     // HF
  int min_count = 10;          // MINCOUNT
  bool gyro_comp = false;      // GC (needs a GyroSample at estimate time)

  bool operator==(const Params&) const = default;
};

// SPEC §1's limits, the values of the freestanding spec core (spec/include/pxflow_spec/params.h;
// reference/spec_core.cpp static_asserts each). T is the kernel's 8x8 block; S <= 31 keeps the
// half-pixel displacement 2S+1 inside an i8; B <= 255 keeps B*B POIs within u16 histogram bins
// and the quality formula; FT, VT and MINCOUNT are compared with u16 values.
inline constexpr int kTile = 8;
inline constexpr int kMinSearchRadius = 1;
inline constexpr int kMaxSearchRadius = 31;
inline constexpr int kMinBlocks = 1;
inline constexpr int kMaxBlocks = 255;
inline constexpr int kMaxThreshold = 65535;
// Frame size limits: records store coordinates as u16, and larger frames would be a typo.
inline constexpr int kMaxFrameSide = 16384;
inline constexpr std::int64_t kMaxFramePixels = std::int64_t{1} << 26;  // 64 Mpx

// The default profile (the ISCAS 2022 configuration): --profile's default, the first of
// profile_names(), and the problem the hosts' studies and reports are about.
inline constexpr std::string_view kDefaultProfile = "px4flow-64";

// Names of the built-in profiles, default first.
const std::vector<std::string>& profile_names();

// The named profile; throws InputError naming the profile and listing the known ones.
Params profile(std::string_view name);

// Names accepted by set_param, in the order --help lists them.
const std::vector<std::string>& param_keys();

// Applies KEY=VALUE (a --set argument) to p. Throws InputError for an unknown key or a value
// that is not a plain decimal integer (hist_filter/gyro_comp: 0 or 1). Ranges are checked by
// validate(), after all overrides are in.
void set_param(Params& p, std::string_view key, std::string_view value);

// One `--set KEY=VALUE`: set_param on its two sides; InputError naming it when it is not
// KEY=VALUE. Returns the key.
std::string_view set_param_assignment(Params& p, std::string_view assignment);

// pxflow's commands take no gyro rates, so GC on would add nothing: InputError when p.gyro_comp.
void require_no_gyro_comp(const Params& p);

// The smallest frame side with one POI at radius S (SPEC §2: lo = S+1 < hi = side-(S+1)-T).
constexpr int min_frame_side(int search_radius) { return 2 * (search_radius + 1) + kTile + 1; }

// Throws InputError with one line naming the offending parameter when p is not a valid
// combination (SPEC §1): T != 8, S outside 1..31, B outside 1..255, thresholds outside u16,
// a frame too small for one POI, or a frame beyond the size limits above.
void validate(const Params& p);

// Parses a decimal integer in [lo, hi]; throws InputError mentioning `what` otherwise.
int parse_int(std::string_view text, std::string_view what, std::int64_t lo, std::int64_t hi);

}  // namespace pxflow
