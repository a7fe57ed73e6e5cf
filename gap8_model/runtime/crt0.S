/* Start-up code: every core starts here. Each takes its stack from the top of L1 by core id;
 * core 0 clears .bss, runs main and ends the run with main's status; the other cores wait for
 * work from pi_cl_team_fork in __gap8_worker_loop. */
#include "gap8_regs.h"

  .section .text.start, "ax"
  .global _start
_start:
  .option push
  .option norelax
  la gp, __global_pointer$
  .option pop
  csrr a0, mhartid
  andi a0, a0, 0x1f
  lui t0, %hi(__stack_size)
  addi t0, t0, %lo(__stack_size)
  mul t1, a0, t0
  la sp, __stack_top
  sub sp, sp, t1
  bnez a0, 1f
  la a0, __bss_start
  la a1, __bss_end
  call __gap8_zero
  la a0, __l1_bss_start
  la a1, __l1_bss_end
  call __gap8_zero
  call main
  j __gap8_exit
1:
  j __gap8_worker_loop

/* Cores 1..N-1, as pulp-os's __rt_slave_start / __rt_wait_for_dispatch for GAP8 (gap_sdk
 * gap8/rtos/pulp/pulp-os/kernel/riscv/pe-eu-v3.S, with lw for p.elw): pop entry and arg from the
 * dispatch FIFO (sleeping while it is empty), run entry; an entry with bit 0 clear returns to
 * the barrier that closes a fork, then waits for the next dispatch. */
  .global __gap8_worker_loop
__gap8_worker_loop:
  li s2, GAP8_EU_BASE
  la s4, __gap8_fork_return
  la s5, __gap8_wait_for_dispatch
  j __gap8_wait_for_dispatch
__gap8_fork_return:
  lw t0, (GAP8_EU_BARRIER_WAIT - GAP8_EU_BASE)(s2)
__gap8_wait_for_dispatch:
  lw t0, (GAP8_EU_DISPATCH_FIFO - GAP8_EU_BASE)(s2)
  lw a0, (GAP8_EU_DISPATCH_FIFO - GAP8_EU_BASE)(s2)
  andi t1, t0, 1
  bne t1, zero, __gap8_other_entry
  add ra, s4, x0
  jr t0
__gap8_other_entry:
  add ra, s5, x0
  jr t0

/* Zeroes the words in [a0, a1). */
__gap8_zero:
  bgeu a0, a1, 2f
  sw zero, 0(a0)
  addi a0, a0, 4
  j __gap8_zero
2:
  ret

/* Ends the run with status a0 (the differential test stops here: it is the first peripheral
 * access of a finished program). */
  .global __gap8_exit
__gap8_exit:
  li t0, GAP8_CTRL_EXIT
  sw a0, 0(t0)
3:
  j 3b
