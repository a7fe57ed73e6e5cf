/* flow_poi.c with the fast variant's hooks (flow_kernel.h): each accepted POI goes into its
 * core's histograms, and each core ends with variant_finish. */
#define PXFLOW_GAP8_FAST_HOOKS 1
#include "flow_poi.c"
