# The CPU ISA table (isas.def) for CMake: kernels/cpu (kernel sources and their flags), hosts/cpu
# (the psadbw ceiling files), tests/cpu (the masked-path tests, the NEON cross build) read it
# here, so that an ISA is listed once.
#
#   pxflow_cpu_arch(<out>)            this build's architecture in the table's spelling:
#                                     x86_64, aarch64 or other
#   pxflow_cpu_isas(<arch> <prefix>)  the rows built for <arch> (rows of arch `any` are built
#                                     everywhere), weakest first:
#     <prefix>_NAMES           the ISA names
#     <prefix>_<name>_FLAGS    the compile options of kernels/cpu/<name>.cpp (a list)
#     <prefix>_<name>_CEILING  the psadbw width it unlocks (xmm, ymm, zmm) or none
#     <prefix>_ALL             every name in the table, on any architecture
# A row this cannot read is a configure error, never a silently dropped ISA.

# The portable part of every CPU kernel, built for every architecture (kernels/cpu and the NEON
# cross build list it from here). Before the guard: a variable is set in each includer's scope.
set(PXFLOW_CPU_PORTABLE_SOURCES poi_loop.cpp window_guard.cpp isa_table.cpp)
include_guard(GLOBAL)

function(pxflow_cpu_arch out)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
    set(${out} x86_64 PARENT_SCOPE)
  elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64)$")
    set(${out} aarch64 PARENT_SCOPE)
  else()
    set(${out} other PARENT_SCOPE)
  endif()
endfunction()

function(pxflow_cpu_isas arch prefix)
  set(PXFLOW_CPU_KERNEL_DIR ${CMAKE_CURRENT_FUNCTION_LIST_DIR})
  set(PXFLOW_CPU_ISA_TABLE ${PXFLOW_CPU_KERNEL_DIR}/isas.def)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PXFLOW_CPU_ISA_TABLE})
  file(STRINGS ${PXFLOW_CPU_ISA_TABLE} rows REGEX "^PXFLOW_CPU_ISA\\(")
  set(names "")
  set(all "")
  set(ceilings "")
  foreach(row IN LISTS rows)
    if(NOT row MATCHES
       "^PXFLOW_CPU_ISA\\(([a-z0-9]+), *([a-z0-9_]+), *\"([^\",]*)\", *([a-z]+), *\"[^\"]*\", .*\\)$")
      message(FATAL_ERROR "${PXFLOW_CPU_ISA_TABLE}: cannot read the row\n  ${row}\n"
                          "(one row per line: name, arch, \"flags\", ceiling, \"needs\", test)")
    endif()
    set(name ${CMAKE_MATCH_1})
    set(row_arch ${CMAKE_MATCH_2})
    separate_arguments(flags UNIX_COMMAND "${CMAKE_MATCH_3}")
    set(ceiling ${CMAKE_MATCH_4})
    if(NOT row_arch MATCHES "^(any|x86_64|aarch64)$")
      message(FATAL_ERROR "${PXFLOW_CPU_ISA_TABLE}: ${name}: unknown arch '${row_arch}' "
                          "(any, x86_64, aarch64)")
    endif()
    if(NOT ceiling MATCHES "^(none|xmm|ymm|zmm)$")
      message(FATAL_ERROR "${PXFLOW_CPU_ISA_TABLE}: ${name}: unknown ceiling '${ceiling}' "
                          "(none, xmm, ymm, zmm)")
    endif()
    if(name IN_LIST all)
      message(FATAL_ERROR "${PXFLOW_CPU_ISA_TABLE}: ${name} is listed twice")
    endif()
    if(NOT EXISTS ${PXFLOW_CPU_KERNEL_DIR}/${name}.cpp)
      message(FATAL_ERROR "${PXFLOW_CPU_ISA_TABLE}: ${name} has no kernel file "
                          "${PXFLOW_CPU_KERNEL_DIR}/${name}.cpp")
    endif()
    list(APPEND all ${name})
    if(row_arch STREQUAL "any" OR row_arch STREQUAL arch)
      if(NOT ceiling STREQUAL "none")
        if(ceiling IN_LIST ceilings)
          message(FATAL_ERROR "${PXFLOW_CPU_ISA_TABLE}: the ${ceiling} ceiling is claimed twice")
        endif()
        list(APPEND ceilings ${ceiling})
      endif()
      list(APPEND names ${name})
      set(${prefix}_${name}_FLAGS "${flags}" PARENT_SCOPE)
      set(${prefix}_${name}_CEILING ${ceiling} PARENT_SCOPE)
    endif()
  endforeach()
  if(NOT all)
    message(FATAL_ERROR "${PXFLOW_CPU_ISA_TABLE}: no rows")
  endif()
  set(${prefix}_NAMES "${names}" PARENT_SCOPE)
  set(${prefix}_ALL "${all}" PARENT_SCOPE)
endfunction()
