/* Linked at 0x20000000 (its segment, headers included, starts at 0x1ffff000), outside L1 and
 * L2: the loader must refuse it. */
  .text
  .global _start
_start:
  j _start
