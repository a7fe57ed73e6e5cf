"""Which registry rows each mutated kernel file is checked with, and what to rebuild.

The one table of the mutation tool (mutate.py): a kernel file -> its family and the rows built
from it. A family says which build outputs hold the compiled file (compared byte for byte before
and after a mutation: identical code is a trivially equivalent mutant, no check run) and which
targets must be rebuilt before `pxflow check` sees the mutant.
"""

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Family:
    name: str
    # the registry family of its rows (`pxflow backends --json -`), "" for a --dut row
    registry: str
    # ninja targets (relative to the build folder) that compile the file: built first, then the
    # artifacts are compared with the unmutated build's.
    compile_targets: tuple
    # globs (relative to the build folder) of the compiled outputs; empty when the source is
    # compiled at run time (OpenCL C: PoCL compiles the embedded text).
    artifacts: tuple
    # what `pxflow check` runs: rebuilt after the artifacts differ.
    link_targets: tuple = ("pxflow",)
    # extra `pxflow check` arguments (the dut reference device is a --dut row).
    check_args: tuple = ()
    # The test of .ci/run (ci/run-tests.sh) that runs the family's code under a memory checker,
    # as (stage, ctest name): "sanitizer" for its ASan+UBSan stage (host code: the host process
    # or the host-built dut reference device), "release" for a Release-stage test with its own
    # checker (Oclgrind for OpenCL C). Empty for code a device runs (a GPU driver, the GAP8
    # model's ISS, QEMU), which no memory checker here instruments.
    memory_test: tuple = ()


GAP8_ELVES = tuple(f"kernels/gap8/pxflow_gap8_{v}.elf" for v in ("original", "local", "global", "fast"))
REF_OBJECTS = ("reference/CMakeFiles/pxflow_reference.dir/*.o",)
VULKAN_BUILDS = tuple(f"kernels/vulkan/generated/{b}.spv" for b in ("flow", "flow_checked"))
# tests/conformance: the reference and CPU rows on the whole default corpus, one test per row (a
# ctest -R regex; ref-original runs in each as the reference).
CPU_ROWS_UNDER_ASAN = ("sanitizer", r"conformance\.(ref-local|ref-global|swar|sse2|sse41|avx2|avx512bw|cpu)")
M4_ELF = ("hosts/m4qemu/pxflow_m4_dut.elf",)
DUT_OBJECT = ("dut/CMakeFiles/pxdut_algo.dir/src/pxdut_kernel.c.o",)
DUT_REF_ARGS = ("--dut", "dutref=exec:{build}/pxflow-dut-ref")
DUT_REF_UNDER_ASAN = ("sanitizer", "dut_ref_check_fixed_corpus")
POI_KERNEL_OUTPUTS = GAP8_ELVES + M4_ELF + DUT_OBJECT

FAMILIES = {
    f.name: f
    for f in (
        Family("cpu", "cpu", ("kernels/cpu/libpxflow_cpu_kernels.a",),
               ("kernels/cpu/CMakeFiles/pxflow_cpu_kernels.dir/*.o",),
               memory_test=CPU_ROWS_UNDER_ASAN),
        Family("ref-original", "reference", ("reference/libpxflow_reference.a",), REF_OBJECTS,
               memory_test=CPU_ROWS_UNDER_ASAN),
        Family("ref-local", "reference", ("reference/libpxflow_reference.a",), REF_OBJECTS,
               memory_test=CPU_ROWS_UNDER_ASAN),
        Family("ref-global", "reference", ("reference/libpxflow_reference.a",), REF_OBJECTS,
               memory_test=CPU_ROWS_UNDER_ASAN),
        # tests/opencl/CMakeLists.txt: both OpenCL rows under Oclgrind, in the Release stage.
        Family("opencl", "opencl", ("pxflow",), (),
               memory_test=("release", "opencl_memcheck_oclgrind")),
        # Both builds of flow.comp (kernels/vulkan/CMakeLists.txt): pxflow check runs both.
        Family("vulkan", "vulkan", VULKAN_BUILDS, VULKAN_BUILDS),
        Family("gap8", "gap8", GAP8_ELVES, GAP8_ELVES),
        Family("cortex-m4", "m4qemu", M4_ELF, M4_ELF),
        # tests/dut/CMakeLists.txt: the dut reference device on the whole default corpus.
        Family("dut", "", DUT_OBJECT, DUT_OBJECT, ("pxflow", "pxflow-dut-ref"), DUT_REF_ARGS,
               memory_test=DUT_REF_UNDER_ASAN),
        # The shared per-POI kernel (spec/include/pxflow_spec/poi_kernel.h): compiled into every
        # GAP8 ELF, the Cortex-M4 firmware and the dut reference device. Its rows span the gap8
        # and m4qemu registry families and the dutref option row, so no one registry family
        # names them (""): self_test.py checks the same row names through the gap8, cortex-m4
        # and dut entries.
        Family("poi-kernel", "", POI_KERNEL_OUTPUTS, POI_KERNEL_OUTPUTS,
               ("pxflow", "pxflow-dut-ref"), DUT_REF_ARGS, memory_test=DUT_REF_UNDER_ASAN),
    )
}


