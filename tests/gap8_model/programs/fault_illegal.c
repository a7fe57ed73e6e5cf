/* Executes an all-zero half-word: an illegal instruction in RISC-V. */
int main(void) {
  __asm__ volatile(".2byte 0");
  return 0;
}
