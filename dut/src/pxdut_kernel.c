/* The portable C99 kernel of SPEC §3-§4: the shared per-POI kernel (pxflow_spec/poi_kernel.h,
 * the PX4FLOW firmware's shape) with its portable steps and the 4-byte primitives in plain C
 * (pxdut_primitives.h), over SPEC §2's grid. */
#include "pxdut.h"
#include "pxdut_primitives.h"

#define PXFLOW_POI_CONTEXT pxdut_params
#include "pxflow_spec/poi_kernel.h"

static void clear_record(pxdut_record *rec) {
  uint8_t *bytes = (uint8_t *)rec;
  for (uint32_t i = 0; i < sizeof *rec; ++i) bytes[i] = 0;
}

void pxdut_kernel_portable(const pxdut_params *p, const uint8_t *prev, const uint8_t *next,
                           pxdut_record *out) {
  const pxflow_grid_axis ax = pxflow_grid_axis_of(p->width, p->search_radius, p->blocks);
  const pxflow_grid_axis ay = pxflow_grid_axis_of(p->height, p->search_radius, p->blocks);
  for (uint32_t j = 0; j < ay.count; ++j)
    for (uint32_t i = 0; i < ax.count; ++i) {
      pxdut_record *rec = &out[j * ax.count + i];
      clear_record(rec);
      pxflow_poi_kernel(p, prev, next, ax.first + i * ax.step, ay.first + j * ay.step, rec);
    }
}
