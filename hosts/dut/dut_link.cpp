#include "dut_link.hpp"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "guarded_child.hpp"
#include "interrupt.hpp"

namespace pxflow::dut {
namespace {

std::string os_error(const std::string& what) { return what + ": " + std::strerror(errno); }

void set_nonblocking(int fd) { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK); }

// Waits for `events` on fd until the deadline, in slices short enough to notice Ctrl-C.
// Returns false at the deadline.
bool wait_fd(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    stop_if_interrupted("waiting for the device");
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, events, 0};
    const int r = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 100)));
    if (r > 0) return true;  // ready, or an error/hang-up the next read or write reports
    if (r < 0 && errno != EINTR) throw LinkError(os_error("poll"));
  }
}

// A pair of file descriptors (the same one for sockets and ttys).
class FdLink : public Link {
 public:
  FdLink(int in, int out, std::string garbage_hint)
      : in_(in), out_(out), garbage_hint_(std::move(garbage_hint)) {
    set_nonblocking(in_);
    set_nonblocking(out_);
  }
  ~FdLink() override { close_fds(); }
  std::string garbage_hint() const override { return garbage_hint_; }

  void write(std::span<const std::uint8_t> bytes, Clock::time_point deadline) override {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(out_, bytes.data() + done, bytes.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
        if (!wait_fd(out_, POLLOUT, deadline))
          throw LinkError("the device does not take its input (the link stayed full)");
        continue;
      }
      throw LinkError(closed_reason(os_error("write")));
    }
  }

  std::size_t read(std::uint8_t* buf, std::size_t max, Clock::time_point deadline) override {
    for (;;) {
      const ssize_t n = ::read(in_, buf, max);
      if (n > 0) return static_cast<std::size_t>(n);
      if (n == 0) throw LinkError(closed_reason("the link was closed"));
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) throw LinkError(closed_reason(os_error("read")));
      if (!wait_fd(in_, POLLIN, deadline)) return 0;
    }
  }

 protected:
  // What a closed link means (an exec link says how the child ended).
  virtual std::string closed_reason(const std::string& what) { return what; }
  void close_fds() {
    if (out_ >= 0 && out_ != in_) ::close(out_);
    if (in_ >= 0) ::close(in_);
    in_ = out_ = -1;
  }

 private:
  int in_, out_;
  std::string garbage_hint_;
};

class ExecLink : public FdLink {
 public:
  // `in` and `out` are pxflow's ends of the pipes whose other ends `child` got.
  ExecLink(int in, int out, std::unique_ptr<GuardedChild> child, std::string command)
      : FdLink(in, out,
               "does the program write only protocol frames to its stdout? (anything else goes "
               "to stderr)"),
        child_(std::move(child)),
        command_(std::move(command)) {}
  ~ExecLink() override {
    close_fds();  // the device sees the end of its input and may exit by itself
    child_->exited(std::chrono::milliseconds(1000));
    child_->stop();  // the group: whatever the command started goes too
  }

 protected:
  std::string closed_reason(const std::string& what) override {
    // It usually exits right after closing.
    if (!child_->exited(std::chrono::milliseconds(200)))
      return what + " (" + command_ + " still runs)";
    const int status = child_->status();
    if (WIFEXITED(status))
      return command_ + " exited with status " + std::to_string(WEXITSTATUS(status));
    return command_ + " was killed by signal " + std::to_string(WTERMSIG(status));
  }

 private:
  std::unique_ptr<GuardedChild> child_;
  std::string command_;
};

}  // namespace

std::unique_ptr<Link> open_exec_link(const std::vector<std::string>& args) {
  PipedChild c;
  try {
    c = start_piped_child(args);
  } catch (const SpawnError& e) {
    throw LinkError(e.what());
  }
  return std::make_unique<ExecLink>(c.from_child, c.to_child, std::move(c.child), args[0]);
}

std::unique_ptr<Link> open_tcp_link(const std::string& host, const std::string& port,
                                    Clock::time_point deadline) {
  signal(SIGPIPE, SIG_IGN);
  addrinfo hints{};
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int r = getaddrinfo(host.c_str(), port.c_str(), &hints, &found); r != 0)
    throw LinkError("cannot resolve " + host + ": " + gai_strerror(r));
  std::string why = "no address";
  for (addrinfo* a = found; a; a = a->ai_next) {
    const int s = socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (s < 0) continue;
    set_nonblocking(s);
    int r = connect(s, a->ai_addr, a->ai_addrlen);
    if (r != 0 && errno == EINPROGRESS && wait_fd(s, POLLOUT, deadline)) {
      int err = 0;
      socklen_t len = sizeof err;
      getsockopt(s, SOL_SOCKET, SO_ERROR, &err, &len);
      errno = err;
      r = err == 0 ? 0 : -1;
    } else if (r != 0 && errno == EINPROGRESS) {
      errno = ETIMEDOUT;
    }
    if (r == 0) {
      freeaddrinfo(found);
      const int one = 1;
      setsockopt(s, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);  // small frames, answered at once
      return std::make_unique<FdLink>(s, s, "is a pxflow device listening on that port?");
    }
    why = std::strerror(errno);
    ::close(s);
  }
  freeaddrinfo(found);
  throw LinkError("cannot connect to " + host + ":" + port + ": " + why);
}

namespace {

struct BaudRate {
  int baud;
  speed_t code;
};
constexpr BaudRate kBauds[] = {{9600, B9600},       {19200, B19200},     {38400, B38400},
                               {57600, B57600},     {115200, B115200},   {230400, B230400},
                               {460800, B460800},   {921600, B921600},   {1000000, B1000000},
                               {1500000, B1500000}, {2000000, B2000000}, {3000000, B3000000},
                               {4000000, B4000000}};

}  // namespace

bool serial_baud_supported(int baud) {
  for (const auto& b : kBauds)
    if (b.baud == baud) return true;
  return false;
}

std::string serial_bauds_text() {
  std::string s;
  for (const auto& b : kBauds) s += (s.empty() ? "" : ", ") + std::to_string(b.baud);
  return s;
}

std::unique_ptr<Link> open_serial_link(const std::string& path, int baud) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw LinkError(os_error("cannot open " + path));
  termios t{};
  if (tcgetattr(fd, &t) != 0) {
    const std::string why = os_error(path + " is not a serial port (tcgetattr)");
    ::close(fd);
    throw LinkError(why);
  }
  cfmakeraw(&t);  // 8 data bits, no parity, no echo, no line editing, no CR/LF translation
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~(CSTOPB | CRTSCTS);  // one stop bit, no hardware flow control
  t.c_iflag &= ~(IXON | IXOFF | IXANY);
  t.c_cc[VMIN] = 1;  // with O_NONBLOCK: EAGAIN when nothing came, 0 only at a hang-up
  t.c_cc[VTIME] = 0;
  for (const auto& b : kBauds)
    if (b.baud == baud) cfsetispeed(&t, b.code), cfsetospeed(&t, b.code);
  if (tcsetattr(fd, TCSANOW, &t) != 0) {
    const std::string why = os_error(path + ": cannot set raw mode at " + std::to_string(baud));
    ::close(fd);
    throw LinkError(why);
  }
  tcflush(fd, TCIOFLUSH);  // whatever the device printed before we came is not an answer
  return std::make_unique<FdLink>(fd, fd, "wrong port or baud rate?");
}

}  // namespace pxflow::dut
