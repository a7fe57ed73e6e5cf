// Reads the width and height an image file declares, from its header alone, for the formats
// pxflow documents (PNG, BMP, PGM/PPM, JPEG). Lets the loader refuse an absurd size before the
// decoder allocates it. Returns nothing for other formats or a header it cannot read.
#pragma once
#include <optional>
#include <string>

#include "frame_io.hpp"

namespace pxflow {

std::optional<FrameSize> declared_image_size(const std::string& path);

}  // namespace pxflow
