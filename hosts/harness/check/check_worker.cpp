#include "check_worker.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "errors.hpp"
#include "exactness.hpp"
#include "grid.hpp"
#include "guarded_run.hpp"
#include "interrupt.hpp"
#include "registry.hpp"
#include "system_files.hpp"

namespace pxflow::worker {
namespace {

// Blocking I/O of the worker's side: pxflow watches the clock.
bool read_all(int fd, std::uint8_t* to, std::size_t n) {
  while (n > 0) {
    const ssize_t r = ::read(fd, to, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    to += r, n -= static_cast<std::size_t>(r);
  }
  return true;
}

void write_all(int fd, const std::vector<std::uint8_t>& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t r = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) _exit(0);  // pxflow is gone: nothing is left to answer
    done += static_cast<std::size_t>(r);
  }
}

void answer(int fd, Type t, const std::vector<std::uint8_t>& payload) {
  write_all(fd, frame_message(t, payload));
}

Hello open_row(const std::string& name, const BackendOptions& options,
               std::unique_ptr<Backend>& backend) {
  Hello h;
  try {
    OpenedBackend opened = open_backend(find_backend(name), options);
    backend = std::move(opened.backend);
    if (!backend) return {Hello::State::kCannotRun, opened.why_not, {}, {}};
    const Backend::Description d = backend->describe();
    h.implementation = d.implementation.empty() ? name : d.implementation;
    h.device = device_or_host(d);
  } catch (const InputError& e) {
    return {Hello::State::kInputError, e.what(), {}, {}};
  } catch (const std::exception& e) {
    return {Hello::State::kCannotRun, std::string("set-up failed: ") + e.what(), {}, {}};
  }
  return h;
}

std::vector<std::uint8_t> run_one(Backend& backend, const DecodedCase& c, Type& type) {
  // A case of no pairs is a question: the answer is unsupported()'s, empty when supported.
  if (std::string why = backend.unsupported(c.params); !why.empty() || c.frames.empty()) {
    type = Type::kNotApplicable;
    return Writer().text(why).take();
  }
  const std::size_t records = poi_count(c.params) * (c.frames.size() / 2);
  GuardedRun guarded(c.frames, sentinel_records(records));
  Done d;
  const auto t0 = Clock::now();
  try {
    backend.run(guarded.pairs(), c.params, guarded.output(), d.counts);
  } catch (const std::exception& e) {
    type = Type::kError;
    return Writer().text(e.what()).take();
  }
  d.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  const auto out = guarded.output();
  d.records.assign(out.begin(), out.end());
  d.guard_note = guarded.check_guards();
  type = Type::kDone;
  return encode(d);
}

// Builds the case's kernels (its frames are none): kPrepared with the seconds it took.
std::vector<std::uint8_t> prepare_one(Backend& backend, const DecodedCase& c, Type& type) {
  if (std::string why = backend.unsupported(c.params); !why.empty()) {
    type = Type::kNotApplicable;
    return Writer().text(why).take();
  }
  const auto t0 = Clock::now();
  try {
    backend.prepare(c.params);
  } catch (const std::exception& e) {
    type = Type::kError;
    return Writer().text(e.what()).take();
  }
  type = Type::kPrepared;
  return Writer().pod(std::chrono::duration<double>(Clock::now() - t0).count()).take();
}

std::string os_error(const char* what) { return std::string(what) + ": " + std::strerror(errno); }

}  // namespace

int serve(const std::string& row, const BackendOptions& options) {
  // The protocol gets descriptors of its own; what a backend prints to stdout goes to stderr,
  // never into a reply.
  const int in = fcntl(0, F_DUPFD_CLOEXEC, 3), out = fcntl(1, F_DUPFD_CLOEXEC, 3);
  dup2(2, 1);
  const int null = open_null_device(false);
  if (null >= 0) dup2(null, 0), ::close(null);
  install_fault_reporter(out);
  std::unique_ptr<Backend> backend;
  const Hello hello = open_row(row, options, backend);
  answer(out, Type::kHello, encode(hello));
  if (!backend) return 0;
  for (;;) {
    std::uint8_t header[kHeaderBytes];
    if (!read_all(in, header, sizeof header)) return 0;  // pxflow is done with this row
    std::uint32_t length;
    std::memcpy(&length, header + 1, sizeof length);
    std::vector<std::uint8_t> payload(length);
    const auto asked = static_cast<Type>(header[0]);
    if ((asked != Type::kCase && asked != Type::kPrepare) || !read_all(in, payload.data(), length))
      return 3;
    Type type{};
    const DecodedCase c = decode_case(payload);
    const std::vector<std::uint8_t> reply =
        asked == Type::kPrepare ? prepare_one(*backend, c, type) : run_one(*backend, c, type);
    answer(out, type, reply);
  }
}

