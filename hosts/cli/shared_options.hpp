// The options several commands take, declared once: one spelling, one meaning, one help text and
// one default (stated per command where a command must differ). Every command adds them through
// the add_* functions below; the README's table of shared options is shared_options_markdown()
// (tests/cli checks it).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "option_spec.hpp"

namespace pxflow::cli {

struct SharedOption {
  std::string name;      // "--threads"
  std::string value;     // "N"; empty for a flag
  std::string meaning;   // the help text
  std::string defaults;  // what it is when not given, per command where they differ
};

const std::vector<SharedOption>& shared_options();

// The README's table: | option | meaning | default |, one row per shared option.
std::string shared_options_markdown();

// `detail` (optional) is appended to the shared help for what only this command adds.
OptionSpec& add_backend_option(CommandSpec& sub, std::string& backend,
                               const std::string& detail = "");
OptionSpec& add_backends_option(CommandSpec& sub, std::string& backends,
                                const std::string& detail = "");
OptionSpec& add_threads_option(CommandSpec& sub, int& threads, const std::string& detail = "");
OptionSpec& add_device_option(CommandSpec& sub, std::string& device);
OptionSpec& add_json_option(CommandSpec& sub, std::string& path, const std::string& detail = "");
OptionSpec& add_data_option(CommandSpec& sub, std::string& dir, const std::string& detail = "");
OptionSpec& add_seed_option(CommandSpec& sub, std::uint64_t& seed, const std::string& detail = "");
// --progress; `given` (optional) is also set when it is given.
void add_progress_flag(CommandSpec& sub, bool* given = nullptr);

// An old spelling of this command's option, now refused with one line naming the new one
// (`accuracy --pairs 40`: "--pairs: renamed: give --cases"). Hidden from --help.
void add_renamed_option(CommandSpec& sub, const std::string& old_name, const std::string& new_name);

}  // namespace pxflow::cli
