/* Hardware loops (lp.setupi, lp.setup; the end address is the loop's last instruction) and
 * post-increment loads, in their PULPv2 encodings through .insn. */
#include "pmsis.h"

static const uint8_t data[16]
    __attribute__((aligned(4))) = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};

int main(void) {
  /* lp.setupi x0(L=0), count 10, end = pc + 2 * 4 (the second body instruction). */
  uint32_t counter = 0, sum = 0;
  __asm__ volatile(
      ".option push\n .option norvc\n"
      ".insn i 0x7B, 5, x0, x4, 10\n"
      "addi %0, %0, 1\n"
      "addi %1, %1, 2\n"
      ".option pop\n"
      : "+r"(counter), "+r"(sum));
  if (counter != 10 || sum != 20) return 1;

  /* lp.setup x1(L=1), count in a register, end = pc + 2 * 4: sums 16 bytes with p.lbu. */
  const uint8_t *p = data;
  uint32_t total = 0, n = 16, byte;
  __asm__ volatile(
      ".option push\n .option norvc\n"
      ".insn i 0x7B, 4, x1, %[n], 4\n"
      ".insn i 0x0B, 4, %[b], 1(%[p])\n"
      "add %[t], %[t], %[b]\n"
      ".option pop\n"
      : [t] "+r"(total), [p] "+r"(p), [b] "=&r"(byte)
      : [n] "r"(n)
      : "memory");
  if (total != 136 || p != data + 16) return 2;
  printf("hwloop ok\n");
  return 0;
}
