# ccache (ci/packages.txt) in front of the host C and C++ compilers when it is installed, set so that
# a second build of the same sources hits the cache wherever it lies: another clone (CI's fresh
# clone of main), another build folder of the same clone (the sanitizer stage, its own flags
# miss). base_dir makes the absolute paths under the source tree relative before hashing and
# compiling; hash_dir=false leaves the working folder out of the hash (-g would put it in).
# -DPXFLOW_CCACHE=OFF turns it off; a launcher the caller set is kept.
option(PXFLOW_CCACHE "Compile through ccache when it is installed" ON)
find_program(PXFLOW_CCACHE_PROGRAM ccache)
if(PXFLOW_CCACHE AND PXFLOW_CCACHE_PROGRAM)
  foreach(lang C CXX)
    if(NOT CMAKE_${lang}_COMPILER_LAUNCHER)
      set(CMAKE_${lang}_COMPILER_LAUNCHER
          ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=1
          ${PXFLOW_CCACHE_PROGRAM})
    endif()
  endforeach()
endif()
