// A JSON file a test's pxflow run wrote, parsed (a parse error fails the test with its message).
#pragma once
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace pxflow::test {

inline nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace pxflow::test
