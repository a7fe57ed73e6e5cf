// The GAP8 registry rows: one per kernel variant, on the 8-core cluster model.
#include "backend.hpp"
#include "errors.hpp"
#include "gap8_backend.hpp"
#include "gap8_kernel_elf.hpp"

namespace pxflow {
namespace {

BackendRow gap8_row(const std::string& variant) {
  return {"gap8-" + variant, "nothing (the GAP8 cluster cycle model is built in; 8 cores, 50 MHz)",
          [variant]() -> std::string {
            return gap8_kernel_elf(variant).empty() ? "no embedded GAP8 kernel ELF" : "";
          },
          [variant](const BackendOptions& o) -> std::unique_ptr<Backend> {
            return std::make_unique<Gap8Backend>(variant, gap8_host::RunOptions{}, o.threads);
          }};
}

}  // namespace

BackendFamily gap8_family() {
  return {"gap8", {gap8_row("original"), gap8_row("local"), gap8_row("global")}, {}, {}};
}

}  // namespace pxflow
