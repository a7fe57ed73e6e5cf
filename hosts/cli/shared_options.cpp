#include "shared_options.hpp"

#include <stdexcept>

#include "list_option.hpp"
#include "path_options.hpp"
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

CLI::Option* add(CLI::App& sub, std::string_view name, auto& variable, const std::string& detail) {
  return sub.add_option(std::string(name), variable, help(name, detail))
      ->type_name(shared_option(name).value);
}

}  // namespace

CLI::Option* add_backend_option(CLI::App& sub, std::string& backend, const std::string& detail) {
  return add(sub, "--backend", backend, detail);
}

CLI::Option* add_backends_option(CLI::App& sub, std::string& backends, const std::string& detail) {
  return add(sub, "--backends", backends, detail);
}

CLI::Option* add_threads_option(CLI::App& sub, int& threads, const std::string& detail) {
  return add(sub, "--threads", threads, detail)->check(CLI::Range(0, 1024));
}

CLI::Option* add_device_option(CLI::App& sub, std::string& device) {
  return add(sub, "--device", device, "");
}

CLI::Option* add_json_option(CLI::App& sub, std::string& path, const std::string& detail) {
  return declare_path(add(sub, "--json", path, detail), PathKind::OutputFile, ".json");
}

CLI::Option* add_data_option(CLI::App& sub, std::string& dir, const std::string& detail) {
  return declare_path(add(sub, "--data", dir, detail), PathKind::InputFolder);
}

CLI::Option* add_seed_option(CLI::App& sub, std::uint64_t& seed, const std::string& detail) {
  return add(sub, "--seed", seed, detail)->check(seed_value());
}

void add_progress_flag(CLI::App& sub, bool* given) {
  sub.add_flag_callback(
      "--progress",
      [given] {
        force_progress(true);
        if (given) *given = true;
      },
      help("--progress", ""));
}

void add_renamed_option(CLI::App& sub, const std::string& old_name, const std::string& new_name) {
  // Thrown from the callback with its own name: CLI11 names a hidden option's errors "".
  sub.add_option_function<std::string>(old_name,
                                       [old_name, new_name](const std::string&) {
                                         throw CLI::ValidationError(old_name,
                                                                    "renamed: give " + new_name);
                                       })
      ->expected(0, 1)  // alone too: CLI11's "needs a value" would name it ""
      ->group("");
}

}  // namespace pxflow::cli