@dataclass(frozen=True)
class Target:
    path: str  # relative to the source tree
    family: str
    rows: tuple = field(default_factory=tuple)  # the rows built from it (--backends, --require)


X86 = ("sse2", "sse41", "avx2", "avx512bw")
GAP8_ALL = ("gap8-original", "gap8-local", "gap8-global", "gap8-fast")

# kernels/cpu/neon.cpp is not listed: it is compiled for aarch64 only (no row on x86-64 CI).
# ref-original is the reference every row is checked against: its mutants are checked by the
# rows ref-local and ref-global (a mutant of the answer makes them differ).
TARGETS = (
    Target("kernels/cpu/swar.cpp", "cpu", ("swar",)),
    Target("kernels/cpu/sse2.cpp", "cpu", ("sse2",)),
    Target("kernels/cpu/sse41.cpp", "cpu", ("sse41",)),
    Target("kernels/cpu/avx2.cpp", "cpu", ("avx2",)),
    Target("kernels/cpu/avx512bw.cpp", "cpu", ("avx512bw",)),
    Target("kernels/cpu/poi_loop.cpp", "cpu", ("swar",) + X86),  # not window_guard.cpp: a checker
    Target("kernels/cpu/x86_feature.hpp", "cpu", X86),
    Target("kernels/cpu/x86_half_pixel.hpp", "cpu", ("sse2", "sse41", "avx2")),
    Target("kernels/cpu/x86_argmin.hpp", "cpu", ("sse41", "avx2")),
    Target("reference/kernel_original.cpp", "ref-original", ("ref-local", "ref-global")),
    Target("reference/kernel_local.cpp", "ref-local", ("ref-local",)),
    Target("reference/kernel_global.cpp", "ref-global", ("ref-global",)),
    Target("kernels/opencl/opencl.cl", "opencl", ("opencl-item", "opencl-group")),
    Target("kernels/vulkan/flow.comp", "vulkan", ("vulkan",)),
    Target("kernels/gap8/flow_main.c", "gap8", GAP8_ALL),
    Target("kernels/gap8/flow_poi.c", "gap8", GAP8_ALL),
    Target("kernels/gap8/flow_simd.h", "gap8", GAP8_ALL),
    Target("kernels/gap8/search_raster.h", "gap8", GAP8_ALL),
    Target("kernels/gap8/flow_search.c", "gap8", ("gap8-original", "gap8-local", "gap8-global")),
    Target("kernels/gap8/half_original.c", "gap8", ("gap8-original",)),
    Target("kernels/gap8/half_local.c", "gap8", ("gap8-local",)),
    Target("kernels/gap8/half_global.c", "gap8", ("gap8-global",)),
    Target("kernels/gap8/half_planes.h", "gap8", ("gap8-global",)),
    Target("kernels/gap8/half_registers.h", "gap8", ("gap8-local", "gap8-fast")),
    Target("kernels/gap8/flow_search_fast.c", "gap8", ("gap8-fast",)),
    Target("kernels/gap8/fast_tables.c", "gap8", ("gap8-fast",)),
    Target("kernels/gap8/fast_tables.h", "gap8", ("gap8-fast",)),
    Target("kernels/gap8/fast_serial.c", "gap8", ("gap8-fast",)),
    Target("kernels/gap8/fast_float.h", "gap8", ("gap8-fast",)),
    Target("kernels/gap8/half_fast.c", "gap8", ("gap8-fast",)),
    Target("kernels/cortex-m4/m4_flow_poi.c", "cortex-m4", ("m4-qemu",)),
    Target("kernels/cortex-m4/m4_flow_frame.c", "cortex-m4", ("m4-qemu",)),
    Target("kernels/cortex-m4/m4_simd.h", "cortex-m4", ("m4-qemu",)),
    Target("dut/src/pxdut_kernel.c", "dut", ("dutref",)),
    Target("dut/src/pxdut_primitives.h", "dut", ("dutref",)),
    Target("spec/include/pxflow_spec/poi_kernel.h", "poi-kernel", GAP8_ALL + ("m4-qemu", "dutref")),
)

# Rows that are not registry rows of the binary but made by a family option (check_args).
OPTION_ROWS = {"dutref"}


def language(path):
    """The source language of a kernel file, for the operators that depend on it."""
    if path.endswith(".comp"):
        return "glsl"
    if path.endswith(".cl"):
        return "opencl"
    if path.endswith((".c", ".h")):
        return "c"
    return "c++"
