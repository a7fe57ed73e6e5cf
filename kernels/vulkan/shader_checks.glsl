// The checks flow.comp runs on itself (docs/vulkan.md, "Shader checks"). Kept out of flow.comp so
// that the mutation tool (tests/mutation/targets.py) mutates the kernel, never its checker.
// Included after the frame binding (`frame_texels`) and the push constants (`pc`).
//
// Two builds (kernels/vulkan/CMakeLists.txt): with PXFLOW_SHADER_CHECKS defined, the checked
// shader below, which `pxflow check`, `flow` and bench's check run; without it, the production
// shader at the end of this file (plain accesses, no poison, no binding 2), which bench times and
// `check` runs beside the checked one (hosts/vulkan/vulkan_backend.hpp, VulkanShaders). What the
// checks cost: docs/vulkan.md, "Benchmark".

const uint kPrev = 0u;
const uint kNext = 1u;

// Where this invocation's prev (frame = kPrev) or next (kNext) starts: pair p's prev at word
// 2*p*words_per_frame of the chunk, its next right after (hosts/vulkan/vulkan_backend.cpp).
uint frame_base(uint frame) {
  uint pair = (pc.first_item + gl_GlobalInvocationID.x) / pc.pois_per_pair;
  return (2u * pair + frame) * pc.words_per_frame;
}

#ifdef PXFLOW_SHADER_CHECKS

// Why: a GPU gives no fault for an index past a private array, for a read past the frame it was
// meant to read, or for a private value read before it was written. Lavapipe reads some other
// value (0, or another pair's pixels), a GPU may do anything, and no sanitizer sees shader code,
// so an off-by-one in the kernel can leave every record right on one driver and wrong on the next.
// - Every dynamic index into a private array goes through AT(array, index): an index in range is
//   used as it is; one out of range is replaced by 0 (a harmless access) and its source line kept.
// - Every frame word is read through FRAME_WORD(frame, word), `word` counted from the start of
//   the invocation's prev (kPrev) or next (kNext) frame, whose base this file computes from the
//   invocation and the host's layout: a word outside the frame is replaced by word 0 and its
//   source line kept. The frame's spare last word (hosts/vulkan/batch_plan.hpp) is inside it.
// - Every private array is filled with kPoison by POISON(array) where it is declared (or, for an
//   `out` array, where its function starts), so an element the kernel forgets to write changes the
//   records on every driver, instead of being whatever the driver leaves there (0 on lavapipe).
//   Where the kernel writes every element, the driver drops the poison as dead stores.
// main() ends with report_shader_faults(), which adds a faulting invocation to `Faults`; the host
// clears that before each chunk and reads it after (hosts/vulkan/vulkan_backend.cpp), and a fault
// fails the run. Constant private indices need no check: glslangValidator rejects a constant index
// out of range at build time.
//
// Why selects and a private variable, not a store at the faulting access: a conditional atomic
// inside the unrolled search is a per-lane loop on lavapipe and doubled the time at S = 16; a
// select folds away wherever the unrolled index is a constant. docs/vulkan.md gives the cost.

// Binding 2: the first faulting invocation's fault (its kind in bits 16 and up, its source line in
// bits 0-15; 0 = none) and how many invocations faulted, over the chunk. The host's copy is
// `ShaderFaults` in hosts/vulkan/vulkan_backend.cpp.
layout(std430, set = 0, binding = 2) buffer Faults {
  uint first_fault;
  uint invocations;
}
faults;

const uint kFaultPrivateIndex = 1u;  // an index past a private array
const uint kFaultFrameRead = 2u;     // a read outside the invocation's frame

uint fault = 0u;  // this invocation's first fault (kind << 16 | line), 0 = none

void note_fault(bool ok, uint kind, int line) {
  fault = (ok || fault != 0u) ? fault : (kind << 16) | uint(line);
}

int checked_index(int index, int length, int line) {
  bool in_range = uint(index) < uint(length);
  note_fault(in_range, kFaultPrivateIndex, line);
  return in_range ? index : 0;
}

#define AT(array, index) array[checked_index(int(index), array.length(), __LINE__)]

uint checked_frame_word(uint frame, uint word, int line) {
  bool inside = word < pc.words_per_frame;
  note_fault(inside, kFaultFrameRead, line);
  return texelFetch(frame_texels, int(frame_base(frame) + (inside ? word : 0u))).x;
}

// Word `word` of this invocation's prev (kPrev) or next (kNext), counted from the frame's start.
#define FRAME_WORD(frame, word) checked_frame_word(frame, word, __LINE__)

// A value no correct kernel reads: the 8-bit lanes are above every pixel, and as a sum it is far
// from every SAD, feature value and pixel sum.
const int kPoison = 0x5A5A5A5A;

#define POISON(array) \
  [[unroll]] for (int poison_i = 0; poison_i < array.length(); ++poison_i) array[poison_i] = kPoison

void report_shader_faults() {
  if (fault == 0u) return;
  atomicCompSwap(faults.first_fault, 0u, fault);
  atomicAdd(faults.invocations, 1u);
}

#else  // the production shader: the same accesses, unchecked, and nothing to report

#define AT(array, index) array[index]
#define FRAME_WORD(frame, word) texelFetch(frame_texels, int(frame_base(frame) + (word))).x
#define POISON(array)

void report_shader_faults() {}

#endif
