# Installing pxflow (`cmake --install build --prefix P`):
#   bin/pxflow, bin/gap8-run, bin/pxflow-dut-ref   the CLI, the GAP8 model's runner and the
#                                            reference device (pxflow check --dut ref=exec:...)
#   include/pxflow/*.hpp                     the contract types (reference/), the backend interface
#                                            and the registry (hosts/core), included as <pxflow/...>
#   lib/libpxflow_*.a                        the registry with every family of this build, and
#                                            every library they link (found by walking the links)
#   lib/pxflow/                              run-time modules (pxflow_install_module())
#   share/pxflow/                            run-time data: the Cortex-M4 firmware
#                                            (pxflow_install_data())
#   lib/cmake/pxflow/                        find_package(pxflow) -> pxflow::pxflow
#   lib/pkgconfig/pxflow.pc                  pkg-config --cflags --libs pxflow
#   share/man/man1/pxflow.1, pxflow-<command>.1   generated from --help by help2man
# The directories are GNUInstallDirs'. Include this file before the targets are declared (it
# defines pxflow_install_module()); call pxflow_install() once after every target exists.
include_guard(GLOBAL)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PXFLOW_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/pxflow)
# Modules pxflow loads at run time (dlopen), relative to the prefix.
set(PXFLOW_INSTALL_MODULEDIR ${CMAKE_INSTALL_LIBDIR}/pxflow)

option(PXFLOW_MAN_PAGES "Generate the man pages from --help with help2man (Debian: help2man)" ON)

# Files pxflow reads at run time that are no code for this host, relative to the prefix.
set(PXFLOW_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/pxflow)

# Installs MODULE or SHARED library targets into PXFLOW_INSTALL_MODULEDIR: the one place a
# run-time module is installed from.
function(pxflow_install_module)
  install(TARGETS ${ARGN} LIBRARY DESTINATION ${PXFLOW_INSTALL_MODULEDIR})
endfunction()

# Installs FILES into PXFLOW_INSTALL_DATADIR: the one place run-time data is installed from.
function(pxflow_install_data)
  install(FILES ${ARGN} DESTINATION ${PXFLOW_INSTALL_DATADIR})
endfunction()

# <out> = <dir> (relative to the prefix) relative to the installed binary's folder, the form the
# run-time lookup takes (hosts/core/own_files.hpp): "../lib/pxflow", "../share/pxflow".
function(pxflow_reldir_from_bindir out dir)
  file(RELATIVE_PATH rel /prefix/${CMAKE_INSTALL_BINDIR} /prefix/${dir})
  set(${out} ${rel} PARENT_SCOPE)
endfunction()

# The link closure of `root`: the project's own targets in link order (each before what it
# links), the imported targets it reaches and plain linker flags. $<LINK_ONLY:...> (a static
# library's private dependency) is followed like any other link; any other generator expression
# is refused, so that nothing a consumer needs is silently left out, but $<BUILD_INTERFACE:...>,
# which the export drops.
function(_pxflow_link_closure root out_targets out_imported out_flags)
  foreach(list VISITED POSTORDER IMPORTED FLAGS)
    set_property(GLOBAL PROPERTY _PXFLOW_CLOSURE_${list} "")
  endforeach()
  _pxflow_visit(${root})
  foreach(list POSTORDER IMPORTED FLAGS)
    get_property(${list} GLOBAL PROPERTY _PXFLOW_CLOSURE_${list})
    list(REMOVE_DUPLICATES ${list})
  endforeach()
  list(REVERSE POSTORDER)  # depth-first post-order reversed: a valid static link order
  set(${out_targets} ${POSTORDER} PARENT_SCOPE)
  set(${out_imported} ${IMPORTED} PARENT_SCOPE)
  set(${out_flags} ${FLAGS} PARENT_SCOPE)
endfunction()

