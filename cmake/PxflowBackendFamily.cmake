# pxflow_backend_family(): a backend family is one call of this function in its own folder.
#
#   pxflow_backend_family(<NAME>
#     DOC "<what the family is>"
#     FAMILY <C++ function>             # returns pxflow::BackendFamily (its rows, options, bound)
#     [NEEDS <condition> "<reason>" ...] # each condition is if()-evaluated; the first false one
#                                        # turns the family off with its reason
#     [SOURCES ...] [INCLUDE_DIRS ...] [LINK ...] [DEFINITIONS ...]
#     [USES <family>...]                 # other families (built before) whose headers it includes
#     [CLI_EXTENSION <C++ function>      # returns pxflow::cli::CliExtension (a command, a report
#      CLI_SOURCES ...])                 # section), compiled into pxflow_cli
#
# It declares PXFLOW_WITH_<NAME> (default PXFLOW_WITH_ALL, ON) and PXFLOW_REQUIRE_<NAME> (default
# PXFLOW_REQUIRE_ALL: CI sets that, so a missing SDK fails the configure instead of dropping
# the family), prints one status line, builds the sources as the family's own target
# pxflow_family_<name> (OBJECT, its INCLUDE_DIRS and DEFINITIONS private to it through
# pxflow_family_<name>_headers, which the family's tests link by name), puts its objects into
# pxflow_core, and registers FAMILY (and CLI_EXTENSION) in the generated tables the registry
# reads. <name> is the family's C++ name (FAMILY without "_family"), lowercase. Nothing else is
# edited when a family is added. The global property PXFLOW_<NAME>_BUILT says whether it was
# built (tests).
include_guard(GLOBAL)

option(PXFLOW_WITH_ALL "Default of every PXFLOW_WITH_<NAME>: build every family that can be" ON)
option(PXFLOW_REQUIRE_ALL "Fail the configure when any backend family cannot be built" OFF)

