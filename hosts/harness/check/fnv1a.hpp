// FNV-1a, 64 bits: fingerprints of a campaign's inputs and seeds made from a case's name, not a
// defence against forgery.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace pxflow {

class Fnv1a {
 public:
  static constexpr std::uint64_t kOffsetBasis = 14695981039346656037ull;
  explicit Fnv1a(std::uint64_t start = kOffsetBasis) : h_(start) {}

  void add(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 1099511628211ull;
  }
  std::uint64_t value() const { return h_; }
  std::string hex() const {
    char b[17];
    std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h_));
    return b;
  }

 private:
  std::uint64_t h_;
};

}  // namespace pxflow
