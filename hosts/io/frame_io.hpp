// Frames in: any 8-bit image OpenCV reads (colour converted to gray the OpenCV way, through the
// OpenCV module) or a raw 8-bit file of a given size. Every bad input is an InputError naming the
// file.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frame.hpp"

namespace pxflow {

struct FrameSize {
  int width = 0;
  int height = 0;
};

// Parses "WxH" (e.g. "64x64"); throws InputError for anything else or a size beyond the limits.
FrameSize parse_frame_size(std::string_view text);

// Loads one frame. With `raw_size` the file is raw 8-bit, whatever its name, and must hold
// exactly W*H bytes; without it a .raw file is an error and any other is decoded by OpenCV. A
// pipe is read like a file (hosts/io/input_file.hpp). Refuses 16-bit and float images, empty
// files, directories, devices, and images whose header declares more than kMaxFramePixels.
Frame load_frame(const std::string& path, std::optional<FrameSize> raw_size);

}  // namespace pxflow
