// The registry: one row per backend compiled into this binary, reference variants first, then
// the families that pxflow_backend_family() built, in the order CMake registered them.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "backend.hpp"

namespace pxflow {

const std::vector<BackendRow>& backend_rows();

// Every family of this build (the reference first) with its rows, options and extensions.
const std::vector<BackendFamily>& backend_families();

// Appends a row. For test programs that need a backend the product does not ship (e.g. a
// deliberately broken one). Call it before anything looks rows up: it may move the table.
void add_backend_row(BackendRow row);

// The row named `name`; throws InputError listing the known names when there is none.
const BackendRow& find_backend(std::string_view name);

// The backend a user gets when they name none: the first preferred row that can run here,
// else ref-original.
const BackendRow& default_backend();

// Opening a backend, the one way every command does it: the probe, then create(). A backend
// that cannot run leaves `backend` null and says why in `why_not` (check and bench report it
// as skipped). An InputError from create() (the user's input, e.g. a --device that names no
// device) is not a skip: it propagates (exit 2).
struct OpenedBackend {
  std::unique_ptr<Backend> backend;
  std::string why_not;  // empty when opened
};
OpenedBackend open_backend(const BackendRow& row, const BackendOptions& options);

// Opening for a command that must run this backend on `p` (flow, accuracy, pictures): a
// backend that cannot run here, or does not support `p`, is an InputError naming it; a failed
// set-up is the backend's BackendError.
std::unique_ptr<Backend> open_backend_for(const BackendRow& row, const BackendOptions& options,
                                          const Params& p);

// Checks that `out` and every frame of `pairs` fit `p`; throws InputError otherwise. The entry
// points (CLI, harness) call it once so that backends can trust their inputs.
void check_batch(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out);

}  // namespace pxflow
