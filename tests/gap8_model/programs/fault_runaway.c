/* Never ends: the run must stop at the cycle budget. */
int main(void) {
  for (volatile int i = 0;; ++i) {
  }
}
