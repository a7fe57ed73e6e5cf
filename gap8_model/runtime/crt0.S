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
