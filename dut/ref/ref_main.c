/* pxflow-dut-ref: the reference device. The dut/ engine and portable kernel, built for the host,
 * with the hooks on stdin/stdout (or --tcp PORT, --pty; ref_link.h). Its counter is the host's
 * CLOCK_MONOTONIC in nanoseconds, so its clock is named for that, not "dut-cycles". */
#include <stdio.h>

#include "pxdut.h"
#include "ref_link.h"

#ifndef PXDUT_REF_NAME /* a test device sets its own (tests/dut: the smallest packet size) */
#define PXDUT_REF_NAME "pxdut-portable-c"
#endif
#ifndef PXDUT_REF_CLOCK
#define PXDUT_REF_CLOCK "dut-ref-monotonic-ns"
#endif

int pxdut_port_read(uint8_t *buf, int max) { return ref_link_read(buf, max); }
int pxdut_port_write(const uint8_t *buf, int len) { return ref_link_write(buf, len); }
uint32_t pxdut_port_cycles(void) { return ref_link_nanoseconds(); }
uint32_t pxdut_port_cycles_hz(void) { return 1000000000u; }
void pxdut_port_kernel(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                       pxdut_record *out) {
  pxdut_kernel_portable(p, prev, next, out);
}

int main(int argc, char **argv) {
  argc = ref_link_open(argc, argv);
  if (argc < 0) return 2;
  if (argc > 1) {
    fprintf(stderr,
            "usage: pxflow-dut-ref [--tcp PORT | --pty]\n"
            "  the pxflow reference device (docs/dut-protocol.md): stdin/stdout by default\n");
    return 2;
  }
  static const pxdut_device dev = {PXDUT_REF_NAME, PXDUT_BUILD_ID, PXDUT_REF_CLOCK};
  pxdut_serve(&dev);
  return 0;
}
