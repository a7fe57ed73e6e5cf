# pxflow_m4_firmware(<name> SOURCES <files...> [INCLUDE_DIRS ...] [DEFINITIONS ...]
#                    [COMPILE_OPTIONS ...] [LINK_OPTIONS ...] [STDIO])
# Builds <name>.elf for QEMU's mps2-an386 (Cortex-M4F) with Debian's arm-none-eabi-gcc: the
# board's start-up code, link (UART or semihosting), SysTick and semihosted exit
# (boards/mps2-an386), newlib-nano for memcpy/memset, and with STDIO newlib's rdimon (semihosted
# printf) for the self-tests. The target is m4_fw_<name>; the ELF's path is in M4_FIRMWARE_<name>.
# Does nothing when the toolchain is missing (PXFLOW_M4_HAVE_TOOLCHAIN OFF, the reason in
# PXFLOW_M4_TOOLCHAIN_WHY). Included by every folder that builds firmware (its variables are
# per folder).
set(PXFLOW_M4_BOARD_DIR ${PROJECT_SOURCE_DIR}/boards/mps2-an386)
set(PXFLOW_M4_KERNEL_DIR ${PROJECT_SOURCE_DIR}/kernels/cortex-m4)

find_program(PXFLOW_M4_CC arm-none-eabi-gcc)
find_program(PXFLOW_M4_QEMU qemu-system-arm)
set(PXFLOW_M4_TOOLCHAIN_WHY "")
if(NOT PXFLOW_M4_CC)
  set(PXFLOW_M4_TOOLCHAIN_WHY "arm-none-eabi-gcc not found (install gcc-arm-none-eabi)")
else()
  # The C library's spec files: -print-file-name answers the bare name when it has none.
  foreach(spec nano.specs rdimon.specs)
    execute_process(COMMAND ${PXFLOW_M4_CC} -print-file-name=${spec}
                    OUTPUT_VARIABLE found OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT IS_ABSOLUTE "${found}" OR NOT EXISTS "${found}")
      set(PXFLOW_M4_TOOLCHAIN_WHY
          "arm-none-eabi-gcc has no ${spec} (install libnewlib-arm-none-eabi)")
    endif()
  endforeach()
endif()
if(PXFLOW_M4_CC AND NOT PXFLOW_M4_TOOLCHAIN_WHY)
  set(PXFLOW_M4_HAVE_TOOLCHAIN ON)
else()
  set(PXFLOW_M4_HAVE_TOOLCHAIN OFF)
endif()

# The kernel and the board, as every firmware links them.
set(PXFLOW_M4_KERNEL_SOURCES ${PXFLOW_M4_KERNEL_DIR}/m4_flow_poi.c
    ${PXFLOW_M4_KERNEL_DIR}/m4_flow_frame.c)
set(PXFLOW_M4_KERNEL_HEADERS ${PXFLOW_M4_KERNEL_DIR}/m4_flow.h ${PXFLOW_M4_KERNEL_DIR}/m4_simd.h)
set(PXFLOW_M4_BOARD_SOURCES ${PXFLOW_M4_BOARD_DIR}/startup.c ${PXFLOW_M4_BOARD_DIR}/semihost.c
    ${PXFLOW_M4_BOARD_DIR}/uart_cmsdk.c ${PXFLOW_M4_BOARD_DIR}/link.c
    ${PXFLOW_M4_BOARD_DIR}/systick.c)

function(pxflow_m4_firmware name)
  cmake_parse_arguments(ARG "STDIO" "" "SOURCES;INCLUDE_DIRS;DEFINITIONS;COMPILE_OPTIONS;DEPENDS;LINK_OPTIONS"
                        ${ARGN})
  if(NOT PXFLOW_M4_HAVE_TOOLCHAIN)
    return()
  endif()
  # PXFLOW_PORTABLE_OPTIONS' -ffp-contract=off: no fused multiply-add, so that the FPU's
  # estimate rounds like the host's.
  set(cflags -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 ${PXFLOW_PORTABLE_OPTIONS}
      -O2 -g -std=gnu99 -ffunction-sections -fdata-sections)
  set(specs --specs=nano.specs)
  if(ARG_STDIO)
    list(APPEND specs --specs=rdimon.specs)
  endif()
  pxflow_cross_arguments(cross
    INCLUDE_DIRS ${PXFLOW_M4_KERNEL_DIR} ${PXFLOW_M4_BOARD_DIR} ${PXFLOW_SPEC_INCLUDE_DIR}
                 ${ARG_INCLUDE_DIRS}
    DEFINITIONS ${ARG_DEFINITIONS} SOURCES ${ARG_SOURCES})
  set(includes ${cross_INCLUDES})
  set(defs ${cross_DEFINES})
  set(sources ${cross_SOURCES})
  set(elf ${CMAKE_CURRENT_BINARY_DIR}/${name}.elf)
  pxflow_cross_output(${elf}
    COMMAND ${PXFLOW_M4_CC} ${cflags} ${ARG_COMPILE_OPTIONS} ${defs} ${includes} ${specs} -nostartfiles
            -T ${PXFLOW_M4_BOARD_DIR}/mps2_an386.ld -Wl,--gc-sections ${ARG_LINK_OPTIONS}
            ${PXFLOW_M4_BOARD_SOURCES} ${PXFLOW_M4_KERNEL_SOURCES} ${sources} -o ${elf}
    DEPENDS ${sources} ${PXFLOW_M4_BOARD_SOURCES} ${PXFLOW_M4_KERNEL_SOURCES}
            ${PXFLOW_M4_KERNEL_HEADERS} ${PXFLOW_SPEC_HEADERS} ${PXFLOW_M4_BOARD_DIR}/board.h
            ${PXFLOW_M4_BOARD_DIR}/mps2_an386.ld ${ARG_DEPENDS}
    COMMENT "Cortex-M4 ${name}.elf")
  add_custom_target(m4_fw_${name} ALL DEPENDS ${elf})
  set(M4_FIRMWARE_${name} ${elf} PARENT_SCOPE)
endfunction()
