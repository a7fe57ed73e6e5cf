# pxflow_gap8_program(<name> SOURCES <files...> [INCLUDE_DIRS <dirs...>] [OUTPUT_DIR <dir>])
# Builds <name>.elf for the GAP8 cluster model with Debian's riscv64-unknown-elf-gcc: RV32IMC,
# ilp32, the runtime (crt0.S, runtime.c, link.ld) and libgcc for soft-float and 64-bit helpers.
# Defines the target gap8_prog_<name>; the ELF path is in the GAP8_PROGRAM_<name> variable.
# Does nothing when the toolchain is missing (PXFLOW_GAP8_HAVE_CC is then OFF).
include_guard(GLOBAL)
find_program(PXFLOW_GAP8_CC riscv64-unknown-elf-gcc)
find_program(PXFLOW_GAP8_OBJCOPY riscv64-unknown-elf-objcopy)  # binutils-riscv64-unknown-elf
if(PXFLOW_GAP8_CC AND EXISTS "${PXFLOW_GAP8_CC}" AND PXFLOW_GAP8_OBJCOPY)
  set(PXFLOW_GAP8_HAVE_CC ON CACHE INTERNAL "")
else()
  set(PXFLOW_GAP8_HAVE_CC OFF CACHE INTERNAL "")
  message(STATUS "gap8_model: riscv64-unknown-elf-gcc or -objcopy not found: GAP8 programs are "
                 "not built, their tests report SKIPPED (install gcc-riscv64-unknown-elf)")
endif()

# xpulp.h takes every instruction's fields from xpulp_fields.h and its C function wrappers from
# xpulp_functions.h, both generated from the model's table (../isa/xpulp.tbl). A target, not a custom command, so that programs of any directory
# can wait for it; the generator leaves an unchanged header's time alone.
if(PXFLOW_GAP8_HAVE_CC)
  find_package(Python3 REQUIRED COMPONENTS Interpreter GLOBAL)
  set(PXFLOW_GAP8_FIELDS_DIR ${CMAKE_BINARY_DIR}/gap8_runtime_generated CACHE INTERNAL "")
  add_custom_target(pxflow_gap8_xpulp_fields
    COMMAND Python3::Interpreter ${CMAKE_CURRENT_LIST_DIR}/../isa/gen_xpulp.py
            ${CMAKE_CURRENT_LIST_DIR}/../isa/xpulp.tbl
            --runtime-header ${PXFLOW_GAP8_FIELDS_DIR}/xpulp_fields.h
    BYPRODUCTS ${PXFLOW_GAP8_FIELDS_DIR}/xpulp_fields.h ${PXFLOW_GAP8_FIELDS_DIR}/xpulp_functions.h
    COMMENT "xpulp_fields.h and xpulp_functions.h from gap8_model/isa/xpulp.tbl"
    VERBATIM)
endif()

function(pxflow_gap8_program name)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR" "SOURCES;INCLUDE_DIRS" ${ARGN})
  if(NOT PXFLOW_GAP8_HAVE_CC)
    return()
  endif()
  if(NOT ARG_OUTPUT_DIR)
    set(ARG_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR})
  endif()
  set(cflags -march=rv32imc -mabi=ilp32 -misa-spec=2.2 -O2 -g ${PXFLOW_PORTABLE_OPTIONS}
      -ffreestanding -fno-builtin -fno-tree-loop-distribute-patterns)
  set(rt ${PXFLOW_GAP8_RUNTIME_DIR})
  set(elf ${ARG_OUTPUT_DIR}/${name}.elf)
  pxflow_cross_arguments(cross INCLUDE_DIRS ${rt} ${ARG_INCLUDE_DIRS} ${PXFLOW_GAP8_FIELDS_DIR}
                         SOURCES ${ARG_SOURCES})
  set(includes ${cross_INCLUDES})
  set(sources ${cross_SOURCES})
  pxflow_cross_output(${elf}
    COMMAND ${PXFLOW_GAP8_CC} ${cflags} ${includes} -nostdlib -nostartfiles
            -T ${rt}/link.ld -Wl,--no-warn-rwx-segments
            ${rt}/crt0.S ${rt}/runtime.c ${sources} -lgcc -o ${elf}
    DEPENDS ${sources} ${rt}/crt0.S ${rt}/runtime.c ${rt}/link.ld ${rt}/pmsis.h
            ${rt}/gap8_regs.h ${rt}/xpulp.h ${PXFLOW_GAP8_FIELDS_DIR}/xpulp_fields.h
            ${PXFLOW_GAP8_FIELDS_DIR}/xpulp_functions.h
    COMMENT "RISC-V ${name}.elf")
  add_custom_target(gap8_prog_${name} ALL DEPENDS ${elf})
  add_dependencies(gap8_prog_${name} pxflow_gap8_xpulp_fields)
  set(GAP8_PROGRAM_${name} ${elf} PARENT_SCOPE)
endfunction()
