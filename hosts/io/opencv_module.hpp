// The OpenCV module (hosts/opencv/, libpxflow_opencv.so), loaded on first use: the one way the
// binary reaches OpenCV. Commands that decode nothing never load it, so they start in a few
// milliseconds instead of the ~200 ms that OpenCV's ~250 shared libraries take to load.
//
// Where it is looked for, first found wins:
//   1. $PXFLOW_OPENCV_MODULE (a full path), when set;
//   2. beside the executable (the build tree: build/libpxflow_opencv.so);
//   3. <executable>/../lib/pxflow/libpxflow_opencv.so, an installed tree (the install rule's
//      ${CMAKE_INSTALL_LIBDIR}/pxflow relative to ${CMAKE_INSTALL_BINDIR}, then ../lib/pxflow).
// A program that links the module's code (target pxflow_opencv_code; tests do) uses it directly.
#pragma once
#include "opencv_api.hpp"

namespace pxflow {

// The module's table, loaded on the first call. Throws InputError (exit 2) naming the path(s)
// tried, why the module did not load, and what to do, when it is missing or broken.
const opencv::Api& opencv_api();

// The file name of the module (what the build installs).
inline constexpr const char* kOpenCvModuleFile = "libpxflow_opencv.so";

}  // namespace pxflow
