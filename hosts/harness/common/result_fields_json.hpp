// A results type's fields (result_fields.hpp) to and from JSON, and the field of one member: for
// the files that define a type's table or write and read its objects (bench_json.cpp,
// check_json.cpp ...). Apart from result_fields.hpp so that the headers declaring a table need
// only <nlohmann/json_fwd.hpp>.
#pragma once
#include <nlohmann/json.hpp>
#include <span>

#include "result_fields.hpp"

namespace pxflow {

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

}  // namespace pxflow
