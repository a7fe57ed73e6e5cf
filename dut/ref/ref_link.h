/* The link of the host-side devices (the reference device, the test devices): stdin/stdout, a
 * loopback TCP port or a pseudo-terminal, chosen on the command line. POSIX; not part of the
 * freestanding library. */
#ifndef PXDUT_REF_LINK_H
#define PXDUT_REF_LINK_H

/* Parses the link options of argv (--tcp PORT, --pty; nothing: stdin/stdout), sets the link up
 * and prints the TCP port or the pty's path on stdout when one was asked for. Removes the
 * options it used from argv and returns the new argc, or -1 after printing an error. */
int ref_link_open(int argc, char **argv);

/* The raw link, for the hooks. */
int ref_link_read(unsigned char *buf, int max);
int ref_link_write(const unsigned char *buf, int len);
unsigned ref_link_nanoseconds(void);

#endif
