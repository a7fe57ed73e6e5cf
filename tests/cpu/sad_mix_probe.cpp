// What a vector instruction costs beside a stream of vdbpsadbw zmm (the bound's instruction,
// docs/harness.md "The bound"): on this CPU, does it run on other ports for free, or take the
// SAD's? Not a test (speed is not a test) and not built by default: `cmake --build build
// --target pxflow_sad_mix_probe && build/pxflow_sad_mix_probe` (x86-64 with AVX-512BW).
//
// Each loop runs register-only instructions with no dependence between iterations but the
// op's own six chains: six vdbpsadbw alone, six of the op alone, and the twelve interleaved.
// Times are TSC cycles per loop, the fastest of many short runs (a preempted run only gets
// slower), shown in units of one vdbpsadbw (so the TSC's rate against the core's cancels):
// `beside` is what each op adds to the six SADs' time. 0 means free (other ports), 1 means
// as much as a vdbpsadbw of its own.
#include <x86intrin.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace {

#define PXFLOW_SIX(X) X(0) X(1) X(2) X(3) X(4) X(5)
#define PXFLOW_SAD(i) "vdbpsadbw $0x94, %%zmm20, %%zmm21, %%zmm" #i "\n"
#define PXFLOW_CLOBBERS                                                                        \
  "xmm0", "xmm1", "xmm2", "xmm3", "xmm4", "xmm5", "xmm10", "xmm11", "xmm12", "xmm13", "xmm14", \
      "xmm15", "xmm20", "xmm21"

// One probe: an op written as an asm line on chain register zmm1<i>.
#define PXFLOW_PROBE(name, OP)                                                              \
  [[gnu::target("avx512bw,avx512vl")]] double name##_loop(long n, bool sads, bool ops) {    \
    const std::uint64_t t0 = __rdtsc();                                                     \
    if (sads && ops)                                                                        \
      for (long i = 0; i < n; ++i)                                                          \
        asm volatile(PXFLOW_SIX(PXFLOW_SAD) PXFLOW_SIX(OP)::: PXFLOW_CLOBBERS);             \
    else if (ops)                                                                           \
      for (long i = 0; i < n; ++i) asm volatile(PXFLOW_SIX(OP)::: PXFLOW_CLOBBERS);         \
    else                                                                                    \
      for (long i = 0; i < n; ++i) asm volatile(PXFLOW_SIX(PXFLOW_SAD)::: PXFLOW_CLOBBERS); \
    return static_cast<double>(__rdtsc() - t0) / static_cast<double>(n);                    \
  }

#define PXFLOW_ADDW(i) "vpaddw %%zmm20, %%zmm1" #i ", %%zmm1" #i "\n"
#define PXFLOW_MINUD(i) "vpminud %%zmm20, %%zmm1" #i ", %%zmm1" #i "\n"
#define PXFLOW_TERNLOG(i) "vpternlogd $0x96, %%zmm20, %%zmm21, %%zmm1" #i "\n"
#define PXFLOW_SLLD(i) "vpslld $16, %%zmm1" #i ", %%zmm1" #i "\n"
#define PXFLOW_PERMD(i) "vpermd %%zmm1" #i ", %%zmm21, %%zmm1" #i "\n"
#define PXFLOW_PERMT2D(i) "vpermt2d %%zmm20, %%zmm21, %%zmm1" #i "\n"
#define PXFLOW_SHUFI(i) "vshufi64x2 $0x4e, %%zmm20, %%zmm1" #i ", %%zmm1" #i "\n"
#define PXFLOW_ALIGNQ(i) "valignq $1, %%zmm20, %%zmm1" #i ", %%zmm1" #i "\n"
#define PXFLOW_PSADBW(i) "vpsadbw %%zmm20, %%zmm1" #i ", %%zmm1" #i "\n"
#define PXFLOW_ADDW_YMM(i) "vpaddw %%ymm20, %%ymm1" #i ", %%ymm1" #i "\n"

PXFLOW_PROBE(addw, PXFLOW_ADDW)
PXFLOW_PROBE(minud, PXFLOW_MINUD)
PXFLOW_PROBE(ternlog, PXFLOW_TERNLOG)
PXFLOW_PROBE(slld, PXFLOW_SLLD)
PXFLOW_PROBE(permd, PXFLOW_PERMD)
PXFLOW_PROBE(permt2d, PXFLOW_PERMT2D)
PXFLOW_PROBE(shufi, PXFLOW_SHUFI)
PXFLOW_PROBE(alignq, PXFLOW_ALIGNQ)
PXFLOW_PROBE(psadbw, PXFLOW_PSADBW)
PXFLOW_PROBE(addw_ymm, PXFLOW_ADDW_YMM)

using Loop = double (*)(long, bool, bool);

double fastest(Loop loop, bool sads, bool ops) {
  double best = 1e30;
  for (int run = 0; run < 400; ++run) best = std::min(best, loop(20000, sads, ops));
  return best;
}

}  // namespace

int main() {
  if (!__builtin_cpu_supports("avx512bw")) {
    std::fprintf(stderr, "pxflow_sad_mix_probe: this CPU has no AVX-512BW\n");
    return 2;
  }
  const struct {
    const char* name;
    Loop loop;
  } ops[] = {{"vpaddw", addw_loop},        {"vpminud", minud_loop},  {"vpternlogd", ternlog_loop},
             {"vpslld", slld_loop},        {"vpermd", permd_loop},   {"vpermt2d", permt2d_loop},
             {"vshufi64x2", shufi_loop},   {"valignq", alignq_loop}, {"vpsadbw", psadbw_loop},
             {"vpaddw ymm", addw_ymm_loop}};
  const double sad = fastest(addw_loop, true, false) / 6;
  std::printf("vdbpsadbw zmm: %.3f TSC cycles each (%.0f bytes per TSC cycle)\n", sad, 128 / sad);
  std::printf("%-11s  %8s  %8s   (zmm but the last; in vdbpsadbw zmm units)\n", "op", "alone",
              "beside");
  for (const auto& op : ops) {
    const double alone = fastest(op.loop, false, true) / 6;
    const double both = fastest(op.loop, true, true) / 6;
    std::printf("%-11s  %8.2f  %8.2f\n", op.name, alone / sad, (both - sad) / sad);
  }
  return 0;
}
