/* The freestanding spec core, all of it (spec/README.md): SPEC.md's record, parameter block,
 * codes, step table, limits, grid and frame estimate, once, in C99 that needs only <stdint.h>
 * and <stddef.h>, allocates nothing and compiles as C++ too. */
#ifndef PXFLOW_SPEC_H
#define PXFLOW_SPEC_H

#include "estimate.h"
#include "grid.h"
#include "params.h"
#include "record.h"

#endif
