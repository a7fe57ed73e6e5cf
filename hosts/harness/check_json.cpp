// The check results file (docs/harness.md, "The check file"): what `pxflow check --json`
// writes, `pxflow merge` reads and writes, and `pxflow report --check-json` shows.
#include <string>

#include "check.hpp"
#include "errors.hpp"

namespace pxflow {
namespace {

Json range_json(const CaseRange& r) { return {{"first_case", r.first}, {"end_case", r.end}}; }

Json backend_json(const BackendOutcome& b) {
  return {{"backend", b.name},     {"state", state_name(b.state)},
          {"reason", b.reason},    {"implementation", b.implementation},
          {"device", b.device},    {"passed", b.passed},
          {"failed", b.failed},    {"not_applicable", b.not_applicable},
          {"pairs", b.pairs},      {"seconds", b.seconds},
          {"failures", b.failures}};
}

BackendOutcome backend_from_json(const Json& j) {
  BackendOutcome b;
  b.name = j.at("backend").get<std::string>();
  b.state = state_from_name(j.at("state").get<std::string>());
  b.reason = j.at("reason").get<std::string>();
  b.implementation = j.at("implementation").get<std::string>();
  b.device = j.at("device").get<std::string>();
  b.passed = j.at("passed").get<long>();
  b.failed = j.at("failed").get<long>();
  b.not_applicable = j.at("not_applicable").get<long>();
  b.pairs = j.at("pairs").get<long>();
  b.seconds = j.at("seconds").get<double>();
  b.failures = j.at("failures").get<std::vector<std::string>>();
  return b;
}

Json campaign_json(const CampaignInfo& c) {
  return {{"kind", c.kind},
          {"fuzz_pairs", c.fuzz_pairs},
          {"generated_only", c.generated_only},
          {"corpus_version", c.corpus_version},
          {"corpus_fingerprint", c.fingerprint},
          {"settings", c.settings},
          {"backends", c.backends},
          {"require", c.require},
          {"cases", c.cases},
          {"pairs", c.pairs}};
}

CampaignInfo campaign_from_json(const Json& j) {
  CampaignInfo c;
  c.kind = j.at("kind").get<std::string>();
  c.fuzz_pairs = j.at("fuzz_pairs").get<long>();
  c.generated_only = j.at("generated_only").get<bool>();
  c.corpus_version = j.at("corpus_version").get<int>();
  c.fingerprint = j.at("corpus_fingerprint").get<std::string>();
  c.settings = j.at("settings").get<std::vector<std::string>>();
  c.backends = j.at("backends").get<std::vector<std::string>>();
  c.require = j.at("require").get<std::vector<std::string>>();
  c.cases = j.at("cases").get<long>();
  c.pairs = j.at("pairs").get<long>();
  return c;
}

Json shard_json(const Shard& s, const CaseRange& r) {
  Json j{{"index", s.index}, {"count", s.count}};
  j.update(range_json(r));
  return j;
}

}  // namespace

Json check_json(const CheckReport& r) {
  Json j;
  j["verdict"] = r.verdict();
  j["seed"] = r.seed;
  j["cases"] = r.cases;
  j["pairs"] = r.pairs;
  j["passed"] = r.passed;
  j["failed"] = r.failed;
  j["skipped"] = r.skipped;
  j["not_applicable"] = r.not_applicable;
  j["compared"] = r.compared;
  j["seconds"] = r.seconds;
  j["command"] = r.command;
  j["pxflow"] = {{"version", r.pxflow_version}, {"commit", r.pxflow_commit}};
  j["campaign"] = campaign_json(r.campaign);
  if (r.merged_from.empty()) {
    j["shard"] = shard_json(r.shard, r.range);
  } else {
    j["merged_from"] = Json::array();
    for (const MergedShard& m : r.merged_from) {
      Json s{{"file", m.file}};
      s.update(shard_json(m.shard, m.range));
      s["pairs"] = m.pairs;
      s["seconds"] = m.seconds;
      j["merged_from"].push_back(s);
    }
    j["missing_shards"] = r.missing_shards;
  }
  j["backends"] = Json::array();
  for (const auto& b : r.backends) j["backends"].push_back(backend_json(b));
  return j;
}

CheckReport check_from_json(const Json& j) {
  CheckReport r;
  try {
    r.seed = j.at("seed").get<std::uint64_t>();
    r.cases = j.at("cases").get<long>();
    r.pairs = j.at("pairs").get<long>();
    r.passed = j.at("passed").get<long>();
    r.failed = j.at("failed").get<long>();
    r.skipped = j.at("skipped").get<long>();
    r.not_applicable = j.at("not_applicable").get<long>();
    r.compared = j.at("compared").get<long>();
    r.seconds = j.at("seconds").get<double>();
    r.command = j.at("command").get<std::string>();
    r.pxflow_version = j.at("pxflow").at("version").get<std::string>();
    r.pxflow_commit = j.at("pxflow").at("commit").get<std::string>();
    r.campaign = campaign_from_json(j.at("campaign"));
    if (j.contains("merged_from")) {
      for (const Json& m : j.at("merged_from"))
        r.merged_from.push_back({m.at("file").get<std::string>(),
                                 {m.at("index").get<int>(), m.at("count").get<int>()},
                                 {m.at("first_case").get<long>(), m.at("end_case").get<long>()},
                                 m.at("pairs").get<long>(),
                                 m.at("seconds").get<double>()});
      r.missing_shards = j.at("missing_shards").get<std::vector<int>>();
    } else {
      const Json& s = j.at("shard");
      r.shard = {s.at("index").get<int>(), s.at("count").get<int>()};
      r.range = {s.at("first_case").get<long>(), s.at("end_case").get<long>()};
    }
    for (const Json& b : j.at("backends")) r.backends.push_back(backend_from_json(b));
  } catch (const std::exception& e) {
    // nlohmann's messages name the key ("key 'campaign' not found") or the type it expected,
    // after a "[json.exception...] " tag the user has no use for.
    std::string what = e.what();
    if (const auto tag = what.find("] "); what.starts_with("[json.") && tag != std::string::npos)
      what.erase(0, tag + 2);
    throw InputError("not a complete check file of this pxflow (" + what + ")");
  }
  return r;
}

}  // namespace pxflow
