/* Exact costs of the cluster's timing rules, measured with the counters over hand-written
 * sequences (docs/gap8-model.md derives each expected value). Every sequence runs three times
 * and the last pass is kept, so its code is in the instruction cache, except the icache one,
 * which measures the cold first pass. The host picks the sequence in timing_mode and reads
 * results[]: CYCLES, ACTIVE_CYCLES, INSTR, IMISS of core 0 over the sequence. */
#include "pmsis.h"

volatile uint32_t timing_mode = 99; /* in .data: set by the host */
volatile uint32_t results[8];

static uint8_t l2_src[1024];
static uint8_t l1_dst[1024] PI_L1 __attribute__((aligned(4)));

/* The fork's entry: returns at once. */
__asm__(".text\n .balign 16\n .global timing_entry\n timing_entry: ret\n");
void timing_entry(void *);

static void record(void) {
  results[0] = pi_perf_read(PI_PERF_CYCLES);
  results[1] = pi_perf_read(PI_PERF_ACTIVE_CYCLES);
  results[2] = pi_perf_read(PI_PERF_INSTR);
  results[3] = pi_perf_read(PI_PERF_IMISS);
  results[4] = pi_perf_read(PI_PERF_TCDM_CONT);
  results[5] = pi_perf_read(PI_PERF_LD_EXT);
  results[6] = pi_perf_read(PI_PERF_ST_EXT);
  results[7] = pi_perf_read(PI_PERF_LD_EXT_CYC);
}

static void begin(void) {
  pi_perf_conf(0xFFFFFFFFu);
  pi_perf_reset();
}

/* Cold code: nop and the start store in line L0, 2 + 28 + 1 addi over lines L0..L8 and a loop
 * back over L1..L8 once. The first pass misses L1..L8 (8 refills), the second hits. */
static void icache_cold(void) {
  begin();
  __asm__ volatile(
      "li t0, %[start]\n li t1, %[stop]\n"
      ".option push\n .option norvc\n"
      ".balign 16\n"
      "nop\n sw zero, 0(t0)\n addi t2, zero, 2\n nop\n"  /* L0 */
      "1:\n .rept 28\n addi a0, a0, 1\n .endr\n"         /* L1..L7 */
      "addi t2, t2, -1\n bnez t2, 1b\n sw zero, 0(t1)\n" /* L8 */
      ".option pop\n"
      :
      : [start] "i"(GAP8_PERF_START), [stop] "i"(GAP8_PERF_STOP)
      : "t0", "t1", "t2", "a0", "memory");
  record();
}

/* pulp-os's rt_team_fork on the master, with the entry that returns at once. */
static void fork_once(uint32_t mask) {
  begin();
  __asm__ volatile(
      "li t0, %[start]\n li t1, %[stop]\n"
      "sw zero, 0(t0)\n"
      "sw %[mask], %[team](%[eu])\n"
      "sw %[mask], %[bmask](%[eu])\n"
      "sw %[mask], %[btarget](%[eu])\n"
      "sw %[entry], %[fifo](%[eu])\n"
      "sw zero, %[fifo](%[eu])\n"
      "jal ra, timing_entry\n"
      "lw t2, %[bwait](%[eu])\n"
      "sw zero, 0(t1)\n"
      :
      : [start] "i"(GAP8_PERF_START), [stop] "i"(GAP8_PERF_STOP), [mask] "r"(mask),
        [entry] "r"(timing_entry), [eu] "r"(GAP8_EU_BASE),
        [team] "i"(GAP8_EU_DISPATCH_TEAM - GAP8_EU_BASE),
        [bmask] "i"(GAP8_EU_BARRIER_MASK - GAP8_EU_BASE),
        [btarget] "i"(GAP8_EU_BARRIER_TARGET - GAP8_EU_BASE),
        [fifo] "i"(GAP8_EU_DISPATCH_FIFO - GAP8_EU_BASE),
        [bwait] "i"(GAP8_EU_BARRIER_WAIT - GAP8_EU_BASE)
      : "t0", "t1", "t2", "ra", "memory");
  record();
}

