// Error types shared by every floor. An InputError is the user's fault (bad file, size, key,
// parameter): the CLI prints its one-line message and exits 2. A BackendError is a backend that
// failed while running (device lost, out of memory): reported per backend, never a crash.
#pragma once
#include <stdexcept>
#include <string>

namespace pxflow {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct BackendError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace pxflow
