/* Plain computation for the Unicorn differential test: no peripheral access before the exit,
 * so both simulators run it to __gap8_exit. Exercises RV32IMC as GCC emits it, libgcc's
 * soft-float and 64-bit helpers, and memory traffic in L1 (stack) and L2 (globals). */
#include <stdint.h>

static uint32_t table[64];
static int64_t wide[16];

static uint32_t crc32(const uint8_t *p, int n) {
  uint32_t crc = 0xFFFFFFFFu;
  for (int i = 0; i < n; ++i) {
    crc ^= p[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

static void insertion_sort(uint32_t *v, int n) {
  for (int i = 1; i < n; ++i) {
    uint32_t x = v[i];
    int j = i - 1;
    while (j >= 0 && v[j] > x) {
      v[j + 1] = v[j];
      --j;
    }
    v[j + 1] = x;
  }
}

static float soft_float(int n) {
  float acc = 0.5f;
  for (int i = 1; i <= n; ++i) acc = acc * 1.25f + (float)i / 3.0f - (float)(i % 5);
  return acc;
}

int main(void) {
  uint32_t x = 12345;
  for (int i = 0; i < 64; ++i) {
    x = x * 1103515245u + 12345u;
    table[i] = x >> 3;
  }
  insertion_sort(table, 64);
  int32_t divs = 0;
  for (int i = 0; i < 64; ++i) {
    int32_t a = (int32_t)table[i] - (int32_t)0x08000000, b = (int32_t)(table[63 - i] % 97) - 48;
    divs += b ? a / b + a % b : a;
    divs ^= (int32_t)((uint32_t)a / (table[i] % 13 + 1));
  }
  for (int i = 0; i < 16; ++i) wide[i] = (int64_t)table[i] * (int64_t)(table[i + 16] | 1) / 7 - i;
  uint8_t local[32];
  for (int i = 0; i < 32; ++i) local[i] = (uint8_t)(wide[i % 16] >> (i % 8));
  const float f = soft_float(20);
  volatile uint32_t bits;
  __builtin_memcpy((void *)&bits, &f, 4);
  return (int)(crc32(local, 32) ^ (uint32_t)divs ^ bits ^ (uint32_t)(wide[3] >> 17));
}
