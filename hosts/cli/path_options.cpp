#include "path_options.hpp"

#include <filesystem>
#include <map>

#include "file_inputs.hpp"

namespace pxflow::cli {
namespace {

std::map<const CLI::Option*, DeclaredPath>& declared() {
  static std::map<const CLI::Option*, DeclaredPath> table;
  return table;
}

}  // namespace

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

CLI::Option* declare_path(CLI::Option* option, PathKind kind, const std::string& suffix) {
  declared()[option] = {kind, suffix};
  return option;
}

std::optional<DeclaredPath> declared_path(const CLI::Option* option) {
  const auto it = declared().find(option);
  if (it == declared().end()) return std::nullopt;
  return it->second;
}

void note_given_inputs(const CLI::App& sub) {
  for (const CLI::Option* option : sub.get_options()) {
    const auto d = declared_path(option);
    if (!d || option->count() == 0) continue;
    for (const std::string& value : option->results()) {
      std::error_code ec;
      const bool folder = std::filesystem::is_directory(value, ec);
      if (d->kind == PathKind::InputFile)
        note_input(value);
      else if (d->kind == PathKind::InputFolder || (d->kind == PathKind::InputSource && folder))
        note_input_folder(option->get_name(), value);
      else if (d->kind == PathKind::InputSource)
        note_input(value);
    }
  }
}

}  // namespace pxflow::cli
