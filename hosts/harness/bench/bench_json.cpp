// The bench's results file (docs/report-schema.md, "bench"): its one table of a row's fields.
#include <array>

#include "bench.hpp"
#include "machine_state.hpp"
#include "provenance.hpp"
#include "result_fields_json.hpp"

namespace pxflow {
namespace {

// A figure a row may lack (0: not measured, or not this clock's): left out of the JSON, an
// empty cell of the CSV.
template <auto M>
Json when_positive(const BenchRow& r) {
  return r.*M > 0 ? Json(r.*M) : Json();
}
template <auto M>
constexpr ResultField<BenchRow> positive_field(const char* key) {
  return {key, &when_positive<M>, &member_set<M>, true, true};
}

// A field of this round's files that an older file lacks (pxflow compare reads both).
template <auto M>
constexpr ResultField<BenchRow> newer_field(const char* key, bool csv = true) {
  return {key, &member_get<M>, &member_set<M>, csv, true};
}

// In the CSV's column order (results.csv); the JSON objects have the same order.
constexpr std::array kBenchRowFields{
    member_field<&BenchRow::backend>(bench_key::kBackend),
    member_field<&BenchRow::sweep>(bench_key::kSweep),
    member_field<&BenchRow::setting>(bench_key::kProfile),
    member_field<&BenchRow::width>(bench_key::kWidth),
    member_field<&BenchRow::height>(bench_key::kHeight),
    member_field<&BenchRow::search_radius>(bench_key::kSearchRadius),
    member_field<&BenchRow::batch>(bench_key::kBatch),
    member_field<&BenchRow::threads>(bench_key::kThreads),
    newer_field<&BenchRow::threads_requested>(bench_key::kThreadsRequested),
    newer_field<&BenchRow::device>(bench_key::kDevice),
    newer_field<&BenchRow::timed_build>("timed_build"),
    newer_field<&BenchRow::params>(bench_key::kParams, false),
    member_field<&BenchRow::source>(bench_key::kSource),
    member_field<&BenchRow::exact_clock>(bench_key::kExactClock),
    member_field<&BenchRow::repeats>("repeats"),
    newer_field<&BenchRow::processes>(bench_key::kProcesses),
    member_field<&BenchRow::pois_per_frame>("pois_per_frame"),
    member_field<&BenchRow::runs_per_sample>("runs_per_sample"),
    member_field<&BenchRow::measured_s>("measured_s"),
    member_field<&BenchRow::median_ns_per_frame>(bench_key::kMedianNs),
    member_field<&BenchRow::median_ci_low_ns>("median_ci_low_ns"),
    member_field<&BenchRow::median_ci_high_ns>("median_ci_high_ns"),
    member_field<&BenchRow::min_ns_per_frame>("min_ns_per_frame"),
    member_field<&BenchRow::max_ns_per_frame>("max_ns_per_frame"),
    member_field<&BenchRow::noisy>("noisy"),
    member_field<&BenchRow::frames_per_s>("frames_per_s"),
    member_field<&BenchRow::ns_per_poi>("ns_per_poi"),
    positive_field<&BenchRow::cycles_per_frame>("cycles_per_frame"),
    positive_field<&BenchRow::instructions_per_frame>("instructions_per_frame"),
    newer_field<&BenchRow::bound>("bound"),
    newer_field<&BenchRow::bound_unit>("bound_unit"),
    positive_field<&BenchRow::bound_per_frame>("bound_per_frame"),
    positive_field<&BenchRow::bound_fraction>("bound_fraction"),
    positive_field<&BenchRow::bound_ratio>("bound_ratio"),
    positive_field<&BenchRow::speedup_vs_reference>("speedup_vs_ref_original"),
    member_field<&BenchRow::note>(bench_key::kNote),
    // Every sample, in the JSON only, process after process (`samples_per_process` of each),
    // and each process's median: what pxflow compare's test and interval read.
    member_field<&BenchRow::samples_ns_per_frame>(bench_key::kSamples, false),
    newer_field<&BenchRow::samples_per_process>("samples_per_process", false),
    newer_field<&BenchRow::process_medians_ns_per_frame>(bench_key::kProcessMedians, false),
};

}  // namespace

std::span<const ResultField<BenchRow>> bench_row_fields() { return kBenchRowFields; }

Json bench_json(const BenchReport& r) {
  Json rows = Json::array();
  for (const BenchRow& b : r.rows) rows.push_back(fields_json(bench_row_fields(), b));
  // "complete": false: a signal stopped the bench after `points_done` whole points of
  // `points_total`; every row measured is kept (the stopped point's finished backends too).
  Json j{{"command", r.command},
         {"complete", r.complete},
         // The unit of replication (docs/harness.md, "Statistics"): a row's median and interval
         // are over its processes' medians; with one process, over its samples.
         {"replication",
          {{"unit", "process"},
           {"processes", r.processes},
           {"statistic", r.processes > 1 ? "median and 95% interval of the processes' medians"
                                         : "median and 95% interval of one process's samples"}}},
         {"points_done", r.points_done},
         {"points_total", r.points_total},
         {"backends", r.backends},
         {"machine", machine_json(r.machine)},
         // Which machine and build: what pxflow compare names each file by.
         {"provenance", r.provenance.is_null()
                            ? Json{{"build", build_provenance()}, {"machine", machine_provenance()}}
                            : r.provenance},
         {"rows", rows},
         {"skipped", r.skipped}};
  if (r.bound_bytes_per_cycle > 0) {
    Json by_threads = Json::array();
    for (const auto& [threads, bpc] : r.bound_by_threads)
      by_threads.push_back({{"threads", threads}, {"bytes_per_cycle", bpc}});
    j["bound"] = {{"name", r.bound_name},
                  {"clock", r.bound_clock},
                  {"bytes_per_cycle", r.bound_bytes_per_cycle},
                  {"by_threads", by_threads}};
    if (r.tsc_hz > 0) j["bound"]["tsc_hz"] = r.tsc_hz;
  }
  return j;
}

}  // namespace pxflow
