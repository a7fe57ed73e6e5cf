#include "path_options.hpp"

#include <filesystem>

#include "file_inputs.hpp"
#include "option_spec.hpp"

namespace pxflow::cli {

const char* path_kind_name(PathKind kind) {
  switch (kind) {
    case PathKind::InputFile:
      return "input-file";
    case PathKind::InputFolder:
      return "input-folder";
    case PathKind::InputSource:
      return "input-source";
    case PathKind::OutputFile:
      return "output-file";
    case PathKind::OutputFolder:
      return "output-folder";
    case PathKind::OwnedFolder:
      return "owned-folder";
    case PathKind::UpdatedFile:
      return "updated-file";
  }
  return "?";
}

void note_given_inputs(const CommandSpec& sub) {
  for (const OptionSpec& option : sub.options) {
    const auto& d = option.path;
    if (!d || option.count() == 0) continue;
    for (const std::string& value : option.results) {
      std::error_code ec;
      const bool folder = std::filesystem::is_directory(value, ec);
      if (d->kind == PathKind::InputFile)
        note_input(value);
      else if (d->kind == PathKind::InputFolder || (d->kind == PathKind::InputSource && folder))
        note_input_folder(option.name(), value);
      else if (d->kind == PathKind::InputSource)
        note_input(value);
    }
  }
}

}  // namespace pxflow::cli
