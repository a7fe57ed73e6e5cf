// A picture of one frame pair's flow (`pxflow flow --draw FILE`): the first frame enlarged, each
// POI with its vector coloured by status, the frame flow as one bold arrow, and a caption.
#pragma once
#include <span>
#include <string>

#include "frame.hpp"
#include "params.hpp"
#include "record.hpp"

namespace pxflow {

// Throws InputError unless `path` ends in .png (standard output, a device or a pipe aside):
// checked before any work.
void check_png_name(const std::string& option, const std::string& path);

struct DrawCaption {
  std::string frames;   // e.g. "rubberwhale1.png -> rubberwhale2.png"
  std::string backend;  // e.g. "cpu"
  std::string profile;  // e.g. "px4flow-64"
};

// The picture as PNG bytes, for an OutputFile or OutputFolder to write.
std::string flow_png(const FrameView& prev, const Params& p, std::span<const PoiRecord> records,
                     const FrameResult& result, const DrawCaption& caption);

}  // namespace pxflow
