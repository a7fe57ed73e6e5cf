// The whole pxflow command line as a function, so that test programs can run it with extra
// registry rows (see tests/harness).
#pragma once

namespace pxflow {

// Returns the process exit code: 0 success, 1 a failed check or backend, 2 bad input.
int run_pxflow(int argc, char** argv);

}  // namespace pxflow
