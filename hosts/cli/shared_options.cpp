#include "shared_options.hpp"

#include <stdexcept>

#include "list_option.hpp"
#include "progress.hpp"
#include "sample_data.hpp"

namespace pxflow::cli {

const std::vector<SharedOption>& shared_options() {
  static const std::vector<SharedOption> table = {
      {"--backend", "NAME", "One backend, by its name in `pxflow backends`",
       "flow: ref-original (the executable spec); accuracy and report's pictures: the preferred "
       "backend that runs here; check and bench: every backend (--backends)"},
      {"--backends", "LIST", "Comma-separated backends, by their names in `pxflow backends`",
       "check and report: every backend compiled in (one that cannot run here is reported "
       "skipped); bench: every backend that can run here"},
      {"--threads", "N",
       "Host worker threads of the CPU backends and the GAP8 model (0 = all cores)",
       "0 (all cores); accuracy: 1, for OpenCV and the backend alike (like for like)"},
      {"--device", "D", "Device index or name substring of the GPU backends (OpenCL, Vulkan)",
       "the backend's preferred device"},
      {"--json", "FILE", "Write the results as JSON to FILE ('-': standard output)", "none"},
      {"--data", "DIR", "Folder of the real frames and videos (Debian's opencv-doc)",
       kSampleDataDir},
      {"--seed", "N", "Seed of the random inputs (the same seed gives the same inputs)", "1"},
      {"--progress", "", "Progress lines on stderr even when it is not a terminal (CI logs)",
       "progress only on a terminal"},
  };
  return table;
}

namespace {

const SharedOption& shared_option(std::string_view name) {
  for (const SharedOption& o : shared_options())
    if (o.name == name) return o;
  throw std::out_of_range("not a shared option: " + std::string(name));
}

}  // namespace

std::string shared_options_markdown() {
  std::string md = "| option | meaning | default |\n|---|---|---|\n";
  for (const SharedOption& o : shared_options())
    md += "| `" + o.name + (o.value.empty() ? "" : " " + o.value) + "` | " + o.meaning + " | " +
          o.defaults + " |\n";
  return md;
}

namespace {

// The shared help, this command's detail, then the default: one text wherever it is declared.
std::string help(std::string_view name, const std::string& detail) {
  const SharedOption& o = shared_option(name);
  return o.meaning + (detail.empty() ? "" : "; " + detail) + ". Default: " + o.defaults;
}

OptionSpec& add(CommandSpec& sub, std::string_view name, OptionTarget variable,
                const std::string& detail) {
  return sub.add(std::string(name), variable, help(name, detail)).type(shared_option(name).value);
}

}  // namespace

OptionSpec& add_backend_option(CommandSpec& sub, std::string& backend, const std::string& detail) {
  return add(sub, "--backend", &backend, detail);
}

OptionSpec& add_backends_option(CommandSpec& sub, std::string& backends,
                                const std::string& detail) {
  return add(sub, "--backends", &backends, detail);
}

OptionSpec& add_threads_option(CommandSpec& sub, int& threads, const std::string& detail) {
  return add(sub, "--threads", &threads, detail).in_range(0, 1024);
}

OptionSpec& add_device_option(CommandSpec& sub, std::string& device) {
  return add(sub, "--device", &device, "");
}

OptionSpec& add_json_option(CommandSpec& sub, std::string& path, const std::string& detail) {
  return add(sub, "--json", &path, detail).path_kind(PathKind::OutputFile, ".json");
}

OptionSpec& add_data_option(CommandSpec& sub, std::string& dir, const std::string& detail) {
  return add(sub, "--data", &dir, detail).path_kind(PathKind::InputFolder);
}

OptionSpec& add_seed_option(CommandSpec& sub, std::uint64_t& seed, const std::string& detail) {
  return add(sub, "--seed", &seed, detail).checked(seed_value());
}

void add_progress_flag(CommandSpec& sub, bool* given) {
  sub.flag_callback(
      "--progress",
      [given] {
        force_progress(true);
        if (given) *given = true;
      },
      help("--progress", ""));
}

void add_renamed_option(CommandSpec& sub, const std::string& old_name,
                        const std::string& new_name) {
  sub.renamed(old_name, new_name);
}

}  // namespace pxflow::cli
