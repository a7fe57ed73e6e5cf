// Catch2's main for every test executable, with the suite's two warnings always on, whatever the
// command line (Catch2 2.x takes one -w per run): NoTests, so a test name that matches no case
// fails (a ";" in it, which CMake splits), and NoAssertions, so a case or leaf section that
// asserted nothing fails instead of passing having tested nothing (cmake/PxflowTests.cmake).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
  Catch::Session session;
  if (const int rc = session.applyCommandLine(argc, argv); rc != 0) return rc;
  Catch::ConfigData& config = session.configData();
  config.warnings = static_cast<Catch::WarnAbout::What>(
      config.warnings | Catch::WarnAbout::NoTests | Catch::WarnAbout::NoAssertions);
  return session.run();
}
