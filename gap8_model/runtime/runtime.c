/* The runtime's C part: the L1 allocator, a small printf and the
 * few libc functions GCC may call on its own (memcpy, memset, memmove, memcmp). */
#include <stdarg.h>

#include "pmsis.h"

extern char __l1_heap_start[], __l1_heap_end[];

static char *l1_next = __l1_heap_start;

void *pi_cl_l1_malloc(struct pi_device *device, uint32_t size) {
  (void)device;
  size = (size + 7u) & ~7u;
  if (size > (uint32_t)(__l1_heap_end - l1_next)) return NULL;
  void *chunk = l1_next;
  l1_next += size;
  return chunk;
}

/* Only the most recent allocation can be given back (a stack discipline, enough for kernels). */
void pi_cl_l1_free(struct pi_device *device, void *chunk, uint32_t size) {
  (void)device;
  size = (size + 7u) & ~7u;
  if ((char *)chunk + size == l1_next) l1_next = (char *)chunk;
}

void *memcpy(void *dst, const void *src, size_t n) {
  unsigned char *d = dst;
  const unsigned char *s = src;
  while (n--) *d++ = *s++;
  return dst;
}

void *memmove(void *dst, const void *src, size_t n) {
  unsigned char *d = dst;
  const unsigned char *s = src;
  if (d < s) return memcpy(dst, src, n);
  while (n--) d[n] = s[n];
  return dst;
}

void *memset(void *dst, int c, size_t n) {
  unsigned char *d = dst;
  while (n--) *d++ = (unsigned char)c;
  return dst;
}

int memcmp(const void *a, const void *b, size_t n) {
  const unsigned char *x = a, *y = b;
  for (; n--; ++x, ++y) {
    if (*x != *y) return *x - *y;
  }
  return 0;
}

void gap8_putc(char c) { __gap8_write(GAP8_CTRL_PUTC, (uint32_t)(unsigned char)c); }

void gap8_puts(const char *s) {
  while (*s) gap8_putc(*s++);
}

static void put_unsigned(uint32_t v, uint32_t base) {
  char digits[11];
  int n = 0;
  do {
    digits[n++] = "0123456789abcdef"[v % base];
    v /= base;
  } while (v);
  while (n) gap8_putc(digits[--n]);
}

/* %d %u %x %s %c %% only: enough for test output and cycle counts. */
int printf(const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  for (; *fmt; ++fmt) {
    if (*fmt != '%') {
      gap8_putc(*fmt);
      continue;
    }
    switch (*++fmt) {
      case 'd': {
        int v = va_arg(ap, int);
        if (v < 0) gap8_putc('-');
        put_unsigned(v < 0 ? 0u - (uint32_t)v : (uint32_t)v, 10);
        break;
      }
      case 'u':
        put_unsigned(va_arg(ap, uint32_t), 10);
        break;
      case 'x':
        put_unsigned(va_arg(ap, uint32_t), 16);
        break;
      case 's':
        gap8_puts(va_arg(ap, const char *));
        break;
      case 'c':
        gap8_putc((char)va_arg(ap, int));
        break;
      case '%':
        gap8_putc('%');
        break;
      default:
        va_end(ap);
        return -1;
    }
  }
  va_end(ap);
  return 0;
}
