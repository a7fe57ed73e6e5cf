#include "registry.hpp"

#include "backend_rows.hpp"
#include "errors.hpp"
#include "grid.hpp"

namespace pxflow {
namespace {

std::vector<BackendRow> build_rows() {
  std::vector<BackendRow> rows;
  auto add = [&](std::vector<BackendRow> more) {
    for (auto& r : more) rows.push_back(std::move(r));
  };
  add(reference_rows());
  // Each family's CMake block defines its PXFLOW_WITH_<NAME> when it is built.
#ifdef PXFLOW_WITH_CPU_SIMD
  add(cpu_rows());
#endif
#ifdef PXFLOW_WITH_OPENCL
  add(opencl_rows());
#endif
#ifdef PXFLOW_WITH_VULKAN
  add(vulkan_rows());
#endif
#ifdef PXFLOW_WITH_GAP8
  add(gap8_rows());
#endif
  return rows;
}

std::vector<BackendRow>& mutable_rows() {
  static std::vector<BackendRow> rows = build_rows();
  return rows;
}

}  // namespace

const std::vector<BackendRow>& backend_rows() { return mutable_rows(); }

void add_backend_row(BackendRow row) { mutable_rows().push_back(std::move(row)); }

const BackendRow& find_backend(std::string_view name) {
  std::string known;
  for (const auto& row : backend_rows()) {
    if (row.name == name) return row;
    known += (known.empty() ? "" : ", ") + row.name;
  }
  throw InputError("unknown backend '" + std::string(name) + "' (compiled in: " + known + ")");
}

void check_batch(std::span<const FramePair> pairs, const Params& p, std::span<PoiRecord> out) {
  validate(p);
  for (const auto& pair : pairs)
    for (const FrameView* f : {&pair.prev, &pair.next})
      if (f->width != p.width || f->height != p.height || f->stride < f->width || !f->data)
        throw InputError("frame is " + std::to_string(f->width) + "x" +
                         std::to_string(f->height) + " but the parameters say " +
                         std::to_string(p.width) + "x" + std::to_string(p.height));
  if (out.size() != pairs.size() * poi_count(p))
    throw InputError("record buffer holds " + std::to_string(out.size()) + " records, the batch needs " +
                     std::to_string(pairs.size() * poi_count(p)));
}

}  // namespace pxflow
