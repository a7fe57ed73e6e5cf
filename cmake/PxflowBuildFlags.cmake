# pxflow_build_flags: the C++ standard, the warnings and the sanitizers of every target the project
# compiles, as one INTERFACE target. pxflow_link_build_flags() links it to each compiled target
# of a folder tree once they all exist, so that no target can be left out; it is a build-only
# link ($<BUILD_INTERFACE:...>), never exported to an installed consumer.
include_guard(GLOBAL)

option(PXFLOW_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(PXFLOW_WERROR "Treat warnings as errors (CI: ci/build.sh)" OFF)

# Bit-exact floats: no fused multiply-add contraction anywhere (SPEC §5). The list is also what
# the provenance reports as the flags every file gets (hosts/CMakeLists.txt).
# PXFLOW_PORTABLE_OPTIONS: what every compiler of the project gets, the cross compilers of the
# firmware, the GAP8 ELFs and the NEON check included (pxflow_cross_arguments below).
set(PXFLOW_PORTABLE_OPTIONS -Wall -Wextra -ffp-contract=off)
set(PXFLOW_COMPILE_OPTIONS ${PXFLOW_PORTABLE_OPTIONS})
if(PXFLOW_WERROR)
  list(APPEND PXFLOW_COMPILE_OPTIONS -Werror)
endif()
if(PXFLOW_SANITIZE)
  list(APPEND PXFLOW_COMPILE_OPTIONS -fsanitize=address,undefined -fno-sanitize-recover=all
       -fno-omit-frame-pointer)
  # GCC's -Wmaybe-uninitialized is not reliable with the sanitizers' instrumentation (GCC's
  # manual says so of -fsanitize=address): GCC 12 flags libstdc++'s own <regex> here. The
  # Release build keeps the warning, and -Werror on it.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    list(APPEND PXFLOW_COMPILE_OPTIONS -Wno-maybe-uninitialized)
  endif()
endif()
add_library(pxflow_build_flags INTERFACE)
target_compile_features(pxflow_build_flags INTERFACE cxx_std_20)
target_compile_options(pxflow_build_flags INTERFACE ${PXFLOW_COMPILE_OPTIONS})
if(PXFLOW_SANITIZE)
  # Executables are not position-independent there: the sanitizer stage starts pxflow thousands
  # of times, and a PIE's start relocated the instrumented binary's pointers page by page
  # (copy-on-write faults were a third of `pxflow --version`'s time; 60 -> 41 ms per start,
  # docs/measurements/sanitizer-time.md).
  target_link_options(pxflow_build_flags INTERFACE -fsanitize=address,undefined
                      $<$<STREQUAL:$<TARGET_PROPERTY:TYPE>,EXECUTABLE>:-no-pie>)
endif()

# pxflow_hot_code(target...): the code most of the sanitizer stage's test time is spent in, compiled
# at -O3 (as in Release) in a sanitizer build (the last -O on the command line wins), where the
# rest is at -O1 (ci/run-tests.sh: -O1 compiles in half the time of -O2). The instrumentation is
# the same at every level (a vectorised load is checked as one access; GCC checks the first and
# the last byte of an access that may be unaligned). -O3 took an ASan check of the reference rows
# from 3.4 to 2.75 CPU-s against -O2 (2026-12-07, docs/measurements/sanitizer-time.md). The
# reference answers every `pxflow check` and ref::integer_search took 56 % of the samples of the
# six slowest ASan tests (docs/measurements/sanitizer-time.md, 2026-12-03); the CPU
# kernels and the SAD ceilings run in every check and bench, and the corpus makes every check's
# frames (its box blur was 17 % of an ASan fuzz check). Other builds are left as they are.
function(pxflow_hot_code)
  if(PXFLOW_SANITIZE)
    foreach(t IN LISTS ARGN)
      target_compile_options(${t} PRIVATE -O3)
    endforeach()
  endif()
endfunction()

# Links pxflow_build_flags to every library, module and executable compiled in `dir` and the
# folders below it (the top folder when none is given; tests/ is added after it, with its own
# call).
function(pxflow_link_build_flags)
  set(dir ${ARGN})
  if(NOT dir)
    set(dir ${PROJECT_SOURCE_DIR})
  endif()
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$")
      target_link_libraries(${t} PRIVATE $<BUILD_INTERFACE:pxflow_build_flags>)
    endif()
  endforeach()
  get_property(folders DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(folder IN LISTS folders)
    pxflow_link_build_flags(${folder})
  endforeach()
endfunction()

# pxflow_cross_arguments(<prefix> [INCLUDE_DIRS dir...] [DEFINITIONS def...] [SOURCES file...]):
# the command-line pieces of a cross build that is one compiler call (the Cortex-M4 firmware,
# the GAP8 ELFs), which CMake's targets cannot hold because one project has one toolchain:
# <prefix>_INCLUDES (-I...), <prefix>_DEFINES (-D...) and <prefix>_SOURCES (absolute paths).
function(pxflow_cross_arguments prefix)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "INCLUDE_DIRS;DEFINITIONS;SOURCES")
  list(TRANSFORM ARG_INCLUDE_DIRS PREPEND -I OUTPUT_VARIABLE includes)
  list(TRANSFORM ARG_DEFINITIONS PREPEND -D OUTPUT_VARIABLE defines)
  set(sources "")
  foreach(s IN LISTS ARG_SOURCES)
    get_filename_component(abs ${s} ABSOLUTE)
    list(APPEND sources ${abs})
  endforeach()
  set(${prefix}_INCLUDES ${includes} PARENT_SCOPE)
  set(${prefix}_DEFINES ${defines} PARENT_SCOPE)
  set(${prefix}_SOURCES ${sources} PARENT_SCOPE)
endfunction()

# The cross-compiled outputs (GAP8 ELFs, the Cortex-M4 firmware, the AArch64 NEON check) do not
# depend on the host's build type or sanitizers: a build may copy them from another build folder
# of the same sources instead of compiling them again (ci/run-tests.sh: the sanitizer stage takes
# the Release stage's, about 75 CPU seconds; docs/test-suite.md, "The test suite's time").
# Build that folder first: a missing file stops the build naming it.
set(PXFLOW_CROSS_FROM "" CACHE PATH
    "Build folder of the same sources whose cross-compiled outputs this build copies")
if(PXFLOW_CROSS_FROM AND NOT EXISTS ${PXFLOW_CROSS_FROM}/CMakeCache.txt)
  message(FATAL_ERROR "PXFLOW_CROSS_FROM=${PXFLOW_CROSS_FROM} is not a build folder "
                      "(no CMakeCache.txt): configure and build it first, or leave the option empty")
endif()

# pxflow_cross_output(<output> COMMENT <text> COMMAND <args...> DEPENDS <files...>): the custom
# command of one cross-compiled output, or its copy from PXFLOW_CROSS_FROM (the same path below
# that folder) when that is set. Every cross build goes through here.
function(pxflow_cross_output output)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "COMMENT" "COMMAND;DEPENDS")
  if(PXFLOW_CROSS_FROM)
    file(RELATIVE_PATH rel ${CMAKE_BINARY_DIR} ${output})
    set(from ${PXFLOW_CROSS_FROM}/${rel})
    add_custom_command(OUTPUT ${output} COMMAND ${CMAKE_COMMAND} -E copy ${from} ${output}
                       DEPENDS ${from} COMMENT "${ARG_COMMENT} (copied from ${PXFLOW_CROSS_FROM})"
                       VERBATIM)
  else()
    add_custom_command(OUTPUT ${output} COMMAND ${ARG_COMMAND} DEPENDS ${ARG_DEPENDS}
                       COMMENT "${ARG_COMMENT}" VERBATIM)
  endif()
endfunction()
