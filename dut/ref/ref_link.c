/* The links of the host-side devices (ref_link.h). */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "ref_link.h"

#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

static int in_fd = 0, out_fd = 1;

static int listen_tcp(const char *port_text) {
  char *end = NULL;
  const long port = strtol(port_text, &end, 10);
  if (!*port_text || *end || port < 0 || port > 65535) {
    fprintf(stderr, "pxflow-dut-ref: --tcp %s: not a port number (0 .. 65535)\n", port_text);
    return -1;
  }
  const int s = socket(AF_INET, SOCK_STREAM, 0);
  struct sockaddr_in a;
  memset(&a, 0, sizeof a);
  a.sin_family = AF_INET;
  a.sin_port = htons((unsigned short)port);
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const int one = 1;
  setsockopt(s, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  socklen_t len = sizeof a;
  if (s < 0 || bind(s, (struct sockaddr *)&a, sizeof a) != 0 || listen(s, 1) != 0 ||
      getsockname(s, (struct sockaddr *)&a, &len) != 0) {
    fprintf(stderr, "pxflow-dut-ref: --tcp %s: %s\n", port_text, strerror(errno));
    return -1;
  }
  printf("%u\n", (unsigned)ntohs(a.sin_port)); /* the test reads the port chosen for 0 */
  fflush(stdout);
  const int c = accept(s, NULL, NULL);
  close(s);
  if (c < 0) return -1;
  in_fd = out_fd = c;
  return 0;
}

static int open_pty(void) {
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) {
    fprintf(stderr, "pxflow-dut-ref: --pty: %s\n", strerror(errno));
    return -1;
  }
  const char *slave_path = ptsname(master);
  /* Keep the slave open ourselves: the master then never reads a hang-up between two users,
   * and the slave starts raw, before the host sets its own termios. */
  const int slave = open(slave_path, O_RDWR | O_NOCTTY);
  struct termios t;
  if (slave < 0 || tcgetattr(slave, &t) != 0) return -1;
  cfmakeraw(&t);
  tcsetattr(slave, TCSANOW, &t);
  printf("%s\n", slave_path);
  fflush(stdout);
  in_fd = out_fd = master;
  return 0;
}

int ref_link_open(int argc, char **argv) {
  signal(SIGPIPE, SIG_IGN); /* a closed link is a write error, not a signal */
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--tcp") == 0 && i + 1 < argc) {
      if (listen_tcp(argv[++i]) != 0) return -1;
    } else if (strcmp(argv[i], "--pty") == 0) {
      if (open_pty() != 0) return -1;
    } else {
      argv[out++] = argv[i];
    }
  }
  return out;
}

int ref_link_read(unsigned char *buf, int max) {
  for (;;) {
    const ssize_t n = read(in_fd, buf, (size_t)max);
    if (n > 0) return (int)n;
    if (n < 0 && errno == EINTR) continue;
    return -1; /* end of stream or error: the host went away */
  }
}

int ref_link_write(const unsigned char *buf, int len) {
  while (len > 0) {
    const ssize_t n = write(out_fd, buf, (size_t)len);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return -1;
    buf += n;
    len -= (int)n;
  }
  return 0;
}

unsigned ref_link_nanoseconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (unsigned)((unsigned long long)ts.tv_sec * 1000000000ull + (unsigned long long)ts.tv_nsec);
}
