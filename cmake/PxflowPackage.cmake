# Packages of the installed tree (`cpack --config build/CPackConfig.cmake`, docs/install.md):
#   pxflow-<version>-linux-<arch>.tar.gz  relocatable: unpack anywhere and run bin/pxflow. The
#       programs find their own modules and data beside themselves (hosts/core/own_files.hpp) and
#       load shared libraries from ../lib first (RUNPATH $ORIGIN/../lib), where the package holds
#       every library they need that is not the C library itself: the OpenCL ICD loader, the
#       Vulkan loader, the C++ runtime, libelf (cmake/PxflowBundleRuntime.cmake). The drivers
#       stay the machine's (OCL_ICD_VENDORS, VK_DRIVER_FILES); OpenCV stays an optional module.
#   pxflow_<version>_<arch>.deb           for /usr on Debian: the same tree, nothing bundled; its
#       Depends come from dpkg-shlibdeps (dpkg-dev, ci/packages.txt).
# Include after pxflow_install(), which names the programs in PXFLOW_INSTALLED_PROGRAMS.
include_guard(GLOBAL)

foreach(program IN LISTS PXFLOW_INSTALLED_PROGRAMS)
  set_target_properties(${program} PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
endforeach()

set(CPACK_PACKAGE_NAME pxflow)
set(CPACK_PACKAGE_VENDOR "pxflow")
set(CPACK_PACKAGE_CONTACT "pxflow developers <pxflow@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "cross-check suite for the PX4FLOW optical-flow kernel on CPUs, GPUs, GAP8 and Cortex-M4")
string(TOLOWER ${CMAKE_SYSTEM_NAME}-${CMAKE_SYSTEM_PROCESSOR} PXFLOW_PACKAGE_SYSTEM)
set(CPACK_PACKAGE_FILE_NAME ${CPACK_PACKAGE_NAME}-${PROJECT_VERSION}-${PXFLOW_PACKAGE_SYSTEM})
set(CPACK_GENERATOR TGZ DEB)
set(CPACK_INCLUDE_TOPLEVEL_DIRECTORY ON)  # the tarball unpacks into one folder
set(CPACK_STRIP_FILES OFF)
# Run by cpack once the tree is staged, before it is archived (per generator).
set(CPACK_PRE_BUILD_SCRIPTS ${PROJECT_SOURCE_DIR}/cmake/PxflowBundleRuntime.cmake)
set(CPACK_PXFLOW_LIBDIR ${CMAKE_INSTALL_LIBDIR})
set(CPACK_PXFLOW_BINDIR ${CMAKE_INSTALL_BINDIR})

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# qemu-system-arm runs the m4-qemu row; without it that row is skipped with its reason.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "qemu-system-arm, pocl-opencl-icd, mesa-vulkan-drivers")

include(CPack)
