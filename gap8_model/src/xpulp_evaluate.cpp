// EvaluateXpulp: the Xpulp operations of path `eval` in gap8_model/isa/xpulp.tbl, one generated
// case per op calling its semantics (xpulp_semantics.h). The kernels' hot instructions (path
// `core`) are computed in the interpreter's own switch instead: one dispatch, not two.
#include "gap8/decoded.h"
#include "xpulp_semantics.h"

namespace gap8 {

uint32_t EvaluateXpulp(const Decoded& d, uint32_t a, uint32_t b, uint32_t c) {
  switch (d.op) {
#include "gap8/xpulp_evaluate.inc"
    default:
      return 0;  // unreachable: the interpreter sends only the `eval` ops here
  }
}

}  // namespace gap8
