/* Control flow as GCC emits it, for the Unicorn differential test: recursion, function
 * pointers (jalr), a switch (jump table), byte and half-word loads and stores, shifts. */
#include <stdint.h>

typedef uint32_t (*op_fn)(uint32_t, uint32_t);

static uint32_t op_add(uint32_t a, uint32_t b) { return a + b; }
static uint32_t op_rot(uint32_t a, uint32_t b) { return (a << (b & 31)) | (a >> ((32 - b) & 31)); }
static uint32_t op_mix(uint32_t a, uint32_t b) { return (a ^ (b * 0x9E3779B9u)) - (b >> 3); }
static op_fn ops[3] = {op_add, op_rot, op_mix};

static int fib(int n) { return n < 2 ? n : fib(n - 1) + fib(n - 2); }

static int classify(int v) {
  switch (v & 7) {
    case 0:
      return 11;
    case 1:
      return -3;
    case 2:
      return v >> 2;
    case 3:
      return v * 5;
    case 4:
      return 1000 - v;
    case 5:
      return v & 0x55;
    case 6:
      return -v;
    default:
      return 7;
  }
}

static int16_t halves[32];
static int8_t signed_bytes[32];

int main(void) {
  uint32_t h = 0x811C9DC5u;
  for (int i = 0; i < 48; ++i) h = ops[i % 3](h, (uint32_t)i * 2654435761u);
  int acc = fib(15);
  for (int i = 0; i < 40; ++i) acc += classify(i * 37 - 200);
  for (int i = 0; i < 32; ++i) {
    halves[i] = (int16_t)(h >> (i % 16)) - (int16_t)(i * 999);
    signed_bytes[i] = (int8_t)(halves[i] >> 3);
  }
  int32_t s = 0;
  for (int i = 0; i < 32; ++i) s += halves[i] * signed_bytes[31 - i] + (uint16_t)halves[i] % 7;
  return (int)(h ^ (uint32_t)acc ^ (uint32_t)s);
}
