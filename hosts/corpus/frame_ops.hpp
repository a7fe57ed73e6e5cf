// Small operations that turn real frames into test and check inputs, in plain C++.
#pragma once
#include "frame.hpp"

namespace pxflow {

// The w x h window of `f` whose top-left corner is (x, y); must lie inside f.
Frame crop(const Frame& f, int x, int y, int w, int h);

// factor x factor pixels averaged into one, rounded to nearest: how the PX4FLOW camera (MT9V034,
// 752x480 read out with 4x binning) makes its small frames. Trailing partial blocks are dropped.
Frame bin(const Frame& f, int factor);

}  // namespace pxflow
