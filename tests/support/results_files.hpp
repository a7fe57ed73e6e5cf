// Results files for report tests: small `pxflow check --json` and `pxflow bench --json` files
// (c.json, b.json in `dir`) of the reference rows, for tests that feed a report without running
// anything else, and a report's sections read back.
#pragma once
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "run_program.hpp"

namespace pxflow::test {

namespace detail {

// The pxflow binary's size and modification time: the cache below is that binary's answers.
inline std::string binary_stamp(const std::string& binary) {
  struct stat st {};
  REQUIRE(::stat(binary.c_str(), &st) == 0);
  return std::to_string(st.st_size) + " " + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec) + "\n";
}

// An exclusive flock on `path`, released when it goes out of scope (also when a REQUIRE throws:
// a lock left held would make the next case of the same process wait for ever).
class FileLock {
 public:
  explicit FileLock(const std::string& path)
      : fd_(::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644)) {
    REQUIRE(fd_ >= 0);
    REQUIRE(::flock(fd_, LOCK_EX) == 0);
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace detail

// c.json and b.json in `dir`. Twenty test cases start from these files, and making them costs
// a check and a bench of the reference rows (about 5 CPU-s in the sanitizer build), so they are
// made once per pxflow binary, into test-cache/small-results beside the binary, and copied from
// there: the same bytes a fresh run would give but for its timings. A lock keeps two tests that
// start together from making them twice; a rebuilt pxflow (another size or mtime) makes them
// again.
inline void make_small_results(const TempDir& dir) {
  namespace fs = std::filesystem;
  const fs::path cache = fs::path(build_paths::pxflow).parent_path() / "test-cache/small-results";
  fs::create_directories(cache);
  const detail::FileLock lock((cache / "lock").string());
  const std::string stamp = detail::binary_stamp(build_paths::pxflow);
  if (slurp((cache / "stamp").string()) != stamp) {
    fs::remove(cache / "stamp");
    REQUIRE(run_pxflow({"check", "--backends", "ref-original,ref-local", "--generated-only",
                        "--json", (cache / "c.json").string()})
                .exit_code == 0);
    REQUIRE(run_pxflow({"bench", "--backends", "ref-original", "--batch", "1", "--min-time", "0",
                        "--json", (cache / "b.json").string()})
                .exit_code == 0);
    std::ofstream(cache / "stamp") << stamp;
  }
  for (const char* name : {"c.json", "b.json"})
    fs::copy_file(cache / name, dir.path(name), fs::copy_options::overwrite_existing);
}

// The section of a report's results.json with this key (nullptr: none).
inline const nlohmann::json* section(const nlohmann::json& results, const std::string& key) {
  for (const auto& s : results["sections"])
    if (s["key"] == key) return &s;
  return nullptr;
}

}  // namespace pxflow::test
