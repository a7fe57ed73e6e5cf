# The NEON kernel, cross-compiled with Debian's aarch64-linux-gnu-g++ (g++-aarch64-linux-gnu)
# together with the reference, the corpus and neon_cross_check.cpp, and run under qemu-aarch64
# (qemu-user) against the cross sysroot. Without those tools the test reports itself skipped
# (exit 77) with the reason, never passed.
set(PXFLOW_AARCH64_SYSROOT /usr/aarch64-linux-gnu)
find_program(PXFLOW_AARCH64_CXX aarch64-linux-gnu-g++)
find_program(PXFLOW_QEMU_AARCH64 qemu-aarch64)

if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64)$")
  return()  # native AArch64: cpu_path_neon already runs the kernel natively
endif()

set(missing "")
if(NOT PXFLOW_AARCH64_CXX)
  string(APPEND missing " aarch64-linux-gnu-g++ (install g++-aarch64-linux-gnu)")
endif()
if(NOT PXFLOW_QEMU_AARCH64)
  string(APPEND missing " qemu-aarch64 (install qemu-user)")
endif()
if(NOT EXISTS ${PXFLOW_AARCH64_SYSROOT}/lib)
  string(APPEND missing " ${PXFLOW_AARCH64_SYSROOT}/lib (install g++-aarch64-linux-gnu)")
endif()

if(missing)
  message(STATUS "pxflow: NEON cross test will be skipped, missing:${missing}")
  add_test(NAME cpu_neon_cross COMMAND sh -c "echo 'skipped: missing${missing}'; exit 77")
  set_tests_properties(cpu_neon_cross PROPERTIES SKIP_RETURN_CODE 77 LABELS "cpu;cross")
  return()
endif()

set(src ${PROJECT_SOURCE_DIR})
set(neon_cross_sources
  ${src}/reference/params.cpp ${src}/reference/grid.cpp ${src}/reference/poi_steps.cpp
  ${src}/reference/kernel.cpp ${src}/reference/kernel_original.cpp
  ${src}/reference/kernel_local.cpp ${src}/reference/kernel_global.cpp
  ${src}/reference/estimate.cpp
  ${src}/hosts/corpus/synthetic.cpp
  ${src}/kernels/cpu/poi_loop.cpp ${src}/kernels/cpu/swar.cpp ${src}/kernels/cpu/neon.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_corpus.cpp ${CMAKE_CURRENT_SOURCE_DIR}/neon_cross_check.cpp)
set(neon_cross_binary ${CMAKE_CURRENT_BINARY_DIR}/neon_cross_check.aarch64)
add_custom_command(
  OUTPUT ${neon_cross_binary}
  COMMAND ${PXFLOW_AARCH64_CXX} -std=c++20 -O2 -Wall -Wextra -ffp-contract=off
          -I${src}/reference -I${src}/hosts/corpus -I${src}/kernels/cpu -I${CMAKE_CURRENT_SOURCE_DIR}
          -MD -MF ${neon_cross_binary}.d
          ${neon_cross_sources} -o ${neon_cross_binary}
  DEPENDS ${neon_cross_sources}
  DEPFILE ${neon_cross_binary}.d
  COMMENT "Cross-compiling the NEON check for AArch64 (aarch64-linux-gnu-g++)"
  VERBATIM)
add_custom_target(neon_cross_check ALL DEPENDS ${neon_cross_binary})

# The real frames reach the AArch64 program as raw files written by the host's path check.
set(real_raw ${CMAKE_CURRENT_BINARY_DIR}/real_raw)
add_test(NAME cpu_real_frames_raw COMMAND cpu_path_check --dump-real ${real_raw})
set_tests_properties(cpu_real_frames_raw PROPERTIES
  SKIP_RETURN_CODE 77 FIXTURES_SETUP cpu_real_raw LABELS "cpu;cross")
add_test(NAME cpu_neon_cross
         COMMAND ${PXFLOW_QEMU_AARCH64} -L ${PXFLOW_AARCH64_SYSROOT} ${neon_cross_binary}
                 ${real_raw}/frames.txt)
set_tests_properties(cpu_neon_cross PROPERTIES LABELS "cpu;cross" FIXTURES_REQUIRED cpu_real_raw)
message(STATUS "pxflow: NEON cross test on (${PXFLOW_AARCH64_CXX}, ${PXFLOW_QEMU_AARCH64})")
