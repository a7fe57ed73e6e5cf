/* flow_main.c with the fast variant's hooks (flow_kernel.h): its estimate is fast_serial.c's. */
#define PXFLOW_GAP8_FAST_HOOKS 1
#include "flow_main.c"
