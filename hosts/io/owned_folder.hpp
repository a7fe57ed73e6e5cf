// A folder pxflow makes and owns (report --out, vectors --out, compare --out; OutputPlan's
// make_folder): it must be missing (it is made), empty, or hold the manifest an earlier run of
// the same command left there (the names of the files it wrote, one per line). Anything else is
// refused before any work, so that no file of a user's is ever replaced. A run lists what it
// wrote in the manifest; the files an earlier run listed that this one may write but did not are
// removed, so the folder holds one run's files, never a mix.
#pragma once
#include <string>
#include <vector>

namespace pxflow {

// Throws InputError when `dir` exists and is neither empty nor holds `manifest`.
void check_owned_folder(const std::string& option, const std::string& dir,
                        const std::string& manifest);

// The file names the manifest in `dir` lists (none when it has none).
std::vector<std::string> manifest_names(const std::string& dir, const std::string& manifest);

// The manifest's text for `names`.
std::string manifest_text(const std::vector<std::string>& names);

// Removes each of `previous` that is among `may_write` and not among `written`, when it is a
// regular file (a hand-edited manifest cannot delete anything else).
void remove_unwritten(const std::string& dir, const std::vector<std::string>& previous,
                      const std::vector<std::string>& may_write,
                      const std::vector<std::string>& written);

}  // namespace pxflow
