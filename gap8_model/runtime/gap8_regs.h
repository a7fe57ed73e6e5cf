/* The simulated GAP8 cluster's memory map: one source of truth, included by the C++ model and by
 * the RISC-V programs' runtime. Memory bases and sizes are GAP8's; the peripheral register layout
 * under GAP8_PERIPH_BASE is this model's own (GAP8's real registers are not reproduced). */
#ifndef GAP8_REGS_H
#define GAP8_REGS_H

#define GAP8_L1_BASE 0x10000000u
#define GAP8_L1_SIZE 0x00010000u /* 64 KiB shared TCDM */
#define GAP8_L1_BANKS 16u        /* word-interleaved: bank = (addr >> 2) & 15 */
#define GAP8_L2_BASE 0x1C000000u
#define GAP8_L2_SIZE 0x00080000u /* 512 KiB */
#define GAP8_MAX_CORES 8u

#define GAP8_PERIPH_BASE 0x10200000u
#define GAP8_PERIPH_SIZE 0x00001000u

/* Control block. */
#define GAP8_CTRL_EXIT (GAP8_PERIPH_BASE + 0x000u)      /* W: end the run with this status */
#define GAP8_CTRL_PUTC (GAP8_PERIPH_BASE + 0x004u)      /* W: one byte to the host's stdout */
#define GAP8_CTRL_NUM_CORES (GAP8_PERIPH_BASE + 0x008u) /* R: cores in this run */
#define GAP8_CTRL_CORE_ID (GAP8_PERIPH_BASE + 0x00Cu)   /* R: id of the reading core */

/* Event unit: team fork and barrier. */
#define GAP8_EU_TEAM_SIZE (GAP8_PERIPH_BASE + 0x100u)  /* W: cores in the next team; R: team */
#define GAP8_EU_FORK_ARG (GAP8_PERIPH_BASE + 0x104u)   /* W: argument for the next dispatch */
#define GAP8_EU_FORK_ENTRY (GAP8_PERIPH_BASE + 0x108u) /* W: entry; dispatches to cores 1..team-1 \
                                                        */
#define GAP8_EU_WAIT_ENTRY (GAP8_PERIPH_BASE + 0x10Cu) /* R: sleeps until dispatched; the entry */
#define GAP8_EU_WAIT_ARG (GAP8_PERIPH_BASE + 0x110u)   /* R: the argument of that dispatch */
#define GAP8_EU_BARRIER (GAP8_PERIPH_BASE + 0x114u)    /* R: sleeps until the whole team arrived */

/* Cluster DMA: fill the fields, read PUSH to enqueue (returns the transfer id), write the id to
 * WAIT to sleep until that transfer is complete. */
#define GAP8_DMA_EXT (GAP8_PERIPH_BASE + 0x200u)    /* L2 address */
#define GAP8_DMA_LOC (GAP8_PERIPH_BASE + 0x204u)    /* L1 address */
#define GAP8_DMA_SIZE (GAP8_PERIPH_BASE + 0x208u)   /* total bytes */
#define GAP8_DMA_DIR (GAP8_PERIPH_BASE + 0x20Cu)    /* 0: L1 -> L2, 1: L2 -> L1 (PMSIS's values) */
#define GAP8_DMA_STRIDE (GAP8_PERIPH_BASE + 0x210u) /* 2-D: L2 bytes between row starts */
#define GAP8_DMA_LENGTH (GAP8_PERIPH_BASE + 0x214u) /* 2-D: bytes per row; 0 means 1-D */
#define GAP8_DMA_PUSH (GAP8_PERIPH_BASE + 0x218u)   /* R: enqueue, returns the id */
#define GAP8_DMA_WAIT (GAP8_PERIPH_BASE + 0x21Cu)   /* W: id; sleeps until it is done */

/* Performance counters, private to the accessing core. */
#define GAP8_PERF_CONF (GAP8_PERIPH_BASE + 0x300u)  /* W: mask of events (1 << event id) */
#define GAP8_PERF_RESET (GAP8_PERIPH_BASE + 0x304u) /* W: zero all counters */
#define GAP8_PERF_START (GAP8_PERIPH_BASE + 0x308u) /* W: start counting */
#define GAP8_PERF_STOP (GAP8_PERIPH_BASE + 0x30Cu)  /* W: stop counting */
#define GAP8_PERF_VALUE(event) (GAP8_PERIPH_BASE + 0x380u + 4u * (event)) /* R: one counter */

/* Event ids: PMSIS's pi_perf_event_e numbering for GAP8. */
#define GAP8_EVT_ACTIVE_CYCLES 0
#define GAP8_EVT_INSTR 1
#define GAP8_EVT_LD_STALL 2
#define GAP8_EVT_JR_STALL 3
#define GAP8_EVT_IMISS 4
#define GAP8_EVT_LD 5
#define GAP8_EVT_ST 6
#define GAP8_EVT_JUMP 7
#define GAP8_EVT_BRANCH 8
#define GAP8_EVT_BTAKEN 9
#define GAP8_EVT_RVC 10
#define GAP8_EVT_LD_EXT 11
#define GAP8_EVT_ST_EXT 12
#define GAP8_EVT_LD_EXT_CYC 13
#define GAP8_EVT_ST_EXT_CYC 14
#define GAP8_EVT_TCDM_CONT 15
#define GAP8_EVT_CYCLES 17
#define GAP8_EVT_COUNT 18

#endif
