/* SPEC §2's POI count and §5's frame estimate as the device's library exports them: the spec
 * core's (spec/include/pxflow_spec), compiled here once. Built with -ffp-contract=off: each float
 * operation rounds once, in the order written, so the bits are the host's (reference/estimate.cpp
 * does the same operations in the same order). */
#include "pxdut.h"

uint32_t pxdut_poi_count(const pxdut_params *p) { return pxflow_poi_count(p); }

void pxdut_estimate_flow(const pxdut_record *records, uint32_t pois, const pxdut_params *p,
                         pxdut_estimate *out) {
  pxflow_estimate_flow(records, pois, p, pxflow_window_mean_float, out);
}
