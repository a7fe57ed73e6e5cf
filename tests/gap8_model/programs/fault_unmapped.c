/* Loads from an address that is neither L1, L2 nor a peripheral register. */
int main(void) { return *(volatile int *)0x30000000; }
