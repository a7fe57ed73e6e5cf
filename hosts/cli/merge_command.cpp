// pxflow merge: the results files of a campaign's shards (pxflow check --shard K/M --json F)
// combined into one verdict and one check file (docs/ci-campaigns.md, "Campaigns over a CI
// matrix").
#include <iostream>
#include <nlohmann/json.hpp>

#include "check_merge.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "input_file.hpp"
#include "json_document.hpp"
#include "output_plan.hpp"
#include "path_options.hpp"

namespace pxflow::cli {
namespace {

struct MergeArgs {
  std::string out;  // --json
  std::vector<std::string> files;
};

ShardFile read_shard(const std::string& path) {
  std::string text;
  try {
    text = read_input_text(path, path);
  } catch (const InputError& e) {  // every refusal points at the help, as the ones below
    throw InputError(std::string(e.what()) + " (see pxflow merge --help)");
  }
  Json j;
  try {
    j = Json::parse(text);
  } catch (const std::exception&) {
    throw InputError(path +
                     ": not valid JSON: expected a file of pxflow check --json (see pxflow merge "
                     "--help)");
  }
  try {
    return {path, check_from_json(j)};
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what() + ": expected a file of pxflow check --shard K/M " +
                     "--json (see pxflow merge --help)");
  }
}

int run_merge_command(const MergeArgs& a) {
  const bool to_stdout = a.out == "-";
  OutputPlan plan;
  plan.read_all(a.files);
  OutputFile& out = plan.file("--json", a.out);
  plan.prepare();
  std::vector<ShardFile> shards;
  for (const std::string& f : a.files) shards.push_back(read_shard(f));
  CheckReport m = merge_shards(shards);
  m.command = "pxflow merge --json " + a.out;
  for (const std::string& f : a.files) m.command += " " + f;

  // The campaign named by the command of its lowest shard given.
  const ShardFile* lowest = &shards.front();
  for (const ShardFile& f : shards)
    if (f.report.shard.index < lowest->report.shard.index) lowest = &f;
  std::ostream& human = to_stdout ? std::cerr : std::cout;
  human << "pxflow merge: " << shards.size() << " of " << lowest->report.shard.count
        << " shards of the " << m.campaign.kind << " campaign of seed " << m.seed << " (`"
        << lowest->report.command << "`)\n";
  for (const BackendOutcome& b : m.backends)
    for (const std::string& line : b.failures) human << line << "\n";
  print_check_summary(m, human);
  const std::string json = json_document(check_json(m));
  out.write(json);
  return m.ok() ? 0 : 1;
}

}  // namespace

const std::vector<std::string> kMergeExamples = {
    "merge --json all.json s1.json s2.json s3.json s4.json  # one verdict from four shards",
};

Command add_merge_command(CommandSpec& app) {
  auto a = std::make_shared<MergeArgs>();
  CommandSpec* sub = &app.add_subcommand(
      "merge",
      "Combine the --json files of a campaign's shards (pxflow check --shard K/M) into one "
      "verdict and check file; exit 0 only when every shard is there and passed");
  sub->footer =
      "Exit 0: every shard 1..M given and passed. 1: a shard failed, nothing was checked, or "
      "shards are missing (verdict 'incomplete'; --json is written). 2: the files are not the "
      "shards of one campaign (another commit, seed, --cases, corpus, backends, --require or "
      "M; a shard twice; a merged file); nothing is written. See docs/harness.md.";
  // The output is named by an option: `merge s1.json s2.json` (the output forgotten) would
  // otherwise overwrite a shard with an incomplete merge.
  add_json_option(*sub, a->out, "the merged check file (required)").needed();
  sub->add("FILES", &a->files, "The shards' check files, every K of one M once")
      .needed()
      .type("FILE")
      .path_kind(PathKind::InputFile);
  return {sub, [a] { return run_merge_command(*a); }, kMergeExamples, {"{CHECK} {CHECK2}"}};
}

}  // namespace pxflow::cli
