// SIGINT and SIGTERM: the first one asks the run to stop at the next point where nothing is
// half done (between check cases, bench points, report steps); a second one ends the process at
// once. Whole files are written only when complete and streams keep their completed records
// (io/output_plan); the CLI says whether any file changed, and exits 128 + the signal (130, 143).
#pragma once
#include <stdexcept>
#include <string>

namespace pxflow {

struct Interrupted : std::runtime_error {
  int signal;
  Interrupted(int sig, const std::string& what) : std::runtime_error(what), signal(sig) {}
};

void install_interrupt_handlers();

// Throws Interrupted saying what had finished (`done`, e.g. "12 of 33 cases") when a signal came.
void stop_if_interrupted(const std::string& done);

}  // namespace pxflow
