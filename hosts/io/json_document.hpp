// Every JSON file pxflow writes (flow's --json and --jsonl, check, merge, bench, backends, the
// report's results.json, gap8, vectors' manifest.json) is made by json_document(), so that each
// says which pxflow wrote it and a new writer cannot leave that out.
#pragma once
#include <string>

#include "result_json.hpp"

namespace pxflow {

// The build that is running: the project version and `git describe --always --dirty` of the
// tree it was configured from (hosts/CMakeLists.txt; "-dirty" when it had uncommitted changes).
struct BuildIdentity {
  std::string version, commit;
};
BuildIdentity build_identity();

// `body` as a file's text: "pxflow": {"version", "commit"} first, then the body's keys, then a
// newline; `indent` as nlohmann::json::dump (-1: one line, as JSON lines need). A body that
// already carries "pxflow" keeps it (a check result names the build that checked, which merge
// may not be).
std::string json_document(const Json& body, int indent = 2);

}  // namespace pxflow
