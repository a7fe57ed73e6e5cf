#include "json_document.hpp"

#include <nlohmann/json.hpp>

#include "pxflow_version.h"

namespace pxflow {

BuildIdentity build_identity() { return {PXFLOW_VERSION, PXFLOW_COMMIT}; }

std::string json_document(const Json& body, int indent) {
  Json j;
  if (body.contains("pxflow")) {
    j["pxflow"] = body["pxflow"];
  } else {
    const BuildIdentity b = build_identity();
    j["pxflow"] = {{"version", b.version}, {"commit", b.commit}};
  }
  for (const auto& [key, value] : body.items())
    if (key != "pxflow") j[key] = value;
  return j.dump(indent) + "\n";
}

}  // namespace pxflow
