// The real frames the tests read: Debian's opencv-doc examples (read-only; never written into).
#pragma once
#include <string>

#include "sample_data.hpp"

namespace pxflow::test {

inline const std::string kData = kSampleDataDir;
// A real consecutive pair (640x480 PNG): the previous and the next frame.
inline const std::string kSamplePrev = std::string(kSampleDataDir) + "/rubberwhale1.png";
inline const std::string kSampleNext = std::string(kSampleDataDir) + "/rubberwhale2.png";

}  // namespace pxflow::test
