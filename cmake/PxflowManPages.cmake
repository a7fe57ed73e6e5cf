# Generates the man pages from the built pxflow (run by the build, cmake/PxflowInstall.cmake):
#   cmake -DPXFLOW=<pxflow> -DHELP2MAN=<help2man> -DOUT_DIR=<dir> -P PxflowManPages.cmake
# pxflow.1 is `pxflow --help` (the global options and the list of subcommands); each subcommand
# has its own page, pxflow-<command>.1 from `pxflow <command> --help`, as git does (git-commit.1):
# every subcommand has a dozen options of its own, and `man pxflow-check` finds them directly.
# The subcommands are read from --help, so a family's command (gap8) gets its page with no edit.
foreach(var PXFLOW HELP2MAN OUT_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "PxflowManPages.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run_pxflow out)
  execute_process(COMMAND ${PXFLOW} ${ARGN} OUTPUT_VARIABLE text ERROR_VARIABLE err
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pxflow ${ARGN} failed (${rc}): ${err}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# --version: "pxflow 0.1 (commit ..., compiler; backend families: ...)". help2man takes the
# first line as "program version" for the page footer, where the whole line would not fit; the
# footer gets "pxflow 0.1" and the full line goes into the VERSION section of pxflow.1.
run_pxflow(version_text --version)
string(REGEX MATCH "^pxflow ([^ \n]+)" matched "${version_text}")
if(NOT matched)
  message(FATAL_ERROR "pxflow --version does not start with 'pxflow VERSION': ${version_text}")
endif()
set(version ${CMAKE_MATCH_1})
string(REGEX REPLACE "\n.*" "" version_line "${version_text}")

# The subcommands: the lines of --help's "Subcommands:" section, "  NAME  description" (CLI11
# puts a long name's description on the next line).
run_pxflow(help --help)
string(REGEX REPLACE ".*\nSubcommands:\n" "" section "${help}")
if(section STREQUAL help)
  message(FATAL_ERROR "pxflow --help has no 'Subcommands:' section")
endif()
string(REGEX REPLACE "\n\n.*" "" section "${section}")
string(REPLACE "\n" ";" lines "${section}")
set(commands "")
set(name "")
foreach(line IN LISTS lines)
  if(line MATCHES "^  ([a-z0-9][a-z0-9-]*)( +(.+))?$")
    set(name ${CMAKE_MATCH_1})
    list(APPEND commands ${name})
    set(summary_${name} "${CMAKE_MATCH_3}")
  elseif(name AND line MATCHES "^ +(.+)$" AND NOT summary_${name})
    set(summary_${name} "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(NOT commands)
  message(FATAL_ERROR "pxflow --help lists no subcommands")
endif()

# help2man runs "pxflow ..." through the shell; the binary's folder goes first on PATH so that
# the usage lines read "pxflow", not the build path.
get_filename_component(bin_dir ${PXFLOW} DIRECTORY)
function(help2man program version_string summary include output)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env "PATH=${bin_dir}:$ENV{PATH}" ${HELP2MAN} --no-info
            --section=1 "--version-string=${version_string}" "--name=${summary}"
            "--include=${include}" "--output=${output}" "${program}"
    RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${output})
    message(FATAL_ERROR "help2man ${program} failed (${rc}): ${err}")
  endif()
  # --help ends with "Exit status:", "Environment:" and "Examples:" (hosts/cli/help_sections.hpp).
  # help2man makes sections of the last two itself and a subsection of the first: made EXIT
  # STATUS here, where man(7) puts it, after OPTIONS and before ENVIRONMENT.
  file(READ ${output} page)
  string(REPLACE ".SS \"Exit status:\"" ".SH \"EXIT STATUS\"" page "${page}")
  # The examples are command lines: set unfilled, or man would justify them across lines.
  string(FIND "${page}" "\n.SH EXAMPLES\n" at)
  if(at GREATER -1)
    math(EXPR body "${at} + 14")
    string(SUBSTRING "${page}" 0 ${body} before)
    string(SUBSTRING "${page}" ${body} -1 rest)
    string(FIND "${rest}" "\n.SH " next)
    string(SUBSTRING "${rest}" 0 ${next} examples)
    set(after "")
    if(next GREATER -1)
      string(SUBSTRING "${rest}" ${next} -1 after)
    endif()
    set(page "${before}.nf\n${examples}\n.fi${after}")
  endif()
  foreach(section "EXIT STATUS" ENVIRONMENT EXAMPLES)
    if(NOT page MATCHES "\n\\.SH \"?${section}\"?\n")
      message(FATAL_ERROR "${output}: no ${section} section (${program} --help lacks it)")
    endif()
  endforeach()
  file(WRITE ${output} "${page}")
endfunction()

file(GLOB stale ${OUT_DIR}/*.1 ${OUT_DIR}/*.h2m)
if(stale)
  file(REMOVE ${stale})
endif()
file(MAKE_DIRECTORY ${OUT_DIR})

set(see_also "")
foreach(command IN LISTS commands)
  string(APPEND see_also ".BR pxflow\\-${command} (1),\n")
  file(WRITE ${OUT_DIR}/pxflow-${command}.h2m "[SEE ALSO]\n.BR pxflow (1)\n")
  # "pxflow-flow (pxflow) 0.1": the page is pxflow-flow(1), its footer "pxflow 0.1".
  help2man("pxflow ${command}" "pxflow-${command} (pxflow) ${version}" "${summary_${command}}"
           ${OUT_DIR}/pxflow-${command}.h2m ${OUT_DIR}/pxflow-${command}.1)
  file(REMOVE ${OUT_DIR}/pxflow-${command}.h2m)
endforeach()
string(REGEX REPLACE ",\n$" "\n" see_also "${see_also}")
string(REPLACE "\\" "\\\\" version_roff "${version_line}")
file(WRITE ${OUT_DIR}/pxflow.h2m
     "[VERSION]\n\\fBpxflow \\-\\-version\\fR of the build this page was generated from:\n.br\n"
     "${version_roff}\n"
     "[SEE ALSO]\n${see_also}")
help2man(pxflow "pxflow ${version}" "cross-check the PX4FLOW optical-flow kernel across backends"
         ${OUT_DIR}/pxflow.h2m ${OUT_DIR}/pxflow.1)
file(REMOVE ${OUT_DIR}/pxflow.h2m)