function(pxflow_backend_family name)
  cmake_parse_arguments(PARSE_ARGV 1 F "" "DOC;FAMILY;CLI_EXTENSION"
                        "NEEDS;SOURCES;INCLUDE_DIRS;LINK;DEFINITIONS;USES;CLI_SOURCES")
  if(NOT F_FAMILY)
    message(FATAL_ERROR "pxflow_backend_family(${name}): FAMILY <function> is required")
  endif()
  string(TOLOWER "${name}" label)
  option(PXFLOW_WITH_${name} "Build the ${label} backends: ${F_DOC}" ${PXFLOW_WITH_ALL})
  option(PXFLOW_REQUIRE_${name} "Fail the configure when the ${label} backends cannot be built"
         ${PXFLOW_REQUIRE_ALL})
  set_property(GLOBAL PROPERTY PXFLOW_${name}_BUILT FALSE)

  set(why "")
  if(NOT PXFLOW_WITH_${name})
    set(why "PXFLOW_WITH_${name}=OFF")
  else()
    list(LENGTH F_NEEDS n)
    math(EXPR last "${n} - 1")
    if(n GREATER 0)
      foreach(i RANGE 0 ${last} 2)
        list(GET F_NEEDS ${i} condition)
        math(EXPR j "${i} + 1")
        list(GET F_NEEDS ${j} reason)
        cmake_language(EVAL CODE "if(${condition})\nset(met TRUE)\nelse()\nset(met FALSE)\nendif()")
        if(NOT met)
          set(why "${reason}")
          break()
        endif()
      endforeach()
    endif()
  endif()

  if(why)
    if(PXFLOW_REQUIRE_${name} AND PXFLOW_WITH_${name})
      message(FATAL_ERROR "pxflow: ${label} backends required (PXFLOW_REQUIRE_${name}) but ${why}")
    endif()
    message(STATUS "pxflow: ${label} backends: off (${why})")
    return()
  endif()
  message(STATUS "pxflow: ${label} backends: on")

  set(here ${CMAKE_CURRENT_SOURCE_DIR})
  list(TRANSFORM F_SOURCES PREPEND ${here}/ REGEX "^[^/]")
  list(TRANSFORM F_CLI_SOURCES PREPEND ${here}/ REGEX "^[^/]")
  list(TRANSFORM F_INCLUDE_DIRS PREPEND ${here}/ REGEX "^[^/]")
  # The family's headers and definitions: for its own sources, its CLI extension and its tests
  # (which link this target by name), never for pxflow_core's consumers, so that one family's
  # device_select.hpp cannot shadow another's and nothing of a family reaches the install.
  set(headers pxflow_family_${label}_headers)
  add_library(${headers} INTERFACE)
  foreach(dir ${here} ${F_INCLUDE_DIRS})
    target_include_directories(${headers} INTERFACE $<BUILD_INTERFACE:${dir}>)
  endforeach()
  target_compile_definitions(${headers} INTERFACE ${F_DEFINITIONS})
  target_link_libraries(${headers} INTERFACE pxflow_core_api ${F_LINK})
  foreach(used ${F_USES})
    target_link_libraries(${headers} INTERFACE pxflow_family_${used}_headers)
  endforeach()
  # The family's own target, compiled against the headers above and linked into pxflow_core as
  # objects: the generated table (registered_families.cpp) calls FAMILY from there.
  add_library(pxflow_family_${label} OBJECT ${F_SOURCES})
  target_link_libraries(pxflow_family_${label} PRIVATE ${headers})
  target_sources(pxflow_core PRIVATE $<TARGET_OBJECTS:pxflow_family_${label}>)
  # What the family's code calls, linked by pxflow_core for the link only (their headers stay
  # the family's): installed, pxflow_core's link closure (these targets with theirs) is
  # installed by pxflow_install(), so a family adds no install rule of its own.
  target_link_libraries(pxflow_core PRIVATE ${F_LINK})
  # An imported target the family found (OpenCL::OpenCL) is seen in its folder only; global,
  # pxflow_install() can name it in pxflowConfig.cmake and pxflow.pc. (CMake lets only the folder
  # that created it do this; one found higher up is left as it is.)
  foreach(item ${F_LINK})
    if(TARGET ${item})
      get_target_property(imported ${item} IMPORTED)
      get_target_property(global ${item} IMPORTED_GLOBAL)
      get_target_property(origin ${item} SOURCE_DIR)
      if(imported AND NOT global AND origin STREQUAL CMAKE_CURRENT_SOURCE_DIR)
        set_target_properties(${item} PROPERTIES IMPORTED_GLOBAL TRUE)
      endif()
    endif()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY PXFLOW_FAMILY_FUNCTIONS ${F_FAMILY})
  if(F_CLI_EXTENSION)
    # Compiled into pxflow_cli (on the CLI floor), with the family's headers for these files only.
    target_sources(pxflow_cli PRIVATE ${F_CLI_SOURCES})
    set_property(SOURCE ${F_CLI_SOURCES} TARGET_DIRECTORY pxflow_cli APPEND PROPERTY
                 INCLUDE_DIRECTORIES $<TARGET_PROPERTY:${headers},INTERFACE_INCLUDE_DIRECTORIES>)
    set_property(SOURCE ${F_CLI_SOURCES} TARGET_DIRECTORY pxflow_cli APPEND PROPERTY
                 COMPILE_DEFINITIONS $<TARGET_PROPERTY:${headers},INTERFACE_COMPILE_DEFINITIONS>)
    set_property(GLOBAL APPEND PROPERTY PXFLOW_CLI_EXTENSION_FUNCTIONS ${F_CLI_EXTENSION})
  endif()
  set_property(GLOBAL PROPERTY PXFLOW_${name}_BUILT TRUE)
endfunction()

# Writes one generated table: `type fn()` declared for every registered function, and `table()`
# returning them in registration order; the file is touched only when its content changes.
function(pxflow_write_function_table file header namespace type table functions)
  set(decl "")
  set(calls "")
  foreach(f ${functions})
    string(APPEND decl "${type} ${f}();\n")
    string(APPEND calls "      ${f}(),\n")
  endforeach()
  file(CONFIGURE OUTPUT ${PXFLOW_GENERATED_DIR}/${file} CONTENT
"// Generated by cmake/PxflowBackendFamily.cmake from the pxflow_backend_family() calls.
#include \"${header}\"

namespace ${namespace} {
${decl}
std::vector<${type}> ${table}() {
  return {
${calls}  };
}

}  // namespace ${namespace}
" @ONLY)
endfunction()

# The families' and their CLI extensions' tables (called once, after every family's call).
function(pxflow_write_family_tables)
  get_property(families GLOBAL PROPERTY PXFLOW_FAMILY_FUNCTIONS)
  get_property(extensions GLOBAL PROPERTY PXFLOW_CLI_EXTENSION_FUNCTIONS)
  pxflow_write_function_table(registered_families.cpp backend.hpp pxflow BackendFamily
                              registered_families "${families}")
  pxflow_write_function_table(registered_cli_extensions.cpp cli_extension.hpp pxflow::cli
                              CliExtension registered_cli_extensions "${extensions}")
endfunction()
