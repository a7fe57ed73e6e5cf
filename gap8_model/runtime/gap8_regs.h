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

/* Event unit, with the semantics of GAP8's eu_v3 as GVSOC models it (gap_sdk
 * gvsoc/gvsoc_gap/models/pulp/event_unit/eu_v3_impl.cpp): one dispatch FIFO, one barrier, and
 * per core an event mask and status for the DMA event. Addresses are this model's. Reads that
 * wait (BARRIER_WAIT, DISPATCH_FIFO when empty, EVT_WAIT_CLEAR) put the core to sleep. */
#define GAP8_EU_BASE (GAP8_PERIPH_BASE + 0x100u)
#define GAP8_EU_DISPATCH_TEAM (GAP8_EU_BASE + 0x00u)  /* W: cores receiving the next pushes */
#define GAP8_EU_DISPATCH_FIFO (GAP8_EU_BASE + 0x04u)  /* W: push to the team; R: pop or sleep */
#define GAP8_EU_BARRIER_MASK (GAP8_EU_BASE + 0x08u)   /* W: cores that must arrive; R: it */
#define GAP8_EU_BARRIER_TARGET (GAP8_EU_BASE + 0x0Cu) /* W: cores woken when it completes */
#define GAP8_EU_BARRIER_WAIT (GAP8_EU_BASE + 0x10u)   /* R: arrive, sleep until all arrived */
#define GAP8_EU_TEAM_SIZE (GAP8_EU_BASE + 0x14u)      /* R: cores in the barrier mask */
#define GAP8_EU_EVT_MASK_OR (GAP8_EU_BASE + 0x18u)    /* W: enable events (bit per event) */
#define GAP8_EU_EVT_MASK_AND (GAP8_EU_BASE + 0x1Cu)   /* W: disable events */
#define GAP8_EU_EVT_WAIT_CLEAR (GAP8_EU_BASE + 0x20u) /* R: sleep until an enabled event; clear */
#define GAP8_EVT_DMA 8u /* GAP8's ARCHI_CL_EVT_DMA0 (gap8_revc.json: pe irq 8 is dma_0) */

/* Cluster DMA, mchan v6 as PMSIS drives it (gap_sdk gap8/rtos/pulp/hal_pulp/include/hal/dma/
 * mchan_v6.h): read QUEUE to allocate a counter, write the command words to QUEUE (command,
 * L1 address, L2 address, and for 2-D stride << 16 | length), read STATUS for the counters with
 * transfers in flight (bits 0..15), write a counter mask to STATUS to free them. */
#define GAP8_DMA_QUEUE (GAP8_PERIPH_BASE + 0x200u)
#define GAP8_DMA_STATUS (GAP8_PERIPH_BASE + 0x204u)
#define GAP8_DMA_COUNTERS 16u
#define GAP8_DMA_CMD_SIZE_MASK 0xFFFFu    /* bytes, 16 bits */
#define GAP8_DMA_CMD_EXT2LOC (1u << 16)   /* PLP_DMA_TYPE_BIT: 1 = L2 -> L1 */
#define GAP8_DMA_CMD_INCR (1u << 17)      /* PLP_DMA_INCR_BIT */
#define GAP8_DMA_CMD_2D (1u << 18)        /* PLP_DMA_2D_BIT */
#define GAP8_DMA_CMD_EVENT (1u << 19)     /* PLP_DMA_ELE_BIT: raise the DMA event */
#define GAP8_DMA_CMD_BROADCAST (1u << 21) /* PLP_DMA_BLE_BIT: to every core */
#define GAP8_DMA_2D_FIELD_MASK 0x7FFFu    /* stride and length: 15 bits each */

/* Performance counters, private to the accessing core. */
#define GAP8_PERF_CONF (GAP8_PERIPH_BASE + 0x300u)  /* W: mask of events (1 << event id) */
#define GAP8_PERF_RESET (GAP8_PERIPH_BASE + 0x304u) /* W: zero all counters */
#define GAP8_PERF_START (GAP8_PERIPH_BASE + 0x308u) /* W: start counting */
#define GAP8_PERF_STOP (GAP8_PERIPH_BASE + 0x30Cu)  /* W: stop counting */
#define GAP8_PERF_VALUE(event) (GAP8_PERIPH_BASE + 0x380u + 4u * (event)) /* R: one counter */

/* Event ids: PMSIS's pi_perf_event_e numbering for GAP8 (gap_sdk
 * rtos/pmsis/pmsis_api/include/pmsis/chips/gap8/perf.h: CYCLES is 16, the others 0..15). */
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
#define GAP8_EVT_CYCLES 16
#define GAP8_EVT_COUNT 17

#endif
