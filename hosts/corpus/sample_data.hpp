// Where the real frames come from: Debian's opencv-doc sample data (installed by
// ci/install-deps.sh, never copied into the tree). Every loader of real frames starts here.
#pragma once

namespace pxflow {

inline constexpr const char* kSampleDataDir = "/usr/share/doc/opencv-doc/examples/data";

// Appended to "no such file" errors about those frames.
inline constexpr const char* kSampleDataHint =
    "(Debian's opencv-doc; bash ci/install-deps.sh installs it)";

}  // namespace pxflow
