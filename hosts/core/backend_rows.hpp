// The registry rows, one function per backend family. Adding a backend: write its row function
// in its own hosts/ folder, declare it here, and add one line to registry.cpp.
#pragma once
#include <vector>

#include "backend.hpp"

namespace pxflow {

std::vector<BackendRow> reference_rows();  // ref-original, ref-local, ref-global

}  // namespace pxflow
