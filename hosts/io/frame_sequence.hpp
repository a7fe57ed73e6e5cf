// The frames of `pxflow flow SOURCE`, one after another: a video file, a folder of frames or a
// glob (sorted by name), raw frames back to back in a file or on standard input (with --size);
// and the pairs of a list file (`--pairs LIST`). Every bad input is an InputError naming it.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frame.hpp"
#include "frame_io.hpp"

namespace pxflow {

struct NamedFrame {
  std::string name;  // a file's path, or "vtest.avi#12", "-#3" for the 4th raw frame on stdin
  Frame frame;
};

class FrameSequence {
 public:
  virtual ~FrameSequence() = default;
  // The next frame; false at the end.
  virtual bool next(NamedFrame& out) = 0;
  // The files the frames come from (outputs must not overwrite them).
  virtual std::vector<std::string> files() const = 0;
};

// What SOURCE is, decided in this order: "-" standard input (raw, needs `raw_size`); a folder
// (its regular files whose names do not start with '.', sorted; with `raw_size` every file is a
// raw frame, else the image files by extension); a pattern with * ? or [ (glob(3), sorted); a
// file: raw frames back to back with `raw_size`, else a video (OpenCV videoio).
std::unique_ptr<FrameSequence> open_frame_sequence(const std::string& source,
                                                   std::optional<FrameSize> raw_size);

// The pairs of a list file: one pair per line, "PREV NEXT" separated by white space (a path with
// spaces in double quotes); empty lines and lines starting with '#' are skipped; relative paths
// are relative to the list file's folder (to the working directory for a list through a pipe).
// `option` (--pairs, --from) starts every error line.
std::vector<std::pair<std::string, std::string>> read_pair_list(const std::string& option,
                                                                const std::string& path);

}  // namespace pxflow
