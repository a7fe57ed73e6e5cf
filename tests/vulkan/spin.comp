#version 450
// A compute shader that does not end, for the hang tests (tests/vulkan/test_vulkan_hang.cpp):
// every invocation waits for `stop` to change, which nothing ever writes, and counts while it
// waits. The buffer is volatile (every read goes to memory) and the loop writes it, so no
// compiler may hoist the read or delete the loop. On a GPU one invocation spins for ever.
// lavapipe (llvmpipe) ends every invocation after 65,535 loop iterations in all (its guard
// against runaway shaders, measured: count = 65535), so the test dispatches 65,535 x 65,535
// work-groups of 64: about 1.8e16 iterations, months of a CPU device's time.
layout(local_size_x = 64) in;
layout(std430, binding = 0) coherent volatile buffer Flag {
  uint stop;
  uint count;
};

void main() {
  while (stop == 0u) {
    count += 1u;
  }
}
