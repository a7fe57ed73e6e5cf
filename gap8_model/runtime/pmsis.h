/* A PMSIS-compatible subset for programs run on the GAP8 cluster model: code written against
 * GAP8's SDK for these calls compiles unchanged. Implemented on the model's own peripheral
 * registers (gap8_regs.h); main() runs on cluster core 0, the other cores wait for forks. */
#ifndef GAP8_PMSIS_H
#define GAP8_PMSIS_H

#include <stddef.h>
#include <stdint.h>

#include "gap8_regs.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PI_L1 __attribute__((section(".data_l1")))
#define PI_CL_L1 PI_L1
#define PI_L1_BSS __attribute__((section(".bss_l1")))

static inline uint32_t __gap8_read(uint32_t addr) { return *(volatile uint32_t *)addr; }
static inline void __gap8_write(uint32_t addr, uint32_t v) { *(volatile uint32_t *)addr = v; }

/* ---- cores and teams ---- */
static inline int pi_core_id(void) {
  int id;
  __asm__ volatile("csrr %0, mhartid" : "=r"(id));
  return id & 0x1f;
}
static inline int pi_cluster_id(void) { return 0; }
static inline int pi_cl_cluster_nb_cores(void) { return (int)__gap8_read(GAP8_CTRL_NUM_CORES); }
/* pulp-os reads the barrier's trigger mask and takes __FL1(mask + 1) (a load, p.fl1, addi); the
 * model's TEAM_SIZE register gives the count in one load. */
static inline int pi_cl_team_nb_cores(void) { return (int)__gap8_read(GAP8_EU_TEAM_SIZE); }
/* pulp-os __rt_team_barrier: one p.elw on the barrier's trigger-wait-clear register. */
static inline void pi_cl_team_barrier(void) { (void)__gap8_read(GAP8_EU_BARRIER_WAIT); }

/* Runs entry(arg) on cores 0..nb_cores-1 (0: the team of the previous fork) and returns when all
 * have finished. The instruction sequence of pulp-os's rt_team_fork for GAP8 (gap_sdk
 * gap8/rtos/pulp/pulp-os/include/rt/rt_pe.h, no cluster controller): configure the dispatch
 * team and the barrier, push entry and arg to the dispatch FIFO, run entry on core 0, wait at
 * the barrier. The workers' side is __gap8_worker_loop in crt0.S. */
static inline void pi_cl_team_fork(int nb_cores, void (*entry)(void *), void *arg) {
  if (nb_cores) {
    const uint32_t mask = (1u << (uint32_t)nb_cores) - 1u;
    __gap8_write(GAP8_EU_DISPATCH_TEAM, mask);
    __gap8_write(GAP8_EU_BARRIER_MASK, mask);
    __gap8_write(GAP8_EU_BARRIER_TARGET, mask);
  }
  __gap8_write(GAP8_EU_DISPATCH_FIFO, (uint32_t)entry);
  __gap8_write(GAP8_EU_DISPATCH_FIFO, (uint32_t)arg);
  entry(arg);
  pi_cl_team_barrier();
}

/* ---- cluster DMA (pulp-os rt_dma.h over the mchan v6 HAL) ---- */
typedef enum { PI_CL_DMA_DIR_LOC2EXT = 0, PI_CL_DMA_DIR_EXT2LOC = 1 } pi_cl_dma_dir_e;

typedef struct pi_cl_dma_copy_s {
  uint32_t ext;
  uint32_t loc;
  uint32_t id;
  uint32_t size;
  pi_cl_dma_dir_e dir;
  uint8_t merge;
  uint32_t stride; /* 2-D only */
  uint32_t length; /* 2-D only */
  struct pi_cl_dma_copy_s *next;
} pi_cl_dma_copy_t;
typedef pi_cl_dma_copy_t pi_cl_dma_copy_2d_t;
typedef struct {
  uint32_t id;
} pi_cl_dma_cmd_t;

/* plp_dma_counter_alloc, plp_dma_getCmd (event, broadcast), plp_dma_cmd_push(_2d). */
static inline uint32_t __gap8_dma_push(uint32_t ext, uint32_t loc, uint32_t size, uint32_t dir,
                                       uint32_t stride, uint32_t length, int is_2d) {
  const uint32_t counter = __gap8_read(GAP8_DMA_QUEUE);
  if (size > GAP8_DMA_CMD_SIZE_MASK) size = 0; /* does not fit the 16-bit field: refused */
  const uint32_t cmd = (size & GAP8_DMA_CMD_SIZE_MASK) | (dir ? GAP8_DMA_CMD_EXT2LOC : 0u) |
                       GAP8_DMA_CMD_INCR | (is_2d ? GAP8_DMA_CMD_2D : 0u) | GAP8_DMA_CMD_EVENT |
                       GAP8_DMA_CMD_BROADCAST;
  __gap8_write(GAP8_DMA_QUEUE, cmd);
  __gap8_write(GAP8_DMA_QUEUE, loc);
  __gap8_write(GAP8_DMA_QUEUE, ext);
  if (is_2d) __gap8_write(GAP8_DMA_QUEUE, (stride << 16) | length);
  return counter;
}
/* plp_dma_wait: while the counter is busy, wait for the DMA event (eu_evt_maskWaitAndClr), then
 * free the counter. */
