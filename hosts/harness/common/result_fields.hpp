// A results type's fields as pxflow's files carry them: one table per type (bench.hpp:
// bench_row_fields(); check.hpp: check_report_fields(), backend_outcome_fields()). The JSON
// writer, the reader, the CSV columns and the schema test (report_tests, "[schema]") all take
// the list from it, so that a new field is one line of its table and no file can drop it.
// Here the table's type and its CSV columns; the JSON writer and reader and member_field(), which
// need nlohmann's whole definition, are in result_fields_json.hpp, for the files that make tables.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "result_json.hpp"

namespace pxflow {

template <class T>
struct ResultField {
  const char* key;                         // the JSON key, and the CSV column when `csv`
  Json (*get)(const T&);                   // null Json: the field is left out of the object
  void (*set)(T&, const Json&) = nullptr;  // the reader's; null: derived, never read
  bool csv = true;                         // a column of the type's CSV file
  bool optional = false;                   // the reader accepts an object without it
};

template <class T>
std::vector<std::string> csv_columns(std::span<const ResultField<T>> fields) {
  std::vector<std::string> columns;
  for (const ResultField<T>& f : fields)
    if (f.csv) columns.push_back(f.key);
  return columns;
}

}  // namespace pxflow
