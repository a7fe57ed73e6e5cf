#include "interrupt.hpp"

#include <atomic>
#include <csignal>

namespace pxflow {
namespace {

std::atomic<int> g_signal{0};

extern "C" void on_signal(int sig) {
  g_signal.store(sig);
  std::signal(sig, SIG_DFL);  // a second one ends the process at once
}

int interrupt_signal() { return g_signal.load(); }

}  // namespace

void install_interrupt_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

void stop_if_interrupted(const std::string& done) {
  if (const int sig = interrupt_signal())
    throw Interrupted(sig, std::string(sig == SIGINT ? "SIGINT" : "SIGTERM") + " after " + done);
}

}  // namespace pxflow
