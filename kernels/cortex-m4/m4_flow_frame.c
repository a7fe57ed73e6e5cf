/* One pair's records in grid order: SPEC §2's grid (the spec core's), SPEC §3 per POI. */
#include "m4_flow.h"

void m4_flow_frame(const pxflow_param_block *p, const uint8_t *prev, const uint8_t *next,
                   pxflow_poi_record *records) {
  const pxflow_grid_axis ax = pxflow_grid_axis_of(p->width, p->search_radius, p->blocks);
  const pxflow_grid_axis ay = pxflow_grid_axis_of(p->height, p->search_radius, p->blocks);
  for (uint32_t j = 0; j < ay.count; ++j)   /* rows outer, */
    for (uint32_t i = 0; i < ax.count; ++i) /* columns inner: the record index is grid order */
      m4_flow_poi(p, prev, next, ax.first + i * ax.step, ay.first + j * ay.step, records++);
}
