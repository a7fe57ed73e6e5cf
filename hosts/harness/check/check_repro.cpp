#include "check_repro.hpp"

#include <filesystem>

#include "grid.hpp"
#include "output_plan.hpp"
#include "param_fields.hpp"
#include "registry.hpp"
#include "shell_word.hpp"

namespace fs = std::filesystem;

namespace pxflow {
namespace {

// A folder name from a backend name: its letters, digits, '.', '-' and '_' kept, others '_'.
std::string folder_name(const std::string& row) {
  std::string s = row;
  for (char& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-' && ch != '_')
      ch = '_';
  return s.empty() || s[0] == '.' ? "_" + s : s;
}

// `pxflow flow` on the reproducer, for `row`: --size and the --set of every parameter that is not
// the default profile's, the records on standard output as JSON.
std::string flow_command(const std::string& program, const std::string& row, const Params& p,
                         const std::string& folder) {
  std::string c = program + " flow --backend " + shell_word(row) + " --size " +
                  std::to_string(p.width) + "x" + std::to_string(p.height);
  const Params base = profile(kDefaultProfile);
  for (const ParamField& f : param_fields()) {
    const std::string key = f.key;
    if (key == "width" || key == "height" || f.get(p) == f.get(base)) continue;
    c += " --set " + key + "=" + std::to_string(f.get(p));
  }
  return c + " --json - " + shell_word((fs::path(folder) / "prev.raw").string()) + " " +
         shell_word((fs::path(folder) / "next.raw").string());
}

}  // namespace

Explanation MismatchExplainer::explain(const CaseLabel& label, const CheckCase& c,
                                       const ReferenceAnswer& want, std::span<const PoiRecord> got,
                                       const PairRunner& run) {
  const std::size_t per = poi_count(c.params);
  for (std::size_t pair = 0; pair < c.pairs.size(); ++pair)
    for (std::size_t n = 0; n < per; ++n) {
      const PoiRecord& w = want.records[pair * per + n];
      const PoiRecord& g = got[pair * per + n];
      if (differing_stage(w, g) == Stage::kSame) continue;
      const OwnedPair& op = c.pairs[pair];
      const std::string where = label.prefix() + " pair=" + op.name + " poi=" + std::to_string(n);
      Explanation e{where + " first differing stage: " + stage_words(op.view(), c.params, w, g),
                    {}};
      if (!o_.write || !shrunk_.insert(label.who).second) return e;
      const std::optional<Reproducer> r = shrink_mismatch(op, c.params, n, run, o_.limits);
      if (r)
        e.reproducer = write_reproducer(label, *r);
      else
        e.reproducer = {where + " no reproducer: the difference did not recur on this pair alone"};
      return e;
    }
  return {label.prefix() + " first differing stage: frame estimate (every record agrees)", {}};
}

std::vector<std::string> MismatchExplainer::write_reproducer(const CaseLabel& label,
                                                             const Reproducer& r) {
  if (run_dir_.empty()) {
    // One folder per run, never one that exists: pxflow-repro-1, -2, ... whichever is free.
    try {
      for (int n = 1; run_dir_.empty(); ++n) {
        const std::string name = "pxflow-repro-" + std::to_string(n);
        if (o_.make_folder(name))
          run_dir_ = name;
        else if (n > 9999)
          return {label.prefix() + " no reproducer: every name up to pxflow-repro-9999 is taken"};
      }
    } catch (const OutputError& e) {
      return {label.prefix() + " no reproducer: " + e.what()};
    }
  }
  const fs::path relative = fs::path(run_dir_) / folder_name(label.who);
  const fs::path folder = fs::path(o_.dir) / relative;
  try {
    if (!o_.make_folder(relative.string()))
      return {label.prefix() + " no reproducer: " + folder.string() + " exists"};
  } catch (const OutputError& e) {
    return {label.prefix() + " no reproducer: " + e.what()};
  }
  const std::string mine = flow_command(o_.program, label.who, r.params, folder.string());
  const std::string theirs = flow_command(o_.program, kReferenceBackend, r.params, folder.string());
  const std::string size = std::to_string(r.params.width) + "x" + std::to_string(r.params.height);
  auto bytes = [](const std::vector<std::uint8_t>& v) {
    return std::string_view(reinterpret_cast<const char*>(v.data()), v.size());
  };
  o_.write((relative / "prev.raw").string(), bytes(r.pair.prev));
  o_.write((relative / "next.raw").string(), bytes(r.pair.next));
  o_.write((relative / "README.txt").string(),
           "A reproducer of " + label.prefix().substr(5) + " (" + r.pair.name + "): " + size +
               " raw 8-bit frames, prev.raw and next.raw.\nFirst differing POI: " +
               std::to_string(r.poi) + ", " + r.what + "\n\n" + mine + "\n" + theirs + "\n");
  const std::string where = label.prefix() + " reproducer";
  return {where + " in " + folder.string() + " (" + size + ", " + stage_name(r.stage) + " at poi " +
              std::to_string(r.poi) + ", " + std::to_string(r.runs) + " backend runs" +
              (r.cropped ? "" : "; the crop did not fail, the frame is whole") + "): " + r.what,
          where + " shows it: " + mine, where + " against: " + theirs};
}

}  // namespace pxflow
