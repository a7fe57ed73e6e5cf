// cpu_path_check ISA: the masked-path test. CTest runs it once per compiled ISA with
// PXFLOW_DISABLE masking every stronger one, so that the dispatcher row `cpu` must choose ISA;
// it then checks `cpu` (all cores) and the row named ISA (one thread) against ref-original on
// the whole corpus (synthetic pairs, hostile pairs and the real frames of opencv-doc) with the
// harness's exactness checker, so a mismatch reads like a `pxflow check` line.
// With --dump-real DIR it writes the real frames as raw files for the NEON cross test.
// Exit 0 when every case matches, 1 on any mismatch, 77 (CTest SKIP_RETURN_CODE) when this CPU
// lacks ISA.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cpu_corpus.hpp"
#include "errors.hpp"
#include "frame_io.hpp"
#include "isa_mask.hpp"
#include "isa_table.hpp"
#include "registry.hpp"
#include "sample_data.hpp"

namespace pxflow::cpu_test {
namespace {

constexpr int kSkip = 77;

// The real frames of opencv-doc, or nothing (with a note) when they are not installed.
struct RealPair {
  std::string name;
  Frame prev, next;
};

std::vector<RealPair> real_pairs(const std::string& dir) {
  std::vector<RealPair> pairs;
  for (const char* name : {"rubberwhale", "basketball"}) {
    const std::string a = dir + "/" + name + "1.png", b = dir + "/" + name + "2.png";
    if (!std::filesystem::exists(a) || !std::filesystem::exists(b)) {
      std::printf("note: %s not found, real frames %s not checked %s\n", a.c_str(), name,
                  kSampleDataHint);
      continue;
    }
    pairs.push_back({name, load_frame(a, std::nullopt), load_frame(b, std::nullopt)});
  }
  return pairs;
}

// --dump-real DIR: the real frames as raw files and DIR/frames.txt ("name W H prev next" per
// line) for the NEON cross test, which runs where OpenCV is not available.
int dump_real(const std::string& dir) {
  const std::vector<RealPair> pairs = real_pairs(kSampleDataDir);
  if (pairs.empty()) {
    std::printf("SKIPPED: no real frames in %s (opencv-doc)\n", kSampleDataDir);
    return kSkip;
  }
  std::filesystem::create_directories(dir);
  std::ofstream list(dir + "/frames.txt");
  for (const RealPair& rp : pairs) {
    const std::string a = dir + "/" + rp.name + "1.raw", b = dir + "/" + rp.name + "2.raw";
    std::ofstream(a, std::ios::binary)
        .write(reinterpret_cast<const char*>(rp.prev.pixels.data()),
               static_cast<std::streamsize>(rp.prev.pixels.size()));
    std::ofstream(b, std::ios::binary)
        .write(reinterpret_cast<const char*>(rp.next.pixels.data()),
               static_cast<std::streamsize>(rp.next.pixels.size()));
    list << rp.name << " " << rp.prev.width << " " << rp.prev.height << " " << a << " " << b
         << "\n";
  }
  std::printf("wrote %zu real frame pairs to %s\n", pairs.size(), dir.c_str());
  return list ? 0 : 1;
}

BatchRun backend_run(const std::string& row_name, int threads) {
  return [row_name, threads](std::span<const FramePair> pairs, const Params& p,
                             std::span<PoiRecord> out) {
    auto backend = find_backend(row_name).create(BackendOptions{threads, {}});
    OpCounts counts;
    backend->run(pairs, p, out, counts);
  };
}

int run(const std::string& isa) {
  cpu::check_environment();  // the mask CTest set must be valid: a typo is a failure, not a skip
  // Whether the CPU has it, regardless of the mask this test was started with.
  const cpu::IsaInfo* info = cpu::find_isa(isa);
  if (!info || !info->compiled()) {
    std::printf("FAIL %s is not a compiled ISA of this build (known: %s)\n", isa.c_str(),
                cpu::known_isas().c_str());
    return 1;
  }
  if (!info->cpu_has()) {
    std::printf("skipped: %s (this CPU lacks it: needs %s)\n", isa.c_str(), info->needs);
    return kSkip;
  }
  const std::string chosen = cpu::best_isa();
  if (chosen != isa) {
    std::printf("FAIL dispatcher chose '%s', expected '%s' (PXFLOW_DISABLE mask)\n", chosen.c_str(),
                isa.c_str());
    return 1;
  }
  std::vector<Group> groups = synthetic_corpus(120);
  for (const RealPair& rp : real_pairs(kSampleDataDir))
    for (Group& g : real_groups(rp.name, rp.prev.width, rp.prev.height, rp.prev.pixels.data(),
                                rp.next.pixels.data()))
      groups.push_back(std::move(g));
  int failed = 0, total = 0, pairs = 0;
  for (const Group& g : groups) {
    total += 2;
    pairs += static_cast<int>(g.cases.size());
    failed += check_group("cpu(" + isa + ")", g, backend_run("cpu", 0)) ? 0 : 1;
    failed += check_group(isa, g, backend_run(isa, 1)) ? 0 : 1;
  }
  std::printf("%s: %d of %d group runs failed (%zu groups, %d pairs, each run by cpu and %s)\n",
              isa.c_str(), failed, total, groups.size(), pairs, isa.c_str());
  return failed == 0 ? 0 : 1;
}

}  // namespace
}  // namespace pxflow::cpu_test

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--dump-real")
    return pxflow::cpu_test::dump_real(argv[2]);
  if (argc != 2) {
    std::fprintf(stderr, "usage: cpu_path_check ISA | cpu_path_check --dump-real DIR\n");
    return 2;
  }
  try {
    return pxflow::cpu_test::run(argv[1]);
  } catch (const std::exception& e) {
    std::printf("FAIL %s: %s\n", argv[1], e.what());
    return 1;
  }
}
