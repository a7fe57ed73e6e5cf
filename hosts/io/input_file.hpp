// Files pxflow reads, the one way, so that every input option answers alike: a regular file or a
// stream (a pipe, a FIFO, /dev/stdin, bash's <(cat a.raw)) is read; a folder "is a directory";
// a device is refused, since a character device such as /dev/zero or /dev/urandom never ends.
// Every refusal is an InputError whose line starts with `label`: the path itself, or the option
// and the path ("--pairs LIST").
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pxflow {

// True for a pipe or FIFO (read to its end once; its size is unknown until then).
bool is_stream(const std::string& path);

// Throws InputError unless `path` is a regular file or a stream.
void require_readable_input(const std::string& label, const std::string& path);

// The whole content of `path` (checked as above; empty is an error). More than `max_bytes` is an
// InputError "LABEL: holds N bytes, WHY" (a stream: "more than N"), read no further than that.
std::vector<std::uint8_t> read_input(const std::string& label, const std::string& path,
                                     std::uint64_t max_bytes, const std::string& why);

// read(2) of up to `n` bytes that a stop signal ends: a read cut short (EINTR), and every second
// spent waiting (a FIFO, a pipe, a terminal), look at the signal flag (an Interrupted "SIGINT
// while reading LABEL") and go on waiting. read()'s result otherwise (-1: errno, never EINTR).
long read_or_stop(int fd, void* buf, std::size_t n, const std::string& label);

// open(path, O_RDONLY) that a stop signal ends (a FIFO's open waits for its writer); -1: errno.
int open_or_stop(const std::string& path, const std::string& label);

// A text input (JSON, a list of pairs): read_input with a bound no file pxflow writes comes near.
std::string read_input_text(const std::string& label, const std::string& path);

// The same for a file the command then replaces whole with its result (check --resume FILE, as
// sed -i does): checked alike, but not noted as an input, so the result may take its place.
std::string read_updated_text(const std::string& label, const std::string& path);

}  // namespace pxflow
