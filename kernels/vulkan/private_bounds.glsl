// Bounds checks for flow.comp's private arrays (docs/vulkan.md, "Private arrays"). Kept out of
// flow.comp so that the mutation tool (tests/mutation/targets.py) mutates the kernel, never its
// checker.
//
// Why: a GPU gives no fault for an index past a private array. Lavapipe reads some other value
// or drops the write, a GPU may do either or worse, and no sanitizer sees shader code, so an
// off-by-one in the kernel can leave every record right on one driver and wrong on the next.
// Every dynamic index into a private array therefore goes through AT(array, index): an index in
// range is used as it is; one out of range is replaced by 0 (a harmless access) and its source
// line is kept in the invocation's private `fault_line`. main() ends with report_private_faults(),
// which adds a faulting invocation to `Faults`; the host clears that before each chunk and reads
// it after (hosts/vulkan/vulkan_backend.cpp), and a fault fails the run. Constant indices need no
// check: glslangValidator rejects a constant index out of range at build time.
//
// Why selects and a private variable, not a store at the faulting access: a conditional atomic
// inside the unrolled search is a per-lane loop on lavapipe and doubled the time at S = 16; a
// select folds away wherever the unrolled index is a constant. docs/vulkan.md gives the cost.

// Binding 2: the first faulting invocation's source line (0 = none) and how many invocations
// faulted, over the chunk.
layout(std430, set = 0, binding = 2) buffer Faults {
  uint first_line;
  uint invocations;
}
faults;

uint fault_line = 0u;  // this invocation's first out-of-range index (its line), 0 = none

int checked_index(int index, int length, int line) {
  bool in_range = uint(index) < uint(length);
  fault_line = (in_range || fault_line != 0u) ? fault_line : uint(line);
  return in_range ? index : 0;
}

void report_private_faults() {
  if (fault_line == 0u) return;
  atomicCompSwap(faults.first_line, 0u, fault_line);
  atomicAdd(faults.invocations, 1u);
}

#define AT(array, index) array[checked_index(int(index), array.length(), __LINE__)]
