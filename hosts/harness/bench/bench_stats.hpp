// The statistics of the bench's samples (docs/harness.md, "Statistics"): the median, its
// distribution-free confidence interval, the noise rule, and the Mann-Whitney U test and the
// ratio's interval that `pxflow compare` computes over two rows' process medians.
#pragma once
#include <span>
#include <utility>
#include <vector>

namespace pxflow {

double median_of(std::vector<double> v);  // v not empty

// The 95 % confidence interval of the median of `v` from its order statistics (the binomial's
// normal approximation), so no distribution is assumed; with few samples it widens to min..max.
std::pair<double, double> median_ci95(std::vector<double> v);

// A point is noisy when its median's 95 % interval is wider than kNoisyCiWidth of the median, or
// its median is more than kNoisyMedianOverMin times its fastest sample: rerun on a quiet machine.
inline constexpr double kNoisyCiWidth = 0.10;
inline constexpr double kNoisyMedianOverMin = 1.5;
bool is_noisy(double median, double ci_low, double ci_high, double min);

// The two-sided p-value of the Mann-Whitney U test (normal approximation with the tie
// correction, as Google Benchmark's compare.py uses scipy's): whether `a` and `b` come from one
// distribution. 1.0 when either has fewer than 2 samples or every value is tied.
double mann_whitney_p(std::span<const double> a, std::span<const double> b);

// The ratio of `b` to `a` (positive times) with its distribution-free 95 % interval: the
// Hodges-Lehmann estimate of the shift between log(b) and log(a) (the median of every difference
// log b_j - log a_i), and the interval of those differences' order statistics that inverts the
// Mann-Whitney test (Hollander and Wolfe), so that the interval excludes 1 only where the test is
// significant. With too few values for a 95 % interval (3 and 3, say) `bounded` is false and the
// interval is 0..infinity.
struct RatioInterval {
  double ratio = 1, low = 0, high = 0;
  bool bounded = false;
};
RatioInterval ratio_interval95(std::span<const double> a, std::span<const double> b);

}  // namespace pxflow
