// Reads the width and height an image file's bytes declare, from its header alone, for the formats
// pxflow documents (PNG, BMP, PGM/PPM, JPEG). Lets the loader refuse an absurd size before the
// decoder allocates it. Returns nothing for other formats or a header it cannot read.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "frame_io.hpp"

namespace pxflow {

std::optional<FrameSize> declared_image_size(const std::vector<std::uint8_t>& bytes);

}  // namespace pxflow
