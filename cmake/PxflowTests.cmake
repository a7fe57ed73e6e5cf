# The test suite's conventions, each kept in one place (README, "Tests"):
#
# - Labels. Every test carries its area label, the name of its folder under tests/ (set once, by
#   tests/CMakeLists.txt, as the folder's LABELS directory property, so discovered Catch2 cases
#   get it too). Any other label is a trait, never an area: `no-sanitizer` (the sanitizer stage
#   leaves the test out; the reason is written beside it), `cross`, `masked-path`, `m4`.
# - Catch2. Every test executable has tests/support/catch_main.cpp's main, which turns on
#   Catch2's NoTests (a name that matches no case fails) and NoAssertions (a case or leaf section
#   that asserted nothing fails) warnings; pxflow_catch_tests() registers its cases.
# - A missing tool. The test is registered whatever this machine has, and a test that cannot run
#   for want of a tool exits 77 after one line "SKIPPED: <reason>". That is a skip
#   (SKIP_RETURN_CODE) on a developer's machine, and a failure where PXFLOW_REQUIRE_ALL is on
#   (CI and the README's commands), where every tool of ci/packages.txt must be present.
#   pxflow_tool_skip() marks tests that may exit 77 so; pxflow_missing_tool_test() registers the
#   stand-in for a test that cannot even be built here. Hardware a machine may lack (an ISA
#   extension) is not a tool: pxflow_hardware_skip() keeps exit 77 a skip everywhere.

# pxflow_catch_tests(<target> [TEST_SPEC ...] [TEST_PREFIX ...] [PROPERTIES ...]): Catch2's
# catch_discover_tests() for an executable linked with pxflow_test_support (its main).
function(pxflow_catch_tests target)
  get_target_property(links ${target} LINK_LIBRARIES)
  if(NOT "pxflow_test_support" IN_LIST links)
    message(FATAL_ERROR "pxflow_catch_tests(${target}): link pxflow_test_support (the suite's main)")
  endif()
  catch_discover_tests(${target} ${ARGN})
endfunction()

# pxflow_tool_skip(<test>...): these tests exit 77 when a tool they need is missing.
function(pxflow_tool_skip)
  if(NOT PXFLOW_REQUIRE_ALL)
    set_tests_properties(${ARGN} PROPERTIES SKIP_RETURN_CODE 77)
  endif()
endfunction()

# pxflow_hardware_skip(<test>...): these tests exit 77 when this machine's hardware lacks what
# they test (a skip under PXFLOW_REQUIRE_ALL too: CI machines differ in their CPUs).
function(pxflow_hardware_skip)
  set_tests_properties(${ARGN} PROPERTIES SKIP_RETURN_CODE 77)
endfunction()

# pxflow_missing_tool_test(<name> <reason>): the stand-in for test <name>, which needs a tool this
# machine lacks; <reason> names the tool and its Debian package.
function(pxflow_missing_tool_test name reason)
  message(STATUS "pxflow: test ${name} cannot run here: ${reason}")
  add_test(NAME ${name} COMMAND sh -c "echo 'SKIPPED: ${reason} (bash ci/install-deps.sh)'; exit 77")
  pxflow_tool_skip(${name})
endfunction()
