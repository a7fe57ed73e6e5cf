// A program outside pxflow that uses the installed library: it opens the registry's default
// backend, runs one pair of raw 8-bit frames through it and prints the frame estimate and every
// POI record as one JSON object, with the keys of `pxflow flow --json`. No OpenCV: the frames
// are raw files (W*H bytes, rows packed).
//   consumer PREV.raw NEXT.raw WIDTHxHEIGHT
#include <bit>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <pxflow/errors.hpp>
#include <pxflow/estimate.hpp>
#include <pxflow/grid.hpp>
#include <pxflow/params.hpp>
#include <pxflow/registry.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

pxflow::Frame load_raw(const std::string& path, int width, int height) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  pxflow::Frame f{width, height, {}};
  f.pixels.assign(std::istreambuf_iterator<char>(in), {});
  if (f.pixels.size() != static_cast<std::size_t>(width) * height)
    throw std::runtime_error(path + " holds " + std::to_string(f.pixels.size()) + " bytes, not " +
                             std::to_string(width) + "x" + std::to_string(height));
  return f;
}

std::string bits(float f) {
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08x", std::bit_cast<std::uint32_t>(f));
  return buf;
}

void print_json(const std::string& backend, const pxflow::FrameResult& r,
                const std::vector<pxflow::PoiRecord>& records) {
  std::printf("{\"backend\":\"%s\",\"flow_x_bits\":\"%s\",\"flow_y_bits\":\"%s\",", backend.c_str(),
              bits(r.flow_x).c_str(), bits(r.flow_y).c_str());
  std::printf("\"quality\":%d,\"meancount\":%d,\"pois\":[", r.quality, r.meancount);
  for (std::size_t i = 0; i < records.size(); ++i) {
    const pxflow::PoiRecord& p = records[i];
    std::printf(
        "%s{\"x\":%d,\"y\":%d,\"status\":%d,\"feature\":%d,\"dx\":%d,\"dy\":%d,\"sad\":%d,"
        "\"dir\":%d,\"sub\":[",
        i ? "," : "", p.x, p.y, p.status, p.feature, p.dx, p.dy, p.sad, p.dir);
    for (int k = 0; k < 8; ++k) std::printf("%s%d", k ? "," : "", p.sub[k]);
    std::printf("],\"hx\":%d,\"hy\":%d}", p.hx, p.hy);
  }
  std::printf("]}\n");
}

}  // namespace

int main(int argc, char** argv) {
  int width = 0, height = 0;
  if (argc != 4 || std::sscanf(argv[3], "%dx%d", &width, &height) != 2) {
    std::fprintf(stderr, "usage: consumer PREV.raw NEXT.raw WIDTHxHEIGHT\n");
    return 2;
  }
  try {
    const pxflow::Frame prev = load_raw(argv[1], width, height);
    const pxflow::Frame next = load_raw(argv[2], width, height);
    pxflow::Params p = pxflow::profile(pxflow::profile_names().front());
    p.width = width;
    p.height = height;
    pxflow::validate(p);

    const pxflow::BackendRow& row = pxflow::default_backend();
    const auto backend = pxflow::open_backend_for(row, {}, p);
    const pxflow::FramePair pair{prev.view(), next.view()};
    std::vector<pxflow::PoiRecord> records(pxflow::poi_count(p));
    pxflow::check_batch({&pair, 1}, p, records);
    pxflow::OpCounts counts;
    backend->run({&pair, 1}, p, records, counts);
    print_json(row.name, pxflow::estimate_flow(records, p), records);
    return std::fflush(stdout) == 0 && !std::ferror(stdout) ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: error: %s\n", e.what());
    return 1;
  }
}
