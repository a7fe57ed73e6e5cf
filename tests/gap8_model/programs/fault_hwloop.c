/* A hardware loop whose last instruction is a branch, which the RI5CY manual forbids ("the last
 * instruction cannot be any jump or branch instruction"): the model stops with the fault. */
int main(void) {
  unsigned counter = 0;
  /* lp.setupi L0, 4 iterations, end = pc + 8: the body is addi ; bne (its last instruction) */
  __asm__ volatile(
      ".option push\n .option norvc\n"
      ".insn i 0x7B, 5, x0, x4, 4\n"
      "addi %0, %0, 1\n"
      "bne %0, x0, 1f\n"
      "1:\n"
      ".option pop\n"
      : "+r"(counter));
  return (int)counter;
}
