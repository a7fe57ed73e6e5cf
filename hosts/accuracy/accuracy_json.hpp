// The accuracy rows as JSON, one object per method and set of pairs: what `pxflow accuracy
// --json` writes and the report's results.json holds under accuracy.rows (docs/report-schema.md).
#pragma once
#include "accuracy_run.hpp"
#include "result_json.hpp"

namespace pxflow::accuracy {

// [{set, setting, against, method, frames, with_flow, mean_error_px, p95_error_px,
//   median_us_per_frame}, ...]; the errors are null for the reference row of an agreement set.
Json accuracy_rows_json(const AccuracyReport& report);

}  // namespace pxflow::accuracy
