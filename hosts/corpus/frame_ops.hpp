// Small operations that turn real frames into test and check inputs, in plain C++.
#pragma once
#include <string_view>

#include "frame.hpp"

namespace pxflow {

// The w x h window of `f` whose top-left corner is (x, y); must lie inside f.
Frame crop(const Frame& f, int x, int y, int w, int h);

// factor x factor pixels averaged into one, rounded to nearest: how the PX4FLOW camera (MT9V034,
// 752x480 read out with 4x binning) makes its small frames. Trailing partial blocks are dropped.
Frame bin(const Frame& f, int factor);

// What `--crop WxH+X+Y` and `--bin N` (pxflow flow, pxflow gap8) do to every input frame: the
// window first, in the input's own pixels (as an image viewer shows them), then the binning.
struct FrameShaping {
  bool cropped = false;
  int crop_x = 0, crop_y = 0, crop_w = 0, crop_h = 0;
  int bin = 1;
  bool any() const { return cropped || bin > 1; }
};

// Parses "WxH+X+Y" (e.g. 64x64+100+40) into `s`; throws InputError naming --crop otherwise.
void parse_crop(std::string_view text, FrameShaping& s);

// `f` cropped and binned as `s` says; throws InputError naming the option when the window does
// not lie inside the frame or the binning leaves nothing.
Frame shape_frame(const Frame& f, const FrameShaping& s);

}  // namespace pxflow
