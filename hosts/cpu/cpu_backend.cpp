// The CPU registry rows: one per compiled ISA (swar, sse2, sse41, avx2, avx512bw / neon) and
// `cpu`, the run-time dispatcher that takes the strongest ISA that can run here. Every row runs
// the frame pairs of a batch on a thread pool (BackendOptions::threads, 0 = all cores).
#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "backend.hpp"
#include "cpu_kernel.hpp"
#include "errors.hpp"
#include "grid.hpp"
#include "isa_mask.hpp"
#if defined(__x86_64__)
#include "psadbw_ceiling.hpp"
#endif
#include "thread_pool.hpp"

namespace pxflow {
namespace {

class CpuBackend final : public Backend {
 public:
  CpuBackend(const cpu::IsaKernel& kernel, int threads) : kernel_(kernel), pool_(threads) {}

  void run(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out,
           OpCounts& counts) override {
    const std::size_t per_pair = poi_count(p);
    const auto rows = static_cast<int>(grid_axis(p.height, p).size());
    const int bands = bands_per_pair(pairs.size(), rows);
    // Each item is one band of grid rows of one pair; its records have their own place and its
    // counts are summed in item order, so the bytes do not depend on who ran it.
    std::vector<OpCounts> item_counts(pairs.size() * static_cast<std::size_t>(bands));
    try {
      pool_.for_each(item_counts.size(), [&](std::size_t item) {
        const std::size_t n = item / static_cast<std::size_t>(bands);
        const int band = static_cast<int>(item % static_cast<std::size_t>(bands));
        cpu::run_flow_rows(kernel_, pairs[n], p, band * rows / bands, (band + 1) * rows / bands,
                           out.subspan(n * per_pair, per_pair), item_counts[item]);
      });
    } catch (const BackendError&) {
      throw;
    } catch (const std::exception& e) {
      throw BackendError(std::string(kernel_.name) + ": " + e.what());
    }
    for (const OpCounts& c : item_counts) counts += c;
  }

 private:
  // Few large frames would leave cores idle (and one late-waking worker costs a whole frame):
  // split each pair into bands of grid rows until there are about four items per worker.
  int bands_per_pair(std::size_t pairs, int grid_rows) const {
    if (pool_.size() == 1 || pairs == 0) return 1;
    const auto wanted =
        static_cast<int>((4 * static_cast<std::size_t>(pool_.size()) + pairs - 1) / pairs);
    return std::max(1, std::min(wanted, grid_rows));
  }

  const cpu::IsaKernel& kernel_;
  ThreadPool pool_;
};

// The kernel of a compiled ISA. Called only for an ISA that can run here: the accessor itself
// lives in the ISA's file, compiled with its flags.
const cpu::IsaKernel& kernel_of(std::string_view isa) {
#if defined(__x86_64__)
  if (isa == "sse2") return cpu::sse2_kernel();
  if (isa == "sse41") return cpu::sse41_kernel();
  if (isa == "avx2") return cpu::avx2_kernel();
  if (isa == "avx512bw") return cpu::avx512bw_kernel();
#endif
#if defined(__aarch64__)
  if (isa == "neon") return cpu::neon_kernel();
#endif
  return cpu::swar_kernel();
}

std::string needs_of(std::string_view isa) {
  if (isa == "swar") return "nothing (portable C++, 4 pixels per uint32)";
  if (isa == "sse2") return "x86-64 (SSE2)";
  if (isa == "sse41") return "x86-64 with SSE4.1";
  if (isa == "avx2") return "x86-64 with AVX2";
  if (isa == "avx512bw") return "x86-64 with AVX-512BW";
  return "AArch64 (NEON)";
}

std::unique_ptr<Backend> create_isa(std::string_view isa, const BackendOptions& o) {
  if (const std::string why = cpu::isa_unavailable(isa); !why.empty())
    throw BackendError(std::string(isa) + " cannot run here: " + why);
  return std::make_unique<CpuBackend>(kernel_of(isa), o.threads);
}

BackendRow dispatcher_row() {
  const std::string chosen = cpu::best_isa();
  return {"cpu",
          "the best compiled ISA this CPU supports (here: " + (chosen.empty() ? "none" : chosen) +
              "; PXFLOW_DISABLE masks ISAs)",
          [] {
            return cpu::best_isa().empty() ? std::string("every CPU kernel is unavailable (" +
                                                         cpu::isa_unavailable("swar") + ")")
                                           : std::string();
          },
          [](const BackendOptions& o) {
            const std::string isa = cpu::best_isa();
            if (isa.empty()) throw BackendError("cpu: every CPU kernel is masked");
            return create_isa(isa, o);
          }};
}

// The bench's bound for TSC-timed rows: the SAD work at the widest psadbw's measured rate.
std::optional<BenchBound> psadbw_bound() {
#if defined(__x86_64__)
  const cpu::Ceiling c = cpu::measure_ceiling();
  if (c.bytes_per_cycle <= 0) return std::nullopt;
  return BenchBound{std::string("back-to-back psadbw ") + c.width + " on L1 data", "tsc",
                    c.bytes_per_cycle, [bpc = c.bytes_per_cycle](long pois, int radius) {
                      return cpu::sad_bytes_per_frame(pois, radius) / bpc;
                    }};
#else
  return std::nullopt;
#endif
}

}  // namespace

BackendFamily cpu_family() {
  BackendFamily family{"cpu", {}, {}, psadbw_bound};
  for (const std::string& isa : cpu::compiled_isas())
    family.rows.push_back({isa, needs_of(isa), [isa] { return cpu::isa_unavailable(isa); },
                           [isa](const BackendOptions& o) { return create_isa(isa, o); }});
  family.rows.push_back(dispatcher_row());
  family.rows.back().preferred = true;
  family.options.push_back({"--disable-isa",
                            "Mask CPU ISAs for this run, e.g. avx512bw,avx2 (replaces PXFLOW_DISABLE)",
                            [](const std::string& list) { cpu::set_disabled_isas(list); }});
  return family;
}

}  // namespace pxflow
