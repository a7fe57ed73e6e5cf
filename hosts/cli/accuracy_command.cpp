// pxflow accuracy: pxflow's frame flow against the true motion of synthetic pairs and against DIS
// on real video, side by side with OpenCV's Lucas-Kanade and DIS flow (hosts/accuracy/).
#include <algorithm>
#include <iostream>
#include <thread>

#include "accuracy_run.hpp"
#include "commands.hpp"
#include "registry.hpp"

namespace pxflow::cli {
namespace {

int run_accuracy_command(accuracy::AccuracyOptions o) {
  find_backend(o.backend);  // unknown names fail before any work
  // 0 = all cores, as everywhere in pxflow; OpenCV and the backend get the same count.
  if (o.threads == 0)
    o.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.backend_options.threads = o.threads;
  const auto report = accuracy::run_accuracy(o);
  std::cout << accuracy::format_accuracy(report, o);
  return 0;
}

}  // namespace

// What --help and the man page show under Examples (the command line after "pxflow ").
const std::vector<std::string> kAccuracyExamples = {
    "accuracy  # error against true motion, beside OpenCV's LK and DIS",
};

Command add_accuracy_command(CLI::App& app) {
  auto o = std::make_shared<accuracy::AccuracyOptions>();
  o->backend = default_backend().name;
  CLI::App* sub = app.add_subcommand(
      "accuracy",
      "pxflow vs OpenCV's Lucas-Kanade and DIS flow: error against known motion, time per frame");
  add_backend_option(*sub, o->backend, "for pxflow's flow");
  add_device_option(*sub, o->backend_options.device);
  sub->add_option("--cases", o->pairs, "Synthetic pairs at 64x64 (a quarter as many at 320x240)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  sub->add_option("--video-pairs", o->video_pairs,
                  "Real frame pairs per video (vtest.avi, tree.avi); 0 = none")
      ->capture_default_str()
      ->check(CLI::Range(0, 40));
  add_seed_option(*sub, o->seed, "of the synthetic motions");
  add_threads_option(*sub, o->threads, "for OpenCV and the backend alike");
  add_data_option(*sub, o->data_dir);
  sub->add_flag("--by-kind", o->by_kind, "Also one block of rows per kind of motion");
  // Old spellings: --pairs is a list file of pairs in flow; --data is every command's folder.
  add_renamed_option(*sub, "--pairs", "--cases N");
  add_renamed_option(*sub, "--data-dir", "--data DIR");
  return {sub, [o] { return run_accuracy_command(*o); }, kAccuracyExamples};
}

}  // namespace pxflow::cli
