// PXFLOW_CPU_ISA_IF_<arch>(yes, no): `yes` where this compiler builds the kernels of isas.def's
// `arch` column (any, x86_64, aarch64), `no` elsewhere. The X-macro readers of isas.def use it
// so that a row of another architecture declares no accessor and compiles no feature test.
#pragma once

#define PXFLOW_CPU_ISA_IF_any(yes, no) yes

#if defined(__x86_64__)
#define PXFLOW_CPU_ISA_IF_x86_64(yes, no) yes
#else
#define PXFLOW_CPU_ISA_IF_x86_64(yes, no) no
#endif

#if defined(__aarch64__)
#define PXFLOW_CPU_ISA_IF_aarch64(yes, no) yes
#else
#define PXFLOW_CPU_ISA_IF_aarch64(yes, no) no
#endif