static inline void __gap8_dma_wait(uint32_t counter) {
  while (__gap8_read(GAP8_DMA_STATUS) & (1u << counter)) {
    __gap8_write(GAP8_EU_EVT_MASK_OR, 1u << GAP8_EVT_DMA);
    (void)__gap8_read(GAP8_EU_EVT_WAIT_CLEAR);
    __gap8_write(GAP8_EU_EVT_MASK_AND, 1u << GAP8_EVT_DMA);
  }
  __gap8_write(GAP8_DMA_STATUS, 1u << counter);
}
static inline void pi_cl_dma_memcpy(pi_cl_dma_copy_t *copy) {
  copy->id = __gap8_dma_push(copy->ext, copy->loc, copy->size, copy->dir, 0, 0, 0);
}
static inline void pi_cl_dma_memcpy_2d(pi_cl_dma_copy_2d_t *copy) {
  copy->id =
      __gap8_dma_push(copy->ext, copy->loc, copy->size, copy->dir, copy->stride, copy->length, 1);
}
static inline void pi_cl_dma_wait(void *copy) { __gap8_dma_wait(((pi_cl_dma_copy_t *)copy)->id); }
static inline void pi_cl_dma_cmd(uint32_t ext, uint32_t loc, uint32_t size, pi_cl_dma_dir_e dir,
                                 pi_cl_dma_cmd_t *cmd) {
  cmd->id = __gap8_dma_push(ext, loc, size, dir, 0, 0, 0);
}
static inline void pi_cl_dma_cmd_2d(uint32_t ext, uint32_t loc, uint32_t size, uint32_t stride,
                                    uint32_t length, pi_cl_dma_dir_e dir, pi_cl_dma_cmd_t *cmd) {
  cmd->id = __gap8_dma_push(ext, loc, size, dir, stride, length, 1);
}
static inline void pi_cl_dma_cmd_wait(pi_cl_dma_cmd_t *cmd) { __gap8_dma_wait(cmd->id); }

/* ---- L1 allocation (a bump allocator between the PI_L1 data and the stacks) ---- */
struct pi_device;
void *pi_cl_l1_malloc(struct pi_device *device, uint32_t size);
void pi_cl_l1_free(struct pi_device *device, void *chunk, uint32_t size);

/* ---- performance counters (pi_perf_event_e numbering of PMSIS for GAP8) ---- */
typedef enum {
  PI_PERF_CYCLES = GAP8_EVT_CYCLES,
  PI_PERF_ACTIVE_CYCLES = GAP8_EVT_ACTIVE_CYCLES,
  PI_PERF_INSTR = GAP8_EVT_INSTR,
  PI_PERF_LD_STALL = GAP8_EVT_LD_STALL,
  PI_PERF_JR_STALL = GAP8_EVT_JR_STALL,
  PI_PERF_IMISS = GAP8_EVT_IMISS,
  PI_PERF_LD = GAP8_EVT_LD,
  PI_PERF_ST = GAP8_EVT_ST,
  PI_PERF_JUMP = GAP8_EVT_JUMP,
  PI_PERF_BRANCH = GAP8_EVT_BRANCH,
  PI_PERF_BTAKEN = GAP8_EVT_BTAKEN,
  PI_PERF_RVC = GAP8_EVT_RVC,
  PI_PERF_LD_EXT = GAP8_EVT_LD_EXT,
  PI_PERF_ST_EXT = GAP8_EVT_ST_EXT,
  PI_PERF_LD_EXT_CYC = GAP8_EVT_LD_EXT_CYC,
  PI_PERF_ST_EXT_CYC = GAP8_EVT_ST_EXT_CYC,
  PI_PERF_TCDM_CONT = GAP8_EVT_TCDM_CONT,
} pi_perf_event_e;

static inline void pi_perf_conf(unsigned events) { __gap8_write(GAP8_PERF_CONF, events); }
static inline void pi_perf_reset(void) { __gap8_write(GAP8_PERF_RESET, 0); }
static inline void pi_perf_start(void) { __gap8_write(GAP8_PERF_START, 0); }
static inline void pi_perf_stop(void) { __gap8_write(GAP8_PERF_STOP, 0); }
static inline unsigned int pi_perf_read(int id) { return __gap8_read(GAP8_PERF_VALUE(id)); }

/* ---- output (not PMSIS: the model's console) ---- */
void gap8_putc(char c);
void gap8_puts(const char *s);
int printf(const char *fmt, ...);

#ifdef __cplusplus
}
#endif

#endif
