// A results type's fields as pxflow's files carry them: one table per type (bench.hpp:
// bench_row_fields(); check.hpp: check_report_fields(), backend_outcome_fields()). The JSON
// writer, the reader, the CSV columns and the schema test (report_tests, "[schema]") all take
// the list from it, so that a new field is one line of its table and no file can drop it.
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

// A field that is one member, read and written as it is: member_field<&BenchRow::width>("width").
template <class>
struct MemberPointer;
template <class T, class V>
struct MemberPointer<V T::*> {
  using Owner = T;
};
template <auto M>
using OwnerOf = typename MemberPointer<decltype(M)>::Owner;

template <auto M>
Json member_get(const OwnerOf<M>& v) {
  return v.*M;
}
template <auto M>
void member_set(OwnerOf<M>& v, const Json& j) {
  j.get_to(v.*M);
}
template <auto M>
constexpr ResultField<OwnerOf<M>> member_field(const char* key, bool csv = true) {
  return {key, &member_get<M>, &member_set<M>, csv, false};
}

template <class T>
Json fields_json(std::span<const ResultField<T>> fields, const T& v) {
  Json j = Json::object();
  for (const ResultField<T>& f : fields)
    if (Json x = f.get(v); !x.is_null()) j[f.key] = std::move(x);
  return j;
}

// Throws nlohmann's exception naming a missing key or the type it expected.
template <class T>
void fields_from_json(std::span<const ResultField<T>> fields, const Json& j, T& v) {
  for (const ResultField<T>& f : fields)
    if (f.set && (!f.optional || j.contains(f.key))) f.set(v, j.at(f.key));
}

template <class T>
std::vector<std::string> csv_columns(std::span<const ResultField<T>> fields) {
  std::vector<std::string> columns;
  for (const ResultField<T>& f : fields)
    if (f.csv) columns.push_back(f.key);
  return columns;
}

}  // namespace pxflow
