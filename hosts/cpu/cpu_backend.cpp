// The CPU registry rows: one per compiled row of the ISA table (kernels/cpu/isas.def) and `cpu`,
// the run-time dispatcher that takes the strongest ISA that can run here. Every row runs
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
#include "isa_table.hpp"
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
    const int rows = grid_axis_triple(p.height, p).count;
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

  // The ISA row that runs (what `cpu` dispatched to). Not the thread count: the records do not
  // depend on it (flow's JSON must not either), and bench names each point's threads itself.
  Description describe() const override { return {std::string(kernel_.name), {}, {}}; }

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

std::unique_ptr<Backend> create_isa(std::string_view isa, const BackendOptions& o) {
  if (const std::string why = cpu::isa_unavailable(isa); !why.empty())
    throw BackendError(std::string(isa) + " cannot run here: " + why);
  // Available means compiled and supported, so the row has its accessor and the CPU its ISA.
  return std::make_unique<CpuBackend>(cpu::find_isa(isa)->kernel(), o.threads);
}

// The row of one compiled ISA of the table.
BackendRow isa_row(const cpu::IsaInfo& info) {
  BackendRow row;
  row.name = info.name;
  row.needs = info.needs;
  row.probe = [isa = row.name] { return cpu::isa_unavailable(isa); };
  row.create = [isa = row.name](const BackendOptions& o) { return create_isa(isa, o); };
  row.host_lacks = [has = info.cpu_has] { return !has(); };
  row.counts_like = RefVariant::kOriginal;  // poi_loop.cpp charges as ref-original when it counts
  return row;
}

// Its `needs` is fixed when the registry is built, before --disable-isa is applied, so it names
// no ISA: the ISA rows above it say which can run.
BackendRow dispatcher_row() {
  BackendRow row;
  row.name = "cpu";
  row.needs = "the strongest ISA row above that is available (not masked)";
  row.probe = [] {
    if (!cpu::best_isa().empty()) return std::string();
    const std::string& weakest = cpu::compiled_isas().front();
    return "every CPU kernel is unavailable (" + weakest + ": " + cpu::isa_unavailable(weakest) +
           ")";
  };
  row.create = [](const BackendOptions& o) {
    const std::string isa = cpu::best_isa();
    if (isa.empty()) throw BackendError("cpu: every CPU kernel is masked");
    return create_isa(isa, o);
  };
  row.preferred = true;
  row.counts_like = RefVariant::kOriginal;  // as the ISA row it dispatches to
  return row;
}

// The bench's bound for TSC-timed rows: the SAD work at the rate of the SAD instruction that
// compares the most bytes per cycle here, measured on as many threads as the row was given.
std::optional<BenchBound> psadbw_bound() {
#if defined(__x86_64__)
  const std::string fastest = cpu::fastest_instruction().instruction;
  if (fastest == "none") return std::nullopt;
  return BenchBound{"back-to-back " + fastest + " on L1 data (the fastest of " +
                        cpu::ceiling_instructions() + " here)",
                    "tsc",
                    [fastest](int threads) { return cpu::measure_ceiling(fastest, threads); },
                    sad_bytes_per_frame};
#else
  return std::nullopt;
#endif
}

}  // namespace

BackendFamily cpu_family() {
  BackendFamily family;
  family.name = "cpu";
  family.measure_bench_bound = psadbw_bound;
  for (const cpu::IsaInfo& info : cpu::isa_table())
    if (info.compiled()) family.rows.push_back(isa_row(info));
  family.rows.push_back(dispatcher_row());
  family.options.push_back({"--disable-isa",
                            "Mask CPU ISAs for this run, a comma-separated list of " +
                                cpu::known_isas() + " (replaces PXFLOW_DISABLE)",
                            [](const std::string& list) { cpu::set_disabled_isas(list); }, false,
                            "LIST"});
  family.check_environment = cpu::check_environment;
  family.environment.push_back(
      {cpu::kDisableEnvironment,
       "CPU ISAs the cpu rows must not use, a comma-separated list as for --disable-isa"});
  return family;
}

}  // namespace pxflow