function(_pxflow_visit t)
  get_property(visited GLOBAL PROPERTY _PXFLOW_CLOSURE_VISITED)
  if(t IN_LIST visited)
    return()
  endif()
  set_property(GLOBAL APPEND PROPERTY _PXFLOW_CLOSURE_VISITED ${t})
  get_target_property(links ${t} INTERFACE_LINK_LIBRARIES)
  if(NOT links)
    set(links "")
  endif()
  foreach(item IN LISTS links)
    # ::@(id) ... ::@ bracket links made from another directory than the target's.
    if(item MATCHES "^::@")
      continue()
    endif()
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
    # A build-only link (pxflow_build_flags: the warnings, the standard) is not installed.
    if(item MATCHES "^\\$<BUILD_INTERFACE:[^$]*>$")
      continue()
    endif()
    if(item MATCHES "\\$<")
      message(FATAL_ERROR "pxflow install: ${t} links '${item}', a generator expression the "
                          "install rules cannot follow")
    endif()
    if(NOT TARGET ${item} AND item MATCHES "::")
      message(FATAL_ERROR "pxflow install: ${t} links ${item}, an imported target not seen from "
                          "the top directory: find its package there, or make it IMPORTED_GLOBAL")
    elseif(NOT TARGET ${item})
      set_property(GLOBAL APPEND PROPERTY _PXFLOW_CLOSURE_FLAGS ${item})
      continue()
    endif()
    get_target_property(aliased ${item} ALIASED_TARGET)
    if(aliased)
      set(item ${aliased})
    endif()
    get_target_property(is_imported ${item} IMPORTED)
    if(is_imported)
      set_property(GLOBAL APPEND PROPERTY _PXFLOW_CLOSURE_IMPORTED ${item})
    else()
      _pxflow_visit(${item})
    endif()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY _PXFLOW_CLOSURE_POSTORDER ${t})
endfunction()

# The package that provides the imported targets of a namespace, for pxflowConfig.cmake's
# find_dependency(): one row per namespace the installed libraries may link, never a guess
# (CUDA::cudart comes from CUDAToolkit, not from a package CUDA). A family whose SDK brings a
# namespace not listed adds its row with pxflow_imported_package(<namespace> <package>) in its
# folder; a namespace without a row fails the configure.
set_property(GLOBAL PROPERTY PXFLOW_IMPORTED_PACKAGES
             Threads=Threads OpenCL=OpenCL Vulkan=Vulkan CUDA=CUDAToolkit)
function(pxflow_imported_package namespace package)
  set_property(GLOBAL APPEND PROPERTY PXFLOW_IMPORTED_PACKAGES ${namespace}=${package})
endfunction()

# What a consumer's pxflowConfig.cmake runs to recreate an imported target the libraries link:
# find_dependency(<package>) for <namespace>::<name> (the table above), and pkg_check_modules()
# again for PkgConfig::<prefix> (the module name cached by that call).
function(_pxflow_find_code imported out)
  get_property(packages GLOBAL PROPERTY PXFLOW_IMPORTED_PACKAGES)
  set(code "")
  foreach(t IN LISTS imported)
    if(t MATCHES "^PkgConfig::(.+)$")
      set(prefix ${CMAKE_MATCH_1})
      if(NOT ${prefix}_MODULE_NAME)
        message(FATAL_ERROR "pxflow install: no pkg-config module name for ${t}")
      endif()
      string(APPEND code "find_dependency(PkgConfig)\n"
                         "if(NOT TARGET ${t})\n"
                         "  pkg_check_modules(${prefix} REQUIRED QUIET IMPORTED_TARGET "
                         "${${prefix}_MODULE_NAME})\n"
                         "endif()\n")
    elseif(t MATCHES "^([^:]+)::")
      set(namespace ${CMAKE_MATCH_1})
      set(package "")
      foreach(row IN LISTS packages)
        if(row MATCHES "^${namespace}=(.+)$")
          set(package ${CMAKE_MATCH_1})
        endif()
      endforeach()
      if(NOT package)
        message(FATAL_ERROR "pxflow install: the libraries link ${t}, and no package is known "
                            "for ${namespace}:: (add pxflow_imported_package(${namespace} "
                            "<package>) where it is found)")
      endif()
      string(APPEND code "find_dependency(${package})\n")
    else()
      message(FATAL_ERROR "pxflow install: the libraries link the imported target ${t}, whose "
                          "package a consumer could not know; link it as <Package>::<name>")
    endif()
  endforeach()
  set(${out} "${code}" PARENT_SCOPE)
endfunction()

