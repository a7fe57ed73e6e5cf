// The family function of tests/install/library_family: configured by the install test, never
// built; a family with no rows.
#include "backend.hpp"

namespace pxflow {

BackendFamily library_family() { return BackendFamily{"library-family", {}, {}, {}, {}}; }

}  // namespace pxflow