/* plp_dma_memcpy + plp_dma_wait (mchan_v6.h) of 1024 bytes L2 -> L1. */
static void dma_once(void) {
  const uint32_t cmd = 1024u | GAP8_DMA_CMD_EXT2LOC | GAP8_DMA_CMD_INCR | GAP8_DMA_CMD_EVENT |
                       GAP8_DMA_CMD_BROADCAST;
  begin();
  __asm__ volatile(
      "li t0, %[start]\n li t1, %[stop]\n li t4, %[evt]\n"
      "sw zero, 0(t0)\n"
      "lw t3, 0(%[dma])\n" /* counter */
      "sw %[cmd], 0(%[dma])\n sw %[loc], 0(%[dma])\n sw %[ext], 0(%[dma])\n"
      "li t2, 1\n sll t3, t2, t3\n" /* 1 << counter */
      "1: lw t2, 4(%[dma])\n and t2, t2, t3\n beqz t2, 2f\n"
      "sw t4, %[mor](%[eu])\n lw zero, %[wclr](%[eu])\n sw t4, %[mand](%[eu])\n j 1b\n"
      "2: sw t3, 4(%[dma])\n"
      "sw zero, 0(t1)\n"
      :
      : [start] "i"(GAP8_PERF_START), [stop] "i"(GAP8_PERF_STOP), [evt] "i"(1u << GAP8_EVT_DMA),
        [dma] "r"(GAP8_DMA_QUEUE), [cmd] "r"(cmd), [loc] "r"(l1_dst), [ext] "r"(l2_src),
        [eu] "r"(GAP8_EU_BASE), [mor] "i"(GAP8_EU_EVT_MASK_OR - GAP8_EU_BASE),
        [mand] "i"(GAP8_EU_EVT_MASK_AND - GAP8_EU_BASE),
        [wclr] "i"(GAP8_EU_EVT_WAIT_CLEAR - GAP8_EU_BASE)
      : "t0", "t1", "t2", "t3", "t4", "memory");
  record();
}

/* A 64-byte DMA L2 -> L1 pushed at t0+4 writes its first two words (banks of l1_dst[0] and
 * [4]) at t0+7; the core loads l1_dst[0] from t0+5 to t0+12, so one load meets the DMA. */
static void dma_bank_once(void) {
  const uint32_t cmd =
      64u | GAP8_DMA_CMD_EXT2LOC | GAP8_DMA_CMD_INCR | GAP8_DMA_CMD_EVENT | GAP8_DMA_CMD_BROADCAST;
  uint32_t counter;
  begin();
  __asm__ volatile(
      "li t0, %[start]\n li t1, %[stop]\n"
      "sw zero, 0(t0)\n"
      "lw %[counter], 0(%[dma])\n"
      "sw %[cmd], 0(%[dma])\n sw %[loc], 0(%[dma])\n sw %[ext], 0(%[dma])\n"
      ".rept 8\n lw t2, 0(%[loc])\n .endr\n"
      "sw zero, 0(t1)\n"
      : [counter] "=&r"(counter)
      : [start] "i"(GAP8_PERF_START), [stop] "i"(GAP8_PERF_STOP), [dma] "r"(GAP8_DMA_QUEUE),
        [cmd] "r"(cmd), [loc] "r"(l1_dst), [ext] "r"(l2_src)
      : "t0", "t1", "t2", "memory");
  record();
  __gap8_dma_wait(counter);
}

int main(void) {
  const uint32_t mask = (1u << pi_cl_cluster_nb_cores()) - 1u;
  /* Three passes: the workers' start-up code, running during the first, refills lines of the
   * same sets (random replacement), which the second may refill once more. */
  for (volatile int pass = 0; pass < 3; ++pass) {
    if (timing_mode == 0 && pass == 0) icache_cold();
    if (timing_mode == 1) fork_once(mask);
    if (timing_mode == 2) dma_once();
    if (timing_mode == 3) dma_bank_once();
  }
  return timing_mode > 3 ? 3 : 0;
}
