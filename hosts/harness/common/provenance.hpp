// Where a result comes from, for the report's first screen, results.json and bench's header:
// pxflow's build (version, commit, compiler, flags), the machine, and what each backend ran
// (Backend::describe: implementation, device, driver).
#pragma once
#include <string>

#include "backend.hpp"
#include "result_json.hpp"

namespace pxflow {

// {"version", "commit", "dirty", "compiler", "build_type", "cxx_flags"}: the values CMake gave
// this build at configure time (hosts/CMakeLists.txt).
Json build_provenance();

// {"cpu", "cores", "os", "kernel", "host", "date"} of the machine this runs on, now.
Json machine_provenance();

// {"name", "implementation", "device", "driver"} of one opened backend; empty fields left out.
Json describe_backend(const std::string& name, const Backend& backend);

// "avx512bw, 2 threads; device ...; driver ..." from describe_backend()'s object: empty when it
// says nothing beyond the name.
std::string description_line(const Json& described);

}  // namespace pxflow
