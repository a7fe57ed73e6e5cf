// `pxflow vectors`: test vectors for on-target unit tests and for implementations that cannot
// talk the protocol (docs/dut-protocol.md section 9): seeded random pairs, their parameters, the
// expected records and the expected flow bits, as binary files with a JSON manifest or as C
// arrays with a freestanding checker; `pxflow vectors verify DIR RECORDS` compares records made
// elsewhere with check's mismatch lines and exit codes.
#include <bit>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string_view>

#include "cli_extension.hpp"
#include "counted.hpp"
#include "dut_wire.hpp"
#include "errors.hpp"
#include "estimate.hpp"
#include "exactness.hpp"
#include "frame_io.hpp"
#include "frame_sequence.hpp"
#include "grid.hpp"
#include "input_file.hpp"
#include "interrupt.hpp"
#include "json_document.hpp"
#include "list_option.hpp"
#include "output_plan.hpp"
#include "owned_folder.hpp"
#include "param_fields.hpp"
#include "path_options.hpp"
#include "progress.hpp"
#include "synthetic.hpp"

namespace pxflow::cli {
namespace {

using Json = nlohmann::ordered_json;

struct VectorsArgs {
  std::string out, format = "bin";
  ProblemOptions problem;
  int cases = 16;
  std::uint64_t seed = 1;
  std::string from, size;  // --from PAIRS (instead of random pairs), --size WxH for raw frames
  bool random_options_given = false;  // --cases or --seed
  std::string verify_dir, verify_records;
};

std::string hex32(std::uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08x", v);
  return b;
}

struct Vectors {
  Params p;
  std::vector<OwnedPair> pairs;
  ReferenceAnswer answer;
};

// The pairs of a --from list (frames a user chose: real frames, a regression), all one size.
using PairList = std::vector<std::pair<std::string, std::string>>;

std::vector<OwnedPair> pairs_from_list(const VectorsArgs& a, const PairList& list) {
  if (list.empty()) throw InputError("--from " + a.from + ": no pairs in the list");
  std::optional<FrameSize> raw;
  if (!a.size.empty()) raw = parse_frame_size(a.size);
  std::vector<OwnedPair> pairs;
  for (const auto& [prev_path, next_path] : list) {
    const Frame prev = load_frame(prev_path, raw), next = load_frame(next_path, raw);
    if (prev.width != next.width || prev.height != next.height ||
        (!pairs.empty() && (prev.width != pairs[0].width || prev.height != pairs[0].height)))
      throw InputError("--from " + a.from + ": " + prev_path + " " + next_path +
                       ": every frame of the list must have one size");
    pairs.push_back(
        {prev_path + " -> " + next_path, prev.width, prev.height, prev.pixels, next.pixels});
  }
  return pairs;
}

Vectors make_vectors(const VectorsArgs& a, const PairList& list) {
  Vectors v;
  if (!a.from.empty()) {
    if (a.random_options_given)
      throw InputError(
          "--cases and --seed choose random pairs; --from gives the pairs (see pxflow vectors "
          "--help)");
    v.pairs = pairs_from_list(a, list);
    v.p = a.problem.resolve(std::pair{v.pairs[0].width, v.pairs[0].height});
  } else {
    if (!a.size.empty())
      throw InputError(
          "--size applies to the raw frames of --from only (see pxflow vectors --help)");
    v.p = a.problem.resolve(std::nullopt);
    for (int i = 0; i < a.cases; ++i) {
      const std::string done = std::to_string(i) + " of " + std::to_string(a.cases) + " pairs made";
      stop_if_interrupted(done);
      progress("vectors: " + done);
      v.pairs.push_back(random_pair(v.p.width, v.p.height, v.p.search_radius, a.seed + i));
    }
  }
  // Pair by pair, so that Ctrl-C stops within one pair.
  for (std::size_t i = 0; i < v.pairs.size(); ++i) {
    const std::string done =
        std::to_string(i) + " of " + std::to_string(v.pairs.size()) + " pairs computed";
    stop_if_interrupted(done);
    progress("vectors: " + done);
    const FramePair view = v.pairs[i].view();
    ReferenceAnswer one = reference_answer({&view, 1}, v.p);
    v.answer.records.insert(v.answer.records.end(), one.records.begin(), one.records.end());
    v.answer.results.push_back(one.results.at(0));
  }
  progress("");  // clears the live line
  return v;
}

// Where the pairs came from, for the header and the summary line.
std::string source_text(const VectorsArgs& a) {
  return a.from.empty() ? "seed " + std::to_string(a.seed) : "from " + a.from;
}

std::string records_bytes(std::span<const PoiRecord> records) {
  std::string s(records.size() * 32, '\0');
  for (std::size_t i = 0; i < records.size(); ++i)
    dut::encode_record(records[i], reinterpret_cast<std::uint8_t*>(s.data() + 32 * i));
  return s;
}

void put32(std::string& s, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>(v >> (8 * i)));
}

// The file of --format c's arrays (pxv_frames, pxv_records, pxv_flow).
constexpr const char* kCArrays = "pxflow_vectors.c";

Json manifest(const Vectors& v, const VectorsArgs& a) {
  Json j;
  j["format"] = "pxflow-vectors";
  j["version"] = 1;
  if (a.from.empty())
    j["seed"] = a.seed;
  else
    j["from"] = a.from;
  Json params = Json::object();
  for (const ParamField& f : param_fields()) params[f.key] = f.get(v.p);
  j["params"] = params;
  j["pairs"] = v.pairs.size();
  j["pois_per_pair"] = poi_count(v.p);
  if (a.format == "bin")
    j["files"] = {{"frames", "frames.bin"}, {"records", "records.bin"}, {"flow", "flow.bin"}};
  else  // the three parts are arrays of one C file: pxv_frames, pxv_records, pxv_flow
    j["files"] = {{"frames", kCArrays}, {"records", kCArrays}, {"flow", kCArrays}};
  j["layout"] = {
      {"frames", "per pair: prev then next, W*H bytes each, rows packed"},
      {"records", "per pair: pois_per_pair records of 32 bytes, SPEC 4, little-endian"},
      {"flow", "per pair: u32 flow_x bits, u32 flow_y bits, i32 quality, i32 meancount, LE"}};
  Json cases = Json::array();
  for (std::size_t i = 0; i < v.pairs.size(); ++i) {
    const FrameResult& r = v.answer.results[i];
    cases.push_back({{"index", i},
                     {"name", v.pairs[i].name},
                     {"flow_x_bits", hex32(std::bit_cast<std::uint32_t>(r.flow_x))},
                     {"flow_y_bits", hex32(std::bit_cast<std::uint32_t>(r.flow_y))},
                     {"quality", r.quality},
                     {"meancount", r.meancount}});
  }
  j["cases"] = cases;
  return j;
}

std::string c_array(const std::string& name, const std::string& bytes) {
  std::ostringstream s;
  s << "const uint8_t " << name << "[" << bytes.size() << "] = {";
  for (std::size_t i = 0; i < bytes.size(); ++i)
    s << (i % 16 ? " " : "\n    ") << static_cast<unsigned>(static_cast<unsigned char>(bytes[i]))
      << ",";
  s << "\n};\n";
  return s.str();
}

const char* kCChecker =
    R"(/* The freestanding checker of pxflow's test vectors (no libc): compares records made on the
 * target (SPEC 4's 32 bytes each, little-endian) and the frame estimate with the expected ones. */
#include "pxflow_vectors.h"

long pxv_check_records(uint32_t pair, const uint8_t *records) {
  const uint8_t *want = pxv_records + (unsigned long)pair * PXV_POIS * 32u;
  for (unsigned long i = 0; i < PXV_POIS * 32ul; ++i)
    if (records[i] != want[i]) return (long)i;
  return -1;
}

int pxv_check_flow(uint32_t pair, uint32_t flow_x_bits, uint32_t flow_y_bits, int32_t quality) {
  const uint8_t *f = pxv_flow + (unsigned long)pair * 16u;
  const uint32_t x = (uint32_t)f[0] | (uint32_t)f[1] << 8 | (uint32_t)f[2] << 16 | (uint32_t)f[3] << 24;
  const uint32_t y = (uint32_t)f[4] | (uint32_t)f[5] << 8 | (uint32_t)f[6] << 16 | (uint32_t)f[7] << 24;
  const uint32_t q = (uint32_t)f[8] | (uint32_t)f[9] << 8 | (uint32_t)f[10] << 16 | (uint32_t)f[11] << 24;
  return x == flow_x_bits && y == flow_y_bits && q == (uint32_t)quality ? 0 : 1;
}
)";

// The list of the files a vectors folder holds (io/owned_folder.hpp): a folder without it that
// holds files is refused, so a user's manifest.json is never replaced.
constexpr const char* kVectorsManifest = ".pxflow-vectors";

// The files of each --format, in the order they are written.
std::vector<std::string> vector_files(const std::string& format) {
  if (format == "bin") return {"manifest.json", "frames.bin", "records.bin", "flow.bin"};
  return {"manifest.json", "pxflow_vectors.h", kCArrays, "pxflow_vectors_check.c"};
}

// The frames of every pair back to back, prev then next (frames.bin, pxv_frames).
std::string frames_bytes(const Vectors& v) {
  std::string frames;
  for (const auto& op : v.pairs) {
    frames.append(op.prev.begin(), op.prev.end());
    frames.append(op.next.begin(), op.next.end());
  }
  return frames;
}

// Per pair: the bits of flow_x and flow_y, quality, meancount, 4 bytes each, little-endian
// (flow.bin, pxv_flow).
std::string flow_bytes(const Vectors& v) {
  std::string flow;
  for (const FrameResult& r : v.answer.results) {
    put32(flow, std::bit_cast<std::uint32_t>(r.flow_x));
    put32(flow, std::bit_cast<std::uint32_t>(r.flow_y));
    put32(flow, static_cast<std::uint32_t>(r.quality));
    put32(flow, static_cast<std::uint32_t>(r.meancount));
  }
  return flow;
}

// pxflow_vectors.h of --format c: the problem as macros, the arrays and the checker declared.
std::string c_header(const Vectors& v, const VectorsArgs& a) {
  std::ostringstream h;
  h << "/* pxflow test vectors (pxflow vectors --format c): " << counted(v.pairs.size(), "pair")
    << " of " << v.p.width << "x" << v.p.height << ", S=" << v.p.search_radius
    << " B=" << v.p.blocks << ", " << source_text(a)
    << ". Layout: manifest.json. */\n#ifndef PXFLOW_VECTORS_H\n"
    << "#define PXFLOW_VECTORS_H\n#include <stdint.h>\n#define PXV_PAIRS " << v.pairs.size()
    << "u\n#define PXV_WIDTH " << v.p.width << "u\n#define PXV_HEIGHT " << v.p.height
    << "u\n#define PXV_POIS " << poi_count(v.p) << "u\n#define PXV_S " << v.p.search_radius
    << "u\n#define PXV_T " << v.p.tile << "u\n#define PXV_B " << v.p.blocks << "u\n#define PXV_FT "
    << v.p.feature_threshold << "u\n#define PXV_VT " << v.p.sad_threshold << "u\n#define PXV_HF "
    << (v.p.hist_filter ? 1 : 0) << "u\n#define PXV_MINCOUNT " << v.p.min_count
    << "u\n#define PXV_GC " << (v.p.gyro_comp ? 1 : 0) << "u\n"
    << "extern const uint8_t pxv_frames[], pxv_records[], pxv_flow[];\n"
    << "long pxv_check_records(uint32_t pair, const uint8_t *records);\n"
    << "int pxv_check_flow(uint32_t pair, uint32_t flow_x_bits, uint32_t flow_y_bits, "
       "int32_t quality);\n#endif\n";
  return h.str();
}

// The files of a.format, into `out` (one planned file per name of vector_files()).
void write_vector_files(const Vectors& v, const VectorsArgs& a,
                        std::map<std::string, OutputFile*>& out) {
  const std::string frames = frames_bytes(v), flow = flow_bytes(v);
  const std::string records = records_bytes(v.answer.records);
  out["manifest.json"]->write(json_document(manifest(v, a)));
  if (a.format == "bin") {
    out["frames.bin"]->write(frames);
    out["records.bin"]->write(records);
    out["flow.bin"]->write(flow);
  } else {
    out["pxflow_vectors.h"]->write(c_header(v, a));
    out[kCArrays]->write("#include \"pxflow_vectors.h\"\n" + c_array("pxv_frames", frames) +
                         c_array("pxv_records", records) + c_array("pxv_flow", flow));
    out["pxflow_vectors_check.c"]->write(kCChecker);
  }
}

int write_vectors(const VectorsArgs& a) {
  OutputPlan plan;
  PairList list;  // read once: --from may be a pipe
  if (!a.from.empty()) {
    list = read_pair_list("--from", a.from);
    plan.read(a.from);
    for (const auto& [prev, next] : list) plan.read_all({prev, next});
  }
  plan.make_folder("--out", a.out, kVectorsManifest);
  std::map<std::string, OutputFile*> out;
  for (const std::string& name : vector_files(a.format))
    out[name] = &plan.file("--out", (std::filesystem::path(a.out) / name).string());
  OutputFile& listed =
      plan.file("--out", (std::filesystem::path(a.out) / kVectorsManifest).string());
  const std::vector<std::string> previous = manifest_names(a.out, kVectorsManifest);
  plan.prepare();
  const Vectors v = make_vectors(a, list);
  write_vector_files(v, a, out);
  // The other format's files of an earlier run go: the folder holds one set of vectors.
  listed.write(manifest_text(vector_files(a.format)));
  std::vector<std::string> may_write = vector_files("bin");
  for (const std::string& name : vector_files("c")) may_write.push_back(name);
  remove_unwritten(a.out, previous, may_write, vector_files(a.format));
  std::printf("wrote %s (%dx%d, %s) to %s\n", counted(v.pairs.size(), "pair").c_str(), v.p.width,
              v.p.height, source_text(a).c_str(), a.out.c_str());
  return 0;
}

std::string read_file(const std::string& path, const char* what) {
  return read_input_text(std::string(what) + ": " + path, path);
}

// A decimal number in `text` after leading blanks, up to `max`; `rest` is what follows it.
std::optional<std::size_t> number_at(std::string_view text, std::size_t max,
                                     std::string_view& rest) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return std::nullopt;
  std::size_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data() + first, end, value);
  if (ec != std::errc() || value > max) return std::nullopt;
  rest = text.substr(static_cast<std::size_t>(ptr - text.data()));
  return value;
}

