/* SPEC §4's per-POI record, its status and direction codes, and SPEC §3's half-pixel step
 * table: the one definition every freestanding kernel (dut/, kernels/cortex-m4, kernels/gap8)
 * includes. reference/ static_asserts its PoiRecord against this layout; the OpenCL, GLSL and
 * Python copies are checked against it by spec/spec_copies_check.py (ctest spec_copies). */
#ifndef PXFLOW_SPEC_RECORD_H
#define PXFLOW_SPEC_RECORD_H

#include <stddef.h>
#include <stdint.h>

/* C99 has no static_assert: a negative array size stops the build. */
#define PXFLOW_SPEC_ASSERT(name, cond) typedef char pxflow_spec_assert_##name[(cond) ? 1 : -1]

/* A record's status (SPEC §4). */
#define PXFLOW_STATUS_DROPPED 0u  /* feature < FT */
#define PXFLOW_STATUS_REJECTED 1u /* best integer SAD >= VT */
#define PXFLOW_STATUS_ACCEPTED 2u

/* Half-pixel directions 0..7 (SPEC §3's table) and the integer match, which wins the vote unless
 * a half step is strictly better; `dir` is PXFLOW_DIR_NONE whenever status < 2. */
#define PXFLOW_DIRECTIONS 8u
#define PXFLOW_DIR_NONE 8u

/* The half-pixel step (sx, sy) of direction k = 0..8, as initialisers so that each kernel keeps
 * its own array type (int8_t in C, int in OpenCL and GLSL copies). */
#define PXFLOW_STEP_X_TABLE \
  { 1, 1, 0, -1, -1, -1, 0, 1, 0 }
#define PXFLOW_STEP_Y_TABLE \
  { 0, 1, 1, 1, 0, -1, -1, -1, 0 }

/* Bytes of one record: in memory, on the wire (little-endian) and in `pxflow vectors`. */
#define PXFLOW_RECORD_BYTES 32u

/* The fields of SPEC §4 in order at natural alignment, with two explicit zero pad bytes, so that
 * undefined fields and padding are 0 and records compare with memcmp. */
typedef struct {
  uint16_t x, y;        /* POI top-left corner */
  uint8_t status, pad0; /* PXFLOW_STATUS_*; pad0 = 0 */
  uint16_t feature;
  int8_t dx, dy; /* integer displacement (bx, by) */
  uint16_t sad;  /* best integer SAD */
  uint8_t dir, pad1;
  uint16_t sub[PXFLOW_DIRECTIONS]; /* the eight half-pixel SADs */
  int8_t hx, hy;                   /* half-pixel displacement */
} pxflow_poi_record;

/* Byte offsets of the fields in memory and on the wire (the layout above, spelled for codecs
 * that write field by field and for the C++ static_asserts). */
#define PXFLOW_RECORD_AT_X 0u
#define PXFLOW_RECORD_AT_Y 2u
#define PXFLOW_RECORD_AT_STATUS 4u
#define PXFLOW_RECORD_AT_FEATURE 6u
#define PXFLOW_RECORD_AT_DX 8u
#define PXFLOW_RECORD_AT_DY 9u
#define PXFLOW_RECORD_AT_SAD 10u
#define PXFLOW_RECORD_AT_DIR 12u
#define PXFLOW_RECORD_AT_SUB 14u
#define PXFLOW_RECORD_AT_HX 30u
#define PXFLOW_RECORD_AT_HY 31u
PXFLOW_SPEC_ASSERT(record_bytes, sizeof(pxflow_poi_record) == PXFLOW_RECORD_BYTES);
PXFLOW_SPEC_ASSERT(record_feature,
                   offsetof(pxflow_poi_record, feature) == PXFLOW_RECORD_AT_FEATURE);
PXFLOW_SPEC_ASSERT(record_sad, offsetof(pxflow_poi_record, sad) == PXFLOW_RECORD_AT_SAD);
PXFLOW_SPEC_ASSERT(record_dir, offsetof(pxflow_poi_record, dir) == PXFLOW_RECORD_AT_DIR);
PXFLOW_SPEC_ASSERT(record_sub, offsetof(pxflow_poi_record, sub) == PXFLOW_RECORD_AT_SUB);
PXFLOW_SPEC_ASSERT(record_hy, offsetof(pxflow_poi_record, hy) == PXFLOW_RECORD_AT_HY);

static inline void pxflow_put_u16(uint8_t *b, uint16_t v) {
  b[0] = (uint8_t)v;
  b[1] = (uint8_t)(v >> 8);
}

static inline uint16_t pxflow_get_u16(const uint8_t *b) {
  return (uint16_t)(b[0] | (uint16_t)(b[1] << 8));
}

/* The record as SPEC §4's 32 little-endian bytes, whatever the byte order of this core (the pad
 * bytes are written as 0). */
static inline void pxflow_record_to_bytes(const pxflow_poi_record *r, uint8_t *b) {
  pxflow_put_u16(b + PXFLOW_RECORD_AT_X, r->x);
  pxflow_put_u16(b + PXFLOW_RECORD_AT_Y, r->y);
  b[PXFLOW_RECORD_AT_STATUS] = r->status;
  b[PXFLOW_RECORD_AT_STATUS + 1] = 0;
  pxflow_put_u16(b + PXFLOW_RECORD_AT_FEATURE, r->feature);
  b[PXFLOW_RECORD_AT_DX] = (uint8_t)r->dx;
  b[PXFLOW_RECORD_AT_DY] = (uint8_t)r->dy;
  pxflow_put_u16(b + PXFLOW_RECORD_AT_SAD, r->sad);
  b[PXFLOW_RECORD_AT_DIR] = r->dir;
  b[PXFLOW_RECORD_AT_DIR + 1] = 0;
  for (uint32_t k = 0; k < PXFLOW_DIRECTIONS; ++k)
    pxflow_put_u16(b + PXFLOW_RECORD_AT_SUB + 2 * k, r->sub[k]);
  b[PXFLOW_RECORD_AT_HX] = (uint8_t)r->hx;
  b[PXFLOW_RECORD_AT_HY] = (uint8_t)r->hy;
}

/* The inverse, keeping the pad bytes as they came (a host compares them too). */
static inline void pxflow_record_from_bytes(const uint8_t *b, pxflow_poi_record *r) {
  r->x = pxflow_get_u16(b + PXFLOW_RECORD_AT_X);
  r->y = pxflow_get_u16(b + PXFLOW_RECORD_AT_Y);
  r->status = b[PXFLOW_RECORD_AT_STATUS];
  r->pad0 = b[PXFLOW_RECORD_AT_STATUS + 1];
  r->feature = pxflow_get_u16(b + PXFLOW_RECORD_AT_FEATURE);
  r->dx = (int8_t)b[PXFLOW_RECORD_AT_DX];
  r->dy = (int8_t)b[PXFLOW_RECORD_AT_DY];
  r->sad = pxflow_get_u16(b + PXFLOW_RECORD_AT_SAD);
  r->dir = b[PXFLOW_RECORD_AT_DIR];
  r->pad1 = b[PXFLOW_RECORD_AT_DIR + 1];
  for (uint32_t k = 0; k < PXFLOW_DIRECTIONS; ++k)
    r->sub[k] = pxflow_get_u16(b + PXFLOW_RECORD_AT_SUB + 2 * k);
  r->hx = (int8_t)b[PXFLOW_RECORD_AT_HX];
  r->hy = (int8_t)b[PXFLOW_RECORD_AT_HY];
}

#endif
