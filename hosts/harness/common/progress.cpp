#include "progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace pxflow {
namespace {

bool g_forced = false;

}  // namespace

void force_progress(bool on) { g_forced = on; }

void progress(const std::string& text) {
  static const bool tty = isatty(2);
  if (tty) {
    std::fprintf(stderr, "\r\033[K%s", text.c_str());
    return;
  }
  if (!g_forced || text.empty()) return;
  using clock = std::chrono::steady_clock;
  static clock::time_point last{};
  const auto now = clock::now();
  if (now - last < std::chrono::milliseconds(500)) return;
  last = now;
  std::fprintf(stderr, "%s\n", text.c_str());
}

}  // namespace pxflow
