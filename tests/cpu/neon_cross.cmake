# The NEON kernel, cross-compiled with Debian's aarch64-linux-gnu-g++ (g++-aarch64-linux-gnu)
# together with the reference, the corpus, the exactness checker and neon_cross_check.cpp, and
# run under qemu-aarch64 (qemu-user) against the cross sysroot. Without those tools the test reports itself skipped
# (exit 77) with the reason, never passed.
set(PXFLOW_AARCH64_SYSROOT /usr/aarch64-linux-gnu)
find_program(PXFLOW_AARCH64_CXX aarch64-linux-gnu-g++)
find_program(PXFLOW_QEMU_AARCH64 qemu-aarch64)

if(arch STREQUAL "aarch64")
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
  pxflow_missing_tool_test(cpu_neon_cross "missing${missing}")
  set_tests_properties(cpu_neon_cross PROPERTIES LABELS "cross")
  return()
endif()

# Every source is compiled on its own, so that each kernel file of the ISA table's AArch64 rows
# gets its row's flags only, as in the native build (kernels/cpu/isa_table.cmake).
include(${PROJECT_SOURCE_DIR}/kernels/cpu/isa_table.cmake)
pxflow_cpu_isas(aarch64 cross)
set(src ${PROJECT_SOURCE_DIR})
# The reference whole, as its target lists it; of the hosts' libraries only the files the check
# needs (the rest brings OpenCV, threads and the registry).
get_target_property(reference_sources pxflow_reference SOURCES)
list(TRANSFORM reference_sources PREPEND ${src}/reference/)
set(neon_cross_sources ${reference_sources}
  ${src}/hosts/corpus/synthetic.cpp
  ${src}/hosts/harness/common/exactness.cpp ${src}/hosts/harness/common/record_diff.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/cpu_corpus.cpp ${CMAKE_CURRENT_SOURCE_DIR}/neon_cross_check.cpp)
foreach(name IN LISTS PXFLOW_CPU_PORTABLE_SOURCES)
  list(APPEND neon_cross_sources ${src}/kernels/cpu/${name})
endforeach()
foreach(name IN LISTS cross_NAMES)
  list(APPEND neon_cross_sources ${src}/kernels/cpu/${name}.cpp)
endforeach()
set(neon_cross_binary ${CMAKE_CURRENT_BINARY_DIR}/neon_cross_check.aarch64)
set(neon_cross_objects "")
foreach(source IN LISTS neon_cross_sources)
  get_filename_component(stem ${source} NAME_WE)
  set(flags "")
  if(stem IN_LIST cross_NAMES AND source MATCHES "/kernels/cpu/")
    set(flags ${cross_${stem}_FLAGS})
  endif()
  set(object ${CMAKE_CURRENT_BINARY_DIR}/neon_cross/${stem}.o)
  add_custom_command(
    OUTPUT ${object}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_CURRENT_BINARY_DIR}/neon_cross
    COMMAND ${PXFLOW_AARCH64_CXX} -std=c++20 -O2 ${PXFLOW_PORTABLE_OPTIONS} ${flags}
            -I${src}/reference -I${PXFLOW_SPEC_INCLUDE_DIR} -I${src}/hosts/corpus -I${src}/hosts/harness/common -I${src}/kernels/cpu
            -I${CMAKE_CURRENT_SOURCE_DIR} -MD -MF ${object}.d -c ${source} -o ${object}
    DEPENDS ${source}
    DEPFILE ${object}.d
    COMMENT "Cross-compiling ${stem}.cpp for AArch64 (aarch64-linux-gnu-g++)"
    VERBATIM)
  list(APPEND neon_cross_objects ${object})
endforeach()
# The objects are built only for this link: copied from PXFLOW_CROSS_FROM, it needs none.
pxflow_cross_output(${neon_cross_binary}
  COMMAND ${PXFLOW_AARCH64_CXX} ${neon_cross_objects} -o ${neon_cross_binary}
  DEPENDS ${neon_cross_objects}
  COMMENT "Linking the NEON check for AArch64")
add_custom_target(neon_cross_check ALL DEPENDS ${neon_cross_binary})

# The real frames reach the AArch64 program as raw files written by the host's path check.
set(real_raw ${CMAKE_CURRENT_BINARY_DIR}/real_raw)
add_test(NAME cpu_real_frames_raw COMMAND cpu_path_check --dump-real ${real_raw})
set_tests_properties(cpu_real_frames_raw PROPERTIES
  FIXTURES_SETUP cpu_real_raw LABELS "cross")
pxflow_tool_skip(cpu_real_frames_raw)  # the real frames of opencv-doc
add_test(NAME cpu_neon_cross
         COMMAND ${PXFLOW_QEMU_AARCH64} -L ${PXFLOW_AARCH64_SYSROOT} ${neon_cross_binary}
                 ${real_raw}/frames.txt)
# no-sanitizer: the cross-built binary under qemu-aarch64 is not instrumented.
set_tests_properties(cpu_neon_cross PROPERTIES LABELS "cross;no-sanitizer" FIXTURES_REQUIRED cpu_real_raw)
message(STATUS "pxflow: NEON cross test on (${PXFLOW_AARCH64_CXX}, ${PXFLOW_QEMU_AARCH64})")
