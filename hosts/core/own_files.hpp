// The files pxflow ships beside its binary (the OpenCV module, the Cortex-M4 firmware) are found
// relative to the running executable, never through a path compiled in: one rule finds them in the
// build tree and in any install prefix, and a build tree that was moved or deleted is never named.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace pxflow {

struct OwnFile {
  std::filesystem::path found;               // empty when no candidate exists
  std::vector<std::filesystem::path> tried;  // every candidate, in order
};

// FILE in each of RELDIRS (folders relative to the running executable's, /proc/self/exe), in
// order: the first that exists. `tried` is empty when /proc/self/exe cannot be read.
OwnFile find_own_file(const std::string& file, const std::vector<std::string>& reldirs);

// "A, B or C": the candidates tried, for a message that says where the file was looked for.
std::string describe_tried(const std::vector<std::filesystem::path>& tried);

}  // namespace pxflow