// The bytes of `name` in --format c's arrays file (`const uint8_t name[N] = {b, b, ...};`).
std::string c_array_bytes(const std::string& text, const std::string& name,
                          const std::string& where) {
  const std::string head = "const uint8_t " + name + "[";
  const std::size_t at = text.find(head);
  const std::size_t open = at == std::string::npos ? at : text.find('{', at);
  const std::size_t close = open == std::string::npos ? open : text.find('}', open);
  std::string_view rest;
  const auto size = close == std::string::npos
                        ? std::nullopt
                        : number_at(std::string_view(text).substr(at + head.size()),
                                    std::numeric_limits<std::uint32_t>::max(), rest);
  if (!size)
    throw InputError("vectors verify: " + where + ": no array " + name +
                     " (not written by pxflow vectors --format c?)");
  std::string bytes;
  std::string_view body = std::string_view(text).substr(open + 1, close - open - 1);
  while (body.find_first_not_of(" \t\r\n") != std::string_view::npos) {
    const auto byte = number_at(body, 255, rest);
    if (!byte || rest.empty() || rest[0] != ',')
      throw InputError("vectors verify: " + where + ": array " + name + ": element " +
                       std::to_string(bytes.size()) + " is not a byte followed by ','");
    bytes.push_back(static_cast<char>(*byte));
    body = rest.substr(1);
  }
  if (bytes.size() != *size)
    throw InputError("vectors verify: " + where + ": array " + name + " has " +
                     std::to_string(bytes.size()) + " bytes, it declares " + std::to_string(*size));
  return bytes;
}

