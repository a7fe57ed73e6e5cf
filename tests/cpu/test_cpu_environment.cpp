// PXFLOW_DISABLE through the CLI: an unknown ISA name is the same bad-input error as
// --disable-isa with one (exit 2, one stderr line naming every valid ISA), never a skipped row
// and a green check; a valid value masks as before. Runs the built pxflow binary, which inherits
// this process's environment.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <optional>
#include <string>

#include "bad_input.hpp"
#include "isa_mask.hpp"
#include "isa_table.hpp"
#include "run_program.hpp"
#include "scoped_env.hpp"

using namespace pxflow;
using pxflow::test::ScopedEnv;

TEST_CASE("PXFLOW_DISABLE with an unknown ISA is exit 2 naming the valid ISAs", "[cpu][mask]") {
  const ScopedEnv env("PXFLOW_DISABLE", "avx-512");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"check"}, {"backends"}, {"backends", "--disable-isa", "swar"}}) {
    INFO("pxflow " << args.front() << (args.size() > 1 ? " " + args[1] : ""));
    test::require_bad_input(args, "PXFLOW_DISABLE: unknown ISA 'avx-512'");
    const auto r = test::run_pxflow(args);
    CHECK(r.err.rfind("pxflow: error: ", 0) == 0);
    for (const cpu::IsaInfo& isa : cpu::isa_table())
      CHECK(r.err.find(isa.name) != std::string::npos);
  }
}

TEST_CASE("the --disable-isa option with an unknown ISA names the valid ISAs too", "[cpu][mask]") {
  test::require_bad_input(
      {"backends", "--disable-isa", "avx-512"},
      "--disable-isa: unknown ISA 'avx-512' (known: " + cpu::known_isas() + ")");
}

TEST_CASE("PXFLOW_DISABLE with a valid ISA masks its row", "[cpu][mask][all-probes]") {
  const std::string strongest = cpu::compiled_isas().back();
  const ScopedEnv env("PXFLOW_DISABLE", strongest.c_str());
  const auto r = test::run_pxflow({"backends"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find(strongest) != std::string::npos);
  CHECK(r.out.find("masked by PXFLOW_DISABLE") != std::string::npos);
}
