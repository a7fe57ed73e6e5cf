// The check results file (docs/harness.md, "The check file"): what `pxflow check --json`
// writes, `pxflow merge` reads and writes, and `pxflow report --check-json` shows.
#include <array>
#include <string>

#include "check.hpp"
#include "errors.hpp"
#include "result_fields_json.hpp"

namespace pxflow {
namespace {

Json range_json(const CaseRange& r) { return {{"first_case", r.first}, {"end_case", r.end}}; }

// In the CSV's column order (conformance.csv); the JSON objects have the same order.
const std::array kBackendOutcomeFields{
    member_field<&BackendOutcome::name>("backend"),
    ResultField<BackendOutcome>{
        "state", [](const BackendOutcome& b) -> Json { return state_name(b.state); },
        [](BackendOutcome& b, const Json& j) { b.state = state_from_name(j.get<std::string>()); }},
    member_field<&BackendOutcome::passed>("passed"),
    member_field<&BackendOutcome::failed>("failed"),
    member_field<&BackendOutcome::not_applicable>("not_applicable"),
    member_field<&BackendOutcome::pairs>("pairs"),
    member_field<&BackendOutcome::seconds>("seconds"),
    member_field<&BackendOutcome::reason>("reason"),
    member_field<&BackendOutcome::implementation>("implementation"),
    member_field<&BackendOutcome::device>("device"),
    member_field<&BackendOutcome::failures>("failures", false),  // lines: results.json only
    member_field<&BackendOutcome::limits>("limits", false),
};

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

Json options_json(const CheckReport& r) {
  if (!r.merged_from.empty()) return {};
  const RunOptions& o = r.options;
  return {{"data", o.data_dir},
          {"limits_only", o.limits_only},
          {"device", o.device},
          {"threads", o.threads},
          {"case_timeout", o.case_timeout},
          {"global_options", o.global_options},
          {"profile", o.params.profile},
          {"sets", o.params.sets}};
}

void options_from_json(CheckReport& r, const Json& j) {
  RunOptions& o = r.options;
  j.at("data").get_to(o.data_dir);
  j.at("limits_only").get_to(o.limits_only);
  j.at("device").get_to(o.device);
  j.at("threads").get_to(o.threads);
  j.at("case_timeout").get_to(o.case_timeout);
  j.at("global_options").get_to(o.global_options);
  o.params.profile = j.value("profile", std::string());
  o.params.sets = j.value("sets", std::vector<std::string>());
}

Json shard_json(const Shard& s, const CaseRange& r) {
  Json j{{"index", s.index}, {"count", s.count}};
  j.update(range_json(r));
  return j;
}

Json merged_from_json(const CheckReport& r) {
  if (r.merged_from.empty()) return {};
  Json all = Json::array();
  for (const MergedShard& m : r.merged_from) {
    Json s{{"file", m.file}};
    s.update(shard_json(m.shard, m.range));
    s["pairs"] = m.pairs;
    s["seconds"] = m.seconds;
    all.push_back(s);
  }
  return all;
}

void merged_from_from_json(CheckReport& r, const Json& all) {
  for (const Json& m : all)
    r.merged_from.push_back({m.at("file").get<std::string>(),
                             {m.at("index").get<int>(), m.at("count").get<int>()},
                             {m.at("first_case").get<long>(), m.at("end_case").get<long>()},
                             m.at("pairs").get<long>(),
                             m.at("seconds").get<double>()});
}

Json backends_json(const CheckReport& r) {
  Json all = Json::array();
  for (const BackendOutcome& b : r.backends)
    all.push_back(fields_json(backend_outcome_fields(), b));
  return all;
}

void backends_from_json(CheckReport& r, const Json& all) {
  for (const Json& j : all)
    fields_from_json(backend_outcome_fields(), j, r.backends.emplace_back());
}

// A single run's file has `shard` and `options`; a merge's has `merged_from` and
// `missing_shards` instead (check_from_json requires one set). "complete": false marks a run a
// signal stopped after `cases` of its `cases_total` (files older than the key are complete).
// The check itself has no CSV file: its csv flags are unused.
const std::array kCheckReportFields{
    ResultField<CheckReport>{"verdict", [](const CheckReport& r) -> Json { return r.verdict(); }},
    ResultField<CheckReport>{"complete", &member_get<&CheckReport::complete>,
                             &member_set<&CheckReport::complete>, false, true},
    member_field<&CheckReport::seed>("seed"),
    member_field<&CheckReport::cases>("cases"),
    ResultField<CheckReport>{"cases_total",
                             [](const CheckReport& r) -> Json { return r.cases_total(); }},
    member_field<&CheckReport::pairs>("pairs"),
    member_field<&CheckReport::passed>("passed"),
    member_field<&CheckReport::failed>("failed"),
    member_field<&CheckReport::skipped>("skipped"),
    member_field<&CheckReport::not_applicable>("not_applicable"),
    member_field<&CheckReport::compared>("compared"),
    member_field<&CheckReport::seconds>("seconds"),
    member_field<&CheckReport::command>("command"),
    ResultField<CheckReport>{"pxflow",
                             [](const CheckReport& r) -> Json {
                               return {{"version", r.pxflow_version}, {"commit", r.pxflow_commit}};
                             },
                             [](CheckReport& r, const Json& j) {
                               j.at("version").get_to(r.pxflow_version);
                               j.at("commit").get_to(r.pxflow_commit);
                             }},
    ResultField<CheckReport>{
        "campaign", [](const CheckReport& r) { return campaign_json(r.campaign); },
        [](CheckReport& r, const Json& j) { r.campaign = campaign_from_json(j); }},
    ResultField<CheckReport>{
        "shard",
        [](const CheckReport& r) -> Json {
          return r.merged_from.empty() ? shard_json(r.shard, r.range) : Json();
        },
        [](CheckReport& r, const Json& s) {
          r.shard = {s.at("index").get<int>(), s.at("count").get<int>()};
          r.range = {s.at("first_case").get<long>(), s.at("end_case").get<long>()};
        },
        false, true},
    ResultField<CheckReport>{"options", &options_json, &options_from_json, false, true},
    ResultField<CheckReport>{"merged_from", &merged_from_json, &merged_from_from_json, false, true},
    ResultField<CheckReport>{"missing_shards",
                             [](const CheckReport& r) -> Json {
                               return r.merged_from.empty() ? Json() : Json(r.missing_shards);
                             },
                             [](CheckReport& r, const Json& j) { j.get_to(r.missing_shards); },
                             false, true},
    ResultField<CheckReport>{"backends", &backends_json, &backends_from_json, false},
};

}  // namespace

std::span<const ResultField<BackendOutcome>> backend_outcome_fields() {
  return kBackendOutcomeFields;
}
std::span<const ResultField<CheckReport>> check_report_fields() { return kCheckReportFields; }

Json check_json(const CheckReport& r) { return fields_json(check_report_fields(), r); }

CheckReport check_from_json(const Json& j) {
  CheckReport r;
  try {
    fields_from_json(check_report_fields(), j, r);
    // The optional keys come in one of two sets: a single run's, or a merge's.
    if (!j.contains("merged_from"))
      (void)j.at("shard");
    else
      (void)j.at("missing_shards");
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