// The expected records of a vectors folder of either --format: records.bin, or the pxv_records
// array of pxflow_vectors.c.
std::string expected_records(const std::string& dir) {
  if (std::filesystem::exists(dir + "records.bin"))
    return read_file(dir + "records.bin", "vectors verify");
  if (std::filesystem::exists(dir + kCArrays))
    return c_array_bytes(read_file(dir + kCArrays, "vectors verify"), "pxv_records",
                         dir + kCArrays);
  throw InputError("vectors verify: " + dir + ": neither records.bin (--format bin) nor " +
                   kCArrays + " (--format c): not a pxflow vectors folder");
}

int verify_vectors(const VectorsArgs& a) {
  const std::string dir = a.verify_dir + "/";
  Json m;
  try {
    m = Json::parse(read_file(dir + "manifest.json", "vectors verify"));
  } catch (const nlohmann::json::exception& e) {
    throw InputError("vectors verify: " + dir +
                     "manifest.json: not a vectors manifest: " + e.what());
  }
  if (m.value("format", "") != "pxflow-vectors" || m.value("version", 0) != 1)
    throw InputError("vectors verify: " + dir +
                     "manifest.json: not a version-1 pxflow-vectors manifest");
  Params p;
  const Json& q = m["params"];
  for (const ParamField& f : param_fields()) {
    if (!q.contains(f.key) || !q[f.key].is_number_integer())
      throw InputError("vectors verify: " + dir + "manifest.json: params." + f.key +
                       " is missing or not an integer");
    f.set(p, q[f.key].get<int>());
  }
  validate(p);
  const std::size_t pairs = m["pairs"], per = poi_count(p);
  const std::string want_bytes = expected_records(dir);
  const std::string got_bytes = read_file(a.verify_records, "vectors verify");
  if (want_bytes.size() != pairs * per * 32)
    throw InputError("vectors verify: " + dir +
                     "'s expected records: " + std::to_string(want_bytes.size()) +
                     " bytes, the manifest says " + std::to_string(pairs * per * 32));
  if (got_bytes.size() != want_bytes.size())
    throw InputError("vectors verify: " + a.verify_records + ": " +
                     std::to_string(got_bytes.size()) + " bytes: allowed " +
                     std::to_string(want_bytes.size()) + " (" + std::to_string(pairs) +
                     " pairs x " + std::to_string(per) + " records x 32 bytes, see manifest.json)");
  ReferenceAnswer want;
  std::vector<PoiRecord> got;
  for (std::size_t i = 0; i < pairs * per; ++i) {
    want.records.push_back(
        dut::decode_record(reinterpret_cast<const std::uint8_t*>(want_bytes.data()) + 32 * i));
    got.push_back(
        dut::decode_record(reinterpret_cast<const std::uint8_t*>(got_bytes.data()) + 32 * i));
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < pairs; ++i) {
    want.results.push_back(
        estimate_flow(std::span<const PoiRecord>(want.records).subspan(i * per, per), p));
    names.push_back(m["cases"][i].value("name", "pair " + std::to_string(i)));
  }
  const Comparison c =
      compare_with_reference({a.verify_records, "vectors", a.verify_dir}, names, p, want, got, 20);
  for (const std::string& line : c.lines) std::printf("%s\n", line.c_str());
  std::printf("%s: %s\n", counted(pairs, "pair").c_str(),
              c.ok() ? "all records and flow bits equal" : "MISMATCH");
  return c.ok() ? 0 : 1;
}

