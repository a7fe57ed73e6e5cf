// pxflow accuracy: pxflow's frame flow against the true motion of synthetic pairs and against DIS
// on real video, side by side with OpenCV's Lucas-Kanade and DIS flow (hosts/accuracy/).
#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "accuracy_json.hpp"
#include "accuracy_run.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "json_document.hpp"
#include "output_plan.hpp"
#include "registry.hpp"

namespace pxflow::cli {
namespace {

struct AccuracyArgs {
  accuracy::AccuracyOptions options;
  std::string json_path;
  std::string command;  // the command line as run (command_line.hpp)
};

int run_accuracy_command(const AccuracyArgs& a) {
  accuracy::AccuracyOptions o = a.options;
  find_backend(o.backend);  // unknown names fail before any work
  // 0 = all cores, as everywhere in pxflow; OpenCV and the backend get the same count.
  if (o.threads == 0)
    o.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.backend_options.threads = o.threads;
  OutputPlan plan;
  OutputFile* const json_file = a.json_path.empty() ? nullptr : &plan.file("--json", a.json_path);
  plan.prepare();
  const auto report = accuracy::run_accuracy(o);
  // `--json -`: the JSON is standard output, so the table goes to standard error.
  (a.json_path == kStdoutPath ? std::cerr : std::cout) << accuracy::format_accuracy(report, o);
  if (json_file)
    json_file->write(json_document(
        Json{{"command", a.command}, {"rows", accuracy::accuracy_rows_json(report)}}));
  return 0;
}

}  // namespace

const std::vector<std::string> kAccuracyExamples = {
    "accuracy  # error against true motion, beside OpenCV's LK and DIS",
};

Command add_accuracy_command(CommandSpec& app) {
  auto a = std::make_shared<AccuracyArgs>();
  accuracy::AccuracyOptions* const o = &a->options;
  o->backend = default_backend().name;
  CommandSpec* sub = &app.add_subcommand(
      "accuracy",
      "pxflow vs OpenCV's Lucas-Kanade and DIS flow: error against known motion, time per frame");
  add_backend_option(*sub, o->backend, "for pxflow's flow");
  add_device_option(*sub, o->backend_options.device);
  sub->add("--cases", &o->pairs, "Synthetic pairs at 64x64 (a quarter as many at 320x240)")
      .with_default()
      .in_range(1, 100000);
  sub->add("--video-pairs", &o->video_pairs,
           "Real frame pairs per video (vtest.avi, tree.avi); 0 = none")
      .with_default()
      .in_range(0, 40);
  add_seed_option(*sub, o->seed, "of the synthetic motions");
  add_threads_option(*sub, o->threads, "for OpenCV and the backend alike");
  add_data_option(*sub, o->data_dir);
  add_json_option(*sub, a->json_path,
                  "the rows, as in the report's results.json; with '-' the "
                  "table goes to stderr");
  sub->flag("--by-kind", o->by_kind, "Also one block of rows per kind of motion");
  add_progress_flag(*sub);
  // Old spellings: --pairs is a list file of pairs in flow; --data is every command's folder.
  add_renamed_option(*sub, "--pairs", "--cases N");
  add_renamed_option(*sub, "--data-dir", "--data DIR");
  return {sub,
          [a, sub] {
            a->command = given_command_line(*sub);
            return run_accuracy_command(*a);
          },
          kAccuracyExamples,
          {"--cases 1 --video-pairs 0 --data {DATA}"},
          {"--cases 2000 --video-pairs 0 --data {DATA} --json {OUT}.json"}};
}

}  // namespace pxflow::cli
