// The kernel source: embedded byte for byte, builds on every OpenCL device here with warnings as
// errors (so a syntax error or a new warning fails CI, not a user), and a build failure carries
// the device's build log.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "build_paths.hpp"
#include "cl_program.hpp"
#include "errors.hpp"
#include "opencl_kernel_source.hpp"
#include "opencl_test_support.hpp"
#include "record.hpp"
#include "registry.hpp"

namespace pxflow::test {

TEST_CASE("opencl: the row is registered and can run here", "[opencl]") {
  const BackendRow& row = find_backend("opencl");
  CHECK(!row.needs.empty());
  require_opencl_device();
}

TEST_CASE("opencl: the embedded kernel is exactly kernels/opencl/opencl.cl", "[opencl]") {
  std::ifstream file(build_paths::opencl_kernel_source, std::ios::binary);
  REQUIRE(file);
  std::ostringstream bytes;
  bytes << file.rdbuf();
  CHECK(opencl_kernel_source() == bytes.str());
}

TEST_CASE("opencl: the kernel's status and direction values are reference/record.hpp's",
          "[opencl]") {
  const std::string source(opencl_kernel_source());
  for (const auto& [name, value] :
       {std::pair{"STATUS_DROPPED", int{kDropped}}, std::pair{"STATUS_REJECTED", int{kRejected}},
        std::pair{"STATUS_ACCEPTED", int{kAccepted}}, std::pair{"DIR_NONE", int{kDirNone}}}) {
    const std::string line = "#define " + std::string(name) + " " + std::to_string(value) + "u\n";
    INFO(line);
    CHECK(source.find(line) != std::string::npos);
  }
}

TEST_CASE("opencl: kernels/opencl/opencl.cl builds with -Werror on every OpenCL device",
          "[opencl]") {
  require_opencl_device();
  const auto devices = cl::list_devices();
  REQUIRE(!devices.empty());
  for (const auto& device : devices) {
    INFO("device " << device.index << " = " << device.name);
    auto context = cl::create_context(device);
    auto build = [&] {
      return cl::build_program(context.get(), device, opencl_kernel_source(),
                               "-Werror " + cl::kernel_options());
    };
    CHECK_NOTHROW(build());
  }
}

TEST_CASE("opencl: a kernel that does not compile reports the device's build log", "[opencl]") {
  require_opencl_device();
  const auto device = cl::list_devices().front();
  auto context = cl::create_context(device);
  const std::string broken = "__kernel void broken(__global int* p) { p[0] = no_such_name; }\n";
  try {
    cl::build_program(context.get(), device, broken);
    FAIL("a broken kernel built");
  } catch (const BackendError& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("CL_BUILD_PROGRAM_FAILURE") != std::string::npos);
    CHECK(message.find("build log") != std::string::npos);
    CHECK(message.find("no_such_name") != std::string::npos);  // from the compiler, not from us
  }
}

}  // namespace pxflow::test