WorkerProcess::WorkerProcess(const std::vector<std::string>& argv)
    : child_(start_piped_child(argv)) {
  fcntl(child_.to_child, F_SETFL, fcntl(child_.to_child, F_GETFL) | O_NONBLOCK);
  fcntl(child_.from_child, F_SETFL, fcntl(child_.from_child, F_GETFL) | O_NONBLOCK);
}

WorkerProcess::~WorkerProcess() {
  ::close(child_.to_child);  // end of its input: the worker returns by itself
  ::close(child_.from_child);
  child_.child->exited(std::chrono::milliseconds(1000));
  child_.child->stop();
}

void WorkerProcess::ended(Reply& gone) {
  gone.kind = Reply::Kind::kDied;
  // It closed its output: it is exiting, or was killed.
  if (!child_.child->exited(std::chrono::milliseconds(5000))) {
    child_.child->stop();
    gone.text = "closed its pipe and was stopped";
    return;
  }
  gone.text = ended_text(child_.child->status());
}

// Waits for `events` until the deadline in slices short enough to notice Ctrl-C.
static bool wait_fd(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    stop_if_interrupted("waiting for a check worker");
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd, events, 0};
    const int r = poll(&p, 1, static_cast<int>(std::min<long long>(left, 100)));
    if (r > 0) return true;  // ready, or hung up: the read or write says which
    if (r < 0 && errno != EINTR) throw BackendError(os_error("poll"));
  }
}

bool WorkerProcess::send(const std::vector<std::uint8_t>& bytes, Clock::time_point deadline,
                         Reply& gone) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(child_.to_child, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      if (!wait_fd(child_.to_child, POLLOUT, deadline)) {
        child_.child->stop();
        gone.kind = Reply::Kind::kTimedOut;
        return false;
      }
    } else {
      ended(gone);  // EPIPE: it ended before reading the case
      return false;
    }
  }
  return true;
}

std::optional<Message> WorkerProcess::receive(Clock::time_point deadline, Reply& gone) {
  std::vector<std::uint8_t> got;
  std::size_t want = kHeaderBytes;
  while (got.size() < want) {
    std::uint8_t buf[65536];
    const ssize_t n = ::read(child_.from_child, buf, std::min(sizeof buf, want - got.size()));
    if (n > 0) {
      got.insert(got.end(), buf, buf + n);
      if (got.size() == kHeaderBytes) {
        std::uint32_t length;
        std::memcpy(&length, got.data() + 1, sizeof length);
        want = kHeaderBytes + length;
      }
    } else if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      if (!wait_fd(child_.from_child, POLLIN, deadline)) {
        child_.child->stop();  // its whole process group
        gone.kind = Reply::Kind::kTimedOut;
        return std::nullopt;
      }
    } else {
      ended(gone);
      return std::nullopt;
    }
  }
  return Message{static_cast<Type>(got[0]), {got.begin() + kHeaderBytes, got.end()}};
}

std::optional<Hello> WorkerProcess::hello(Clock::time_point deadline, Reply& gone) {
  const std::optional<Message> m = receive(deadline, gone);
  if (!m) return std::nullopt;
  if (m->type != Type::kHello) throw WireError("a check worker did not say hello");
  return decode_hello(m->payload);
}

Reply WorkerProcess::run(const Params& p, std::span<const FramePair> pairs,
                         Clock::time_point deadline) {
  return ask(Type::kCase, encode_case(p, pairs), deadline);
}

Reply WorkerProcess::prepare(const Params& p, Clock::time_point deadline) {
  return ask(Type::kPrepare, encode_case(p, {}), deadline);
}

Reply WorkerProcess::ask(Type type, const std::vector<std::uint8_t>& payload,
                         Clock::time_point deadline) {
  Reply r;
  if (!send(frame_message(type, payload), deadline, r)) return r;
  for (;;) {
    std::optional<Message> m = receive(deadline, r);
    if (!m) return r;
    Reader words(m->payload);
    switch (m->type) {
      case Type::kNotApplicable:
        return {Reply::Kind::kNotApplicable, words.text(), {}, {}};
      case Type::kError:
        return {Reply::Kind::kError, words.text(), {}, {}};
      case Type::kDone:
        r.done = decode_done(m->payload);
        return r;
      case Type::kPrepared:
        r.done.seconds = words.pod<double>();
        return r;
      case Type::kFault:  // its last words; the end of its pipe follows
        r.fault = words.pod<Fault>();
        break;
      default:
        throw WireError("a check worker sent an unknown message");
    }
  }
}

}  // namespace pxflow::worker