const std::vector<std::string> kVectorsExamples = {
    "vectors --out vec/ --cases 100  # test vectors for on-target tests (vec/ exists)",
};

Command add_vectors_command(CommandSpec& app) {
  auto a = std::make_shared<VectorsArgs>();
  CommandSpec* sub = &app.add_subcommand(
      "vectors",
      "Write test vectors (inputs, parameters, expected records and flow bits) for "
      "on-target tests; `vectors verify DIR RECORDS` checks records made elsewhere");
  sub->add("--out", &a->out,
           "Folder to write the vectors into (created if missing; a folder "
           "that holds other files than an earlier run's vectors is refused)")
      .type("DIR")
      .path_kind(PathKind::OwnedFolder);
  a->problem.add_to(*sub);
  sub->add("--cases", &a->cases, "Random pairs (seeded)").in_range(1, 100000);
  add_seed_option(*sub, a->seed, "of the first pair; pair i has seed + i");
  sub->add("--from", &a->from,
           "Vectors of these pairs instead of random ones: a list file, one 'PREV "
           "NEXT' per line (paths relative to the list), every frame one size")
      .type("FILE")
      .path_kind(PathKind::InputFile);
  sub->add("--size", &a->size, "Frame size of raw frames in the --from list, WxH").type("WxH");
  add_progress_flag(*sub);
  sub->add("--format", &a->format, "bin (files + manifest.json) or c (C arrays + checker)")
      .type("bin|c")
      .choices({"bin", "c"});
  CommandSpec* verify = &sub->add_subcommand("verify",
                                             "Compare RECORDS (a file of 32-byte records, "
                                             "all pairs in order) with the vectors in DIR");
  verify->add("DIR", &a->verify_dir, "The vectors' folder")
      .needed()
      .type("DIR")
      .path_kind(PathKind::InputFolder);
  verify->add("RECORDS", &a->verify_records, "The records to check")
      .needed()
      .type("FILE")
      .path_kind(PathKind::InputFile);
  return {sub,
          [a, sub, verify] {
            a->random_options_given = sub->count("--cases") + sub->count("--seed") > 0;
            if (verify->parsed) return verify_vectors(*a);
            if (a->out.empty())
              throw InputError(
                  "vectors: --out DIR is required: the folder to write into (see "
                  "pxflow vectors --help)");
            return write_vectors(*a);
          },
          kVectorsExamples,
          {"--cases 1", "--from {PAIRS}", "verify {VECTORS} {RECORDS}"}};
}

}  // namespace

CliExtension dut_cli_extension() { return {"dut", add_vectors_command, "", "", {}}; }

}  // namespace pxflow::cli
