// The GAP8 family's CLI extension: `pxflow gap8` and the report's section beside the paper.
#include "gap8_cli.hpp"

#include "cli_extension.hpp"

namespace pxflow::cli {

CliExtension gap8_cli_extension() {
  return {"gap8", add_gap8_command, "--no-gap8",
          "Leave out the GAP8 model's tables beside the paper's", add_gap8_tables};
}

}  // namespace pxflow::cli
