// Params' fields by SPEC §1's keys, in the order of the spec core's parameter block
// (pxflow_param_block, the device protocol's PARAMS): the one list of the keys. --set
// (set_param), param_keys(), the JSON writers and the vectors manifest's reader walk it.
#pragma once
#include <span>

#include "params.hpp"

namespace pxflow {

struct ParamField {
  const char* key;
  int Params::*number;  // the field, or null for a flag
  bool Params::*flag;   // the field, or null for a number

  int get(const Params& p) const { return number ? p.*number : (p.*flag ? 1 : 0); }
  void set(Params& p, int v) const {
    if (number)
      p.*number = v;
    else
      p.*flag = v != 0;
  }
};

std::span<const ParamField> param_fields();

}  // namespace pxflow
