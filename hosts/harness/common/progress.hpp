// Progress of long runs (check, bench, report) on stderr: a live line on a terminal, nothing
// when stderr is not one, unless asked for (--progress), then one line every half second at most.
#pragma once
#include <string>

namespace pxflow {

void force_progress(bool on);  // --progress

// Shows `text` as the current state; an empty text ends the live line.
void progress(const std::string& text);

}  // namespace pxflow
