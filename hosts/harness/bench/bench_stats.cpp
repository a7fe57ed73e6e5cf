#include "bench_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pxflow {

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

std::pair<double, double> median_ci95(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const double n = static_cast<double>(v.size()), half = 1.959964 * std::sqrt(n) / 2;
  // 1-based ranks j and k with P(X_(j) <= median <= X_(k)) of about 95 %.
  const long j = std::max(1L, static_cast<long>(std::floor(n / 2 - half)));
  const long k =
      std::min(static_cast<long>(v.size()), static_cast<long>(std::ceil(n / 2 + half)) + 1);
  return {v[static_cast<std::size_t>(j - 1)], v[static_cast<std::size_t>(k - 1)]};
}

bool is_noisy(double median, double ci_low, double ci_high, double min) {
  return ci_high - ci_low > kNoisyCiWidth * median || median > kNoisyMedianOverMin * min;
}

double mann_whitney_p(std::span<const double> a, std::span<const double> b) {
  const double n1 = static_cast<double>(a.size()), n2 = static_cast<double>(b.size());
  if (a.size() < 2 || b.size() < 2) return 1.0;
  std::vector<std::pair<double, int>> all;
  for (double x : a) all.push_back({x, 0});
  for (double x : b) all.push_back({x, 1});
  std::sort(all.begin(), all.end());
  // Mid-ranks for ties; the tie term of the variance.
  double rank_sum_a = 0, ties = 0;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i;
    while (j < all.size() && all[j].first == all[i].first) ++j;
    const double t = static_cast<double>(j - i), mid_rank = (static_cast<double>(i + j) + 1) / 2;
    for (std::size_t k = i; k < j; ++k)
      if (all[k].second == 0) rank_sum_a += mid_rank;
    ties += t * t * t - t;
    i = j;
  }
  const double u = rank_sum_a - n1 * (n1 + 1) / 2, n = n1 + n2;
  const double variance = n1 * n2 / 12 * ((n + 1) - ties / (n * (n - 1)));
  if (variance <= 0) return 1.0;
  // Continuity correction, as scipy's default.
  const double z = (std::abs(u - n1 * n2 / 2) - 0.5) / std::sqrt(variance);
  return std::min(1.0, std::erfc(std::max(0.0, z) / std::sqrt(2.0)));
}

RatioInterval ratio_interval95(std::span<const double> a, std::span<const double> b) {
  std::vector<double> d;
  for (double y : b)
    for (double x : a) d.push_back(std::log(y) - std::log(x));
  RatioInterval r;
  if (d.empty()) return r;
  r.ratio = std::exp(median_of(d));
  std::sort(d.begin(), d.end());
  const double n1 = static_cast<double>(a.size()), n2 = static_cast<double>(b.size());
  // The rank of the lower end: N/2 - z sqrt(n1 n2 (n1 + n2 + 1) / 12), rounded down (the
  // normal approximation; at 5 and 5 it gives the exact table's 3).
  const double c = std::floor(n1 * n2 / 2 - 1.959964 * std::sqrt(n1 * n2 * (n1 + n2 + 1) / 12));
  r.high = std::numeric_limits<double>::infinity();
  if (c < 1) return r;
  const auto k = static_cast<std::size_t>(c);
  r.low = std::exp(d[k - 1]);
  r.high = std::exp(d[d.size() - k]);
  r.bounded = true;
  return r;
}

}  // namespace pxflow
