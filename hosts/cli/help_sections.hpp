// The paragraphs every --help ends with, and so every man page: help2man makes sections of
// "Environment:" and "Examples:", cmake/PxflowManPages.cmake turns "Exit status:" into EXIT
// STATUS. Each fact has its one place: the exit codes here (app.cpp returns them), each
// environment variable beside the code that reads it (a family's `environment`, or
// kCoreEnvironment), each example in its command's file (Command::examples).
#pragma once
#include <string>
#include <vector>

#include "commands.hpp"

namespace pxflow::cli {

// "Exit status:", "Environment:" (what every family reads, and the core's variables) and
// "Examples:" (`examples`), in that order: help2man puts everything after "Environment:" into
// ENVIRONMENT until "Examples:".
std::string help_sections(const std::vector<std::string>& examples);

// pxflow --help's examples: the first example of each command.
std::vector<std::string> first_examples(const std::vector<Command>& commands);

}  // namespace pxflow::cli