# pkg-config flags for the imported targets: each library file becomes -l<name> (with -L<dir>
# unless the directory is one the linker searches anyway), plain flags are kept.
function(_pxflow_pc_flags imported out)
  set(result "")
  set(seen "")
  set(queue ${imported})
  while(queue)
    list(POP_FRONT queue t)
    if(t IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${t})
    set(files "")
    get_target_property(type ${t} TYPE)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      foreach(property IMPORTED_LOCATION_RELEASE IMPORTED_LOCATION_NOCONFIG IMPORTED_LOCATION)
        get_target_property(location ${t} ${property})
        if(location)
          list(APPEND files ${location})
          break()
        endif()
      endforeach()
    endif()
    get_target_property(links ${t} INTERFACE_LINK_LIBRARIES)
    if(links)
      foreach(item IN LISTS links)
        if(TARGET ${item})
          list(APPEND queue ${item})
        else()
          list(APPEND files ${item})
        endif()
      endforeach()
    endif()
    foreach(file IN LISTS files)
      if(file MATCHES "^-")
        list(APPEND result ${file})
      elseif(file MATCHES "^(.*)/lib([^/]+)\\.(so|a)(\\.[0-9.]+)?$")
        set(dir ${CMAKE_MATCH_1})
        if(NOT dir IN_LIST CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES)
          list(APPEND result -L${dir})
        endif()
        list(APPEND result -l${CMAKE_MATCH_2})
      elseif(file)
        message(FATAL_ERROR "pxflow install: ${t} links '${file}', which pxflow.pc cannot say")
      endif()
    endforeach()
  endwhile()
  list(REMOVE_DUPLICATES result)
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# The public headers: every header of the contract library (reference/) and the backend
# interface and registry (hosts/core). Each quoted include of an installed header must be
# installed too, or the configure fails: a consumer would not compile.
function(_pxflow_install_headers)
  file(GLOB headers ${PROJECT_SOURCE_DIR}/reference/*.hpp)
  list(APPEND headers ${PROJECT_SOURCE_DIR}/hosts/core/backend.hpp
       ${PROJECT_SOURCE_DIR}/hosts/core/registry.hpp)
  set(names "")
  foreach(h IN LISTS headers)
    get_filename_component(name ${h} NAME)
    list(APPEND names ${name})
  endforeach()
  foreach(h IN LISTS headers)
    file(STRINGS ${h} includes REGEX "^#include \"")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
      if(NOT included IN_LIST names)
        message(FATAL_ERROR "pxflow install: ${h} includes \"${included}\", which is not a "
                            "public header (cmake/PxflowInstall.cmake)")
      endif()
    endforeach()
  endforeach()
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/pxflow)
endfunction()

# The man pages: generated from the built pxflow's --help (cmake/PxflowManPages.cmake) into
# build/man, one page per subcommand beside pxflow.1, and installed to share/man/man1.
function(_pxflow_man_pages)
  if(NOT PXFLOW_MAN_PAGES)
    message(STATUS "pxflow: man pages: off (PXFLOW_MAN_PAGES=OFF)")
    return()
  endif()
  find_program(PXFLOW_HELP2MAN help2man)
  if(NOT PXFLOW_HELP2MAN)
    message(FATAL_ERROR "pxflow: help2man not found: the man pages are generated with it "
                        "(install help2man, ci/packages.txt; or -DPXFLOW_MAN_PAGES=OFF)")
  endif()
  set(man_dir ${CMAKE_BINARY_DIR}/man)
  set(script ${PROJECT_SOURCE_DIR}/cmake/PxflowManPages.cmake)
  add_custom_command(
    OUTPUT ${man_dir}/pxflow.1
    COMMAND ${CMAKE_COMMAND} -DPXFLOW=$<TARGET_FILE:pxflow> -DHELP2MAN=${PXFLOW_HELP2MAN}
            -DOUT_DIR=${man_dir} -P ${script}
    DEPENDS pxflow ${script}
    COMMENT "Generating the man pages from pxflow --help (help2man)"
    VERBATIM)
  add_custom_target(pxflow_man_pages ALL DEPENDS ${man_dir}/pxflow.1)
  install(DIRECTORY ${man_dir}/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
          FILES_MATCHING PATTERN "*.1")
endfunction()

# The install rules, the CMake package and pxflow.pc. pxflow::pxflow is the registry
# (pxflow_core) with every family compiled into it; the libraries installed are exactly the
# closure of its links, so a family's libraries are installed with no line of their own.
function(pxflow_install)
  add_library(pxflow_library INTERFACE)
  set_target_properties(pxflow_library PROPERTIES EXPORT_NAME pxflow)
  target_link_libraries(pxflow_library INTERFACE pxflow_core)
  target_compile_features(pxflow_library INTERFACE cxx_std_20)  # the headers use std::span
  if(PXFLOW_SANITIZE)  # the archives call the sanitizer runtimes
    target_link_options(pxflow_library INTERFACE -fsanitize=address,undefined)
  endif()
  add_library(pxflow::pxflow ALIAS pxflow_library)

  _pxflow_link_closure(pxflow_library targets imported flags)
  list(REMOVE_ITEM targets pxflow_library)
  set(archives "")
  foreach(t IN LISTS targets)
    string(REGEX REPLACE "^pxflow_" "" export_name ${t})
    set_target_properties(${t} PROPERTIES EXPORT_NAME ${export_name})
    get_target_property(type ${t} TYPE)
    if(type STREQUAL "STATIC_LIBRARY")
      list(APPEND archives ${t})
    elseif(NOT type STREQUAL "INTERFACE_LIBRARY")
      message(FATAL_ERROR "pxflow install: ${t} is a ${type}; the registry's closure is expected "
                          "to hold static and interface libraries only")
    endif()
  endforeach()
  list(JOIN archives " " archive_list)
  message(STATUS "pxflow: installed libraries: ${archive_list}")

  install(TARGETS pxflow_library ${targets} EXPORT pxflowTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT pxflowTargets NAMESPACE pxflow:: DESTINATION ${PXFLOW_INSTALL_CMAKEDIR})
  set(programs "")
  foreach(program pxflow gap8-run pxflow-dut-ref)  # each one this build made
    if(TARGET ${program})
      install(TARGETS ${program} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
      list(APPEND programs ${program})
    endif()
  endforeach()
  set(PXFLOW_INSTALLED_PROGRAMS ${programs} PARENT_SCOPE)  # cmake/PxflowPackage.cmake
  _pxflow_install_headers()

  # pxflowConfig.cmake: the dependencies first, then the targets.
  _pxflow_find_code("${imported}" PXFLOW_FIND_DEPENDENCIES)
  set(generated ${CMAKE_BINARY_DIR}/pxflow-package)
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/pxflowConfig.cmake.in
                                ${generated}/pxflowConfig.cmake
                                INSTALL_DESTINATION ${PXFLOW_INSTALL_CMAKEDIR})
  # 0.x: a new minor version may change the interface.
  write_basic_package_version_file(${generated}/pxflowConfigVersion.cmake
                                   COMPATIBILITY SameMinorVersion)
  install(FILES ${generated}/pxflowConfig.cmake ${generated}/pxflowConfigVersion.cmake
          DESTINATION ${PXFLOW_INSTALL_CMAKEDIR})

  # pxflow.pc: relocatable (prefix from the file's own place), every archive in link order,
  # then the flags of what they link.
  set(pc_libs "")
  foreach(t IN LISTS archives)
    get_target_property(name ${t} OUTPUT_NAME)
    if(NOT name)
      set(name ${t})
    endif()
    list(APPEND pc_libs -l${name})
  endforeach()
  _pxflow_pc_flags("${imported}" imported_flags)
  list(APPEND pc_libs ${imported_flags} ${flags})
  if(PXFLOW_SANITIZE)
    list(APPEND pc_libs -fsanitize=address,undefined)
  endif()
  list(JOIN pc_libs " " PXFLOW_PC_LIBS)
  file(RELATIVE_PATH PXFLOW_PC_PREFIX /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
  string(REGEX REPLACE "/$" "" PXFLOW_PC_PREFIX "${PXFLOW_PC_PREFIX}")
  configure_file(${PROJECT_SOURCE_DIR}/cmake/pxflow.pc.in ${generated}/pxflow.pc @ONLY)
  install(FILES ${generated}/pxflow.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

  _pxflow_man_pages()
endfunction()
