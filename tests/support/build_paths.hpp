// Paths of this build's programs and of the source files a test reads. Each test executable
// defines the ones it uses in one generated source (pxflow_build_paths() in
// cmake/PxflowTests.cmake); using one that its executable does not define is a link error.
// They are not -D flags because a path on the compiler's command line differs between two
// clones, and then ccache misses on every source of the executable, not only on one small file.
#pragma once

namespace build_paths {

extern const char* const pxflow;                 // the pxflow binary
extern const char* const pxflow_with_test_rows;  // pxflow with the planted test rows
extern const char* const source_dir;             // the project's source tree
extern const char* const build_dir;              // this build tree
extern const char* const report_schema;          // docs/report-schema.json
extern const char* const protocol_page;          // docs/dut-protocol.md
extern const char* const dut_ref;                // pxflow-dut-ref
extern const char* const dut_faulty;             // pxdut-faulty
extern const char* const dut_small;              // pxdut-small
extern const char* const dut_min_packet;         // pxdut-min-packet
extern const char* const gap8_program_dir;       // the model's test programs (*.elf)
extern const char* const gap8_kernel_dir;        // the GAP8 kernels (pxflow_gap8_*.elf)
extern const char* const gap8_objdump;           // riscv64-unknown-elf-objdump
extern const char* const xgap8_opcodes;          // GreenWaves' Xpulp encodings (test input)
extern const char* const m4_fault_dir;           // the faulty Cortex-M4 firmwares
extern const char* const m4_firmware;            // the Cortex-M4 firmware
extern const char* const opencl_kernel_source;   // kernels/opencl/opencl.cl
extern const char* const opencl_spin_source;     // tests/opencl/spin.cl
extern const char* const vulkan_shader_source;   // kernels/vulkan/flow.comp
extern const char* const install_consumer_dir;   // tests/install/consumer
extern const char* const cmake;                  // the cmake that configured this build

}  // namespace build_paths
