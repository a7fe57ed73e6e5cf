/* Exact counter values for short instruction blocks: each block runs between the store that
 * starts the counters and the one that stops them, so INSTR = block + 1 (the stop store) and
 * CYCLES = 1 (the start store, a peripheral access) + the block's documented cost. Each block
 * runs twice (WARM) and the second pass is checked: its code is in the instruction cache, so
 * these are the pipeline's costs alone (IMISS = 0 is checked too); timing.c measures misses. */
#include "pmsis.h"

#define START_STOP_PROLOGUE "li t0, %[start]\n li t1, %[stop]\n sw zero, 0(t0)\n"
#define STOP "sw zero, 0(t1)\n"
#define REGS [start] "i"(GAP8_PERF_START), [stop] "i"(GAP8_PERF_STOP)

static uint32_t l1_word PI_L1 = 5;
static uint32_t l2_word = 7;
static int failures;

static void expect(const char *block, int event, const char *name, unsigned want) {
  const unsigned got = pi_perf_read(event);
  if (got != want) {
    printf("%s: %s = %u, expected %u\n", block, name, got, want);
    failures++;
  }
}

static void begin(void) {
  pi_perf_conf(0xFFFFFFFFu);
  pi_perf_reset();
}

/* The block twice, in a loop the compiler cannot unroll (one copy of the code). */
#define WARM(block)                                  \
  for (volatile int pass_ = 0; pass_ < 2; ++pass_) { \
    begin();                                         \
    block;                                           \
  }                                                  \
  expect("warm", PI_PERF_IMISS, "IMISS", 0)

int main(void) {
  WARM(__asm__ volatile(START_STOP_PROLOGUE ".option push\n .option norvc\n"
                                            ".rept 10\n addi a0, a0, 1\n .endr\n"
                                            ".option pop\n" STOP ::REGS
                        : "t0", "t1", "a0", "memory"));
  expect("alu", PI_PERF_INSTR, "INSTR", 11);
  expect("alu", PI_PERF_CYCLES, "CYCLES", 11);
  expect("alu", PI_PERF_ACTIVE_CYCLES, "ACTIVE", 11);
  expect("alu", PI_PERF_ST, "ST", 1);
  expect("alu", PI_PERF_RVC, "RVC", 0);

  WARM(__asm__ volatile("mv a2, %[p]\n" START_STOP_PROLOGUE
                        "lw a1, 0(a2)\n addi a1, a1, 1\n" STOP ::REGS,
                        [p] "r"(&l1_word)
                        : "t0", "t1", "a1", "a2", "memory"));
  expect("load-use", PI_PERF_CYCLES, "CYCLES", 1 + 1 + 1 + 1);
  expect("load-use", PI_PERF_LD_STALL, "LD_STALL", 1);
  expect("load-use", PI_PERF_LD, "LD", 1);
  expect("load-use", PI_PERF_LD_EXT, "LD_EXT", 0);

  WARM(__asm__ volatile(
      "mv a2, %[p]\n" START_STOP_PROLOGUE "lw a1, 0(a2)\n" STOP ::REGS, [p] "r"(&l2_word)
      : "t0", "t1", "a1", "a2", "memory"));
  expect("l2-load", PI_PERF_CYCLES, "CYCLES", 1 + 1 + 8);
  expect("l2-load", PI_PERF_LD_EXT, "LD_EXT", 1);
  expect("l2-load", PI_PERF_LD_EXT_CYC, "LD_EXT_CYC", 8);

  WARM(__asm__ volatile(START_STOP_PROLOGUE
                        "beq zero, zero, 1f\n 1: bne zero, zero, 2f\n 2: j 3f\n 3:\n" STOP ::REGS
                        : "t0", "t1", "memory"));
  expect("branches", PI_PERF_CYCLES, "CYCLES", 1 + 3 + 1 + 2);
  expect("branches", PI_PERF_BRANCH, "BRANCH", 2);
  expect("branches", PI_PERF_BTAKEN, "BTAKEN", 1);
  expect("branches", PI_PERF_JUMP, "JUMP", 1);

  WARM(__asm__ volatile(
      "li a1, 3\n li a3, 1\n" START_STOP_PROLOGUE
      "mul a0, a1, a1\n addi a0, a0, 1\n mulh a0, a1, a1\n div a0, a1, a3\n" STOP ::REGS
      : "t0", "t1", "a0", "a1", "a3", "memory"));
  /* mul 1 + use stall 1 + addi 1 + mulh 5 + div by 1: clz(1) + 3 = 34 */
  expect("mul-div", PI_PERF_CYCLES, "CYCLES", 1 + 1 + 1 + 1 + 5 + 34);

  WARM(__asm__ volatile(START_STOP_PROLOGUE
                        "c.addi a0, 1\n c.addi a0, 1\n c.addi a0, 1\n" STOP ::REGS
                        : "t0", "t1", "a0", "memory"));
  expect("compressed", PI_PERF_RVC, "RVC", 3);
  expect("compressed", PI_PERF_INSTR, "INSTR", 4);

  /* jr right after the instruction that computed its target: one jump-register stall. */
  WARM(__asm__ volatile(".option push\n .option norelax\n" START_STOP_PROLOGUE
                        "la t2, 1f\n jr t2\n 1:\n" STOP ".option pop\n" ::REGS
                        : "t0", "t1", "t2", "memory"));
  expect("jump-register", PI_PERF_JR_STALL, "JR_STALL", 1);
  expect("jump-register", PI_PERF_JUMP, "JUMP", 1);
  expect("jump-register", PI_PERF_CYCLES, "CYCLES", 1 + 1 + 1 + 1 + 2);

  /* A misaligned word load is split in two: one more cycle, counted as two loads. */
  WARM(__asm__ volatile(
      "mv a2, %[p]\n" START_STOP_PROLOGUE "lw a1, 1(a2)\n" STOP ::REGS, [p] "r"(&l1_word)
      : "t0", "t1", "a1", "a2", "memory"));
  expect("misaligned", PI_PERF_CYCLES, "CYCLES", 1 + 2);
  expect("misaligned", PI_PERF_LD, "LD", 2);

  /* Hardware loop of 4 iterations over two addi (RI5CY's minimum loop size): set-up 1 cycle,
   * back edges free. */
  WARM(__asm__ volatile(START_STOP_PROLOGUE ".option push\n .option norvc\n"
                                            ".insn i 0x7B, 5, x0, x4, 4\n addi a0, a0, 1\n"
                                            " addi a0, a0, 1\n.option pop\n" STOP ::REGS
                        : "t0", "t1", "a0", "memory"));
  expect("hwloop", PI_PERF_INSTR, "INSTR", 1 + 4 * 2 + 1);
  expect("hwloop", PI_PERF_CYCLES, "CYCLES", 1 + 1 + 4 * 2);
  expect("hwloop", PI_PERF_BRANCH, "BRANCH", 0);

  /* A disabled event reads 0; a stopped counter keeps its value. */
  pi_perf_conf(1u << PI_PERF_INSTR);
  pi_perf_reset();
  __asm__ volatile(START_STOP_PROLOGUE "mv a2, %[p]\n lw a1, 0(a2)\n" STOP ::REGS, [p] "r"(&l1_word)
                   : "t0", "t1", "a1", "a2", "memory");
  expect("mask", PI_PERF_LD, "LD", 0);
  expect("mask", PI_PERF_INSTR, "INSTR", 3);
  for (volatile int i = 0; i < 10; ++i) {
  }
  expect("stopped", PI_PERF_INSTR, "INSTR", 3);

  if (failures) return 1;
  printf("counters ok\n");
  return 0;
}
