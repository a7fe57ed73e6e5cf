// pxflow gap8's output options: `--json -` puts the JSON alone on standard output.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "run_program.hpp"

TEST_CASE("gap8 --json - prints the JSON alone, the same as --json FILE", "[gap8][cli]") {
  pxflow::test::TempDir dir;
  const auto piped =
      pxflow::test::run_pxflow({"gap8", "--variant", "fast", "--cores", "2", "--json", "-"});
  REQUIRE(piped.exit_code == 0);
  const auto to_file = pxflow::test::run_pxflow(
      {"gap8", "--variant", "fast", "--cores", "2", "--json", dir.path("g.json")});
  REQUIRE(to_file.exit_code == 0);
  CHECK(to_file.out.find("cycles") != std::string::npos);  // the tables, on stdout
  const auto j = nlohmann::json::parse(piped.out);         // nothing but JSON on stdout
  CHECK(j == nlohmann::json::parse(pxflow::test::slurp(dir.path("g.json"))));
}
