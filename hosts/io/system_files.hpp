// The files pxflow opens that are neither a user's inputs nor its outputs, opened here so that
// hosts/io stays the one place a file is opened (tests/cli's io_one_door lint): the system's own
// files (/proc, /etc/os-release), /dev/null, and a file this process wrote and committed.
#pragma once
#include <string>

namespace pxflow {

// The whole text of a file of the system's (/proc/loadavg, /etc/os-release): "" when it cannot
// be read. Never an input of the plan: pxflow never writes there.
std::string read_system_file(const std::string& path);

// A new descriptor on /dev/null (close-on-exec), or -1.
int open_null_device(bool for_writing);

// The bytes of a file this process wrote through its OutputPlan and committed (a report's
// picture that its HTML inlines); "" when it cannot be read.
std::string read_own_output(const std::string& path);

}  // namespace pxflow
