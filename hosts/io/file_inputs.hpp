// Every file and folder this process reads, noted where it is read: by hosts/io's readers
// (input_file, frame_io, frame_sequence, video_file) and, before a command runs, by the CLI for
// every option its table declares as an input (hosts/cli/path_options.hpp). OutputPlan refuses an
// output that is one of them, or lies inside a folder read, whoever declared it: a command cannot
// forget an input, since reading it is what declares it.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace pxflow {

// A file read ("-", standard input, and "" are not files and are ignored).
void note_input(const std::string& path);

// A folder read inside (a folder of frames, --data): nothing may be written in it. `option`
// names it in messages ("--data", "SOURCE").
void note_input_folder(const std::string& option, const std::string& dir);

const std::vector<std::string>& inputs_noted();
const std::vector<std::pair<std::string, std::string>>& input_folders_noted();  // option, folder

}  // namespace pxflow
