// What `pxflow check` adds to a mismatch so that a porter can go from "failed" to the faulty line
// of their kernel: the first stage that differs, in words, and (once per backend and run) a
// minimal reproducer written as raw frames with the `pxflow flow` commands that show the
// difference on it (shrink.hpp makes it).
#pragma once
#include <functional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "backend.hpp"
#include "check_corpus.hpp"
#include "exactness.hpp"
#include "shrink.hpp"

namespace pxflow {

struct ReproOptions {
  // Writes a whole file at `path`, relative to `dir`, through the command's output plan. Empty:
  // no reproducers (pxflow check --no-repro, or a library caller that wants none).
  std::function<void(const std::string& path, std::string_view bytes)> write;
  // Makes the folder `path`, relative to `dir`, through the same plan: false when it exists;
  // throws OutputError when it cannot be made.
  std::function<bool(const std::string& path)> make_folder;
  std::string dir = ".";  // an existing folder; each run makes its own pxflow-repro-N in it
  std::string program = "pxflow";  // the printed commands' start, with the run's global options
  ShrinkLimits limits;             // per backend
};

// What follows a failed comparison's mismatch lines.
struct Explanation {
  // The first differing stage: a failure line like the others (the results file keeps it; the
  // same in every shard of a campaign as in the whole run).
  std::string stage;
  // For the backend's first failure of the run: its reproducer's folder and commands, or why
  // there is none. Printed only: they name this run's files, which a merged result cannot.
  std::vector<std::string> reproducer;
};

class MismatchExplainer {
 public:
  explicit MismatchExplainer(ReproOptions o) : o_(std::move(o)) {}

  Explanation explain(const CaseLabel& label, const CheckCase& c, const ReferenceAnswer& want,
                      std::span<const PoiRecord> got, const PairRunner& run);

 private:
  std::vector<std::string> write_reproducer(const CaseLabel& label, const Reproducer& r);
  ReproOptions o_;
  std::set<std::string> shrunk_;  // backends that have had their reproducer
  std::string run_dir_;  // this run's pxflow-repro-N (in dir), made at the first reproducer
};

}  // namespace pxflow
