#pragma once
// Shared by the pattern tests: a two-sided t-test that a pattern's estimate of
// a known integral is unbiased over independent seeds.
#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace stratum::testing {

/// The integrand used across the pattern tests, exp(x_0) prod_{j>=1} (1 + x_j^2):
/// is smooth but not linear, so no stratified rule integrates it exactly.
inline double test_integrand(const double* x, unsigned d) {
  double value = std::exp(x[0]);
  for (unsigned j = 1; j < d; ++j) value *= 1.0 + x[j] * x[j];
  return value;
}
/// Its integral over [0,1)^d: (e - 1) (4/3)^(d-1).
inline double test_integral(unsigned d) { return (std::exp(1.0) - 1.0) * std::pow(4.0 / 3.0, d - 1.0); }

/// Šidák-corrected per-test level for `tests` tests at family level `family_alpha`.
inline double sidak(double family_alpha, int tests) { return 1.0 - std::pow(1.0 - family_alpha, 1.0 / tests); }

/// Q = (1/n) Σ_k x_k0 · x_k1² · exp(x_k2) over n × d row-major points (d ≥ 3):
/// smooth, not a product of equal factors, and E Q = (e − 1)/6 for uniform points.
inline double product_test_mean(const double* x, std::size_t n, std::size_t d) {
  double sum = 0;
  for (std::size_t k = 0; k < n; ++k) sum += x[k * d] * x[k * d + 1] * x[k * d + 1] * std::exp(x[k * d + 2]);
  return sum / static_cast<double>(n);
}
inline double product_test_integral() { return (std::exp(1.0) - 1) / 6; }

/// Two-sided one-sample t-test of H0: E[estimate] = truth at level alpha.
inline void expect_unbiased(const std::string& what, const std::vector<double>& estimates, double truth, double alpha) {
  const auto r = static_cast<double>(estimates.size());
  double mean = 0;
  for (double e : estimates) mean += e;
  mean /= r;
  double ss = 0;
  for (double e : estimates) ss += (e - mean) * (e - mean);
  const double sd = std::sqrt(ss / (r - 1));
  ASSERT_GT(sd, 0.0) << what;
  const double t = (mean - truth) / (sd / std::sqrt(r));
  const boost::math::students_t dist(r - 1);
  const double critical = boost::math::quantile(boost::math::complement(dist, alpha / 2));
  EXPECT_LT(std::abs(t), critical) << what << ": mean " << mean << " vs " << truth << ", t = " << t;
}

/// Estimates of test_integral(d) from `replicates` seeds; `points(seed)` returns n × d row-major values.
inline std::vector<double> estimates_over_seeds(int replicates, unsigned d,
                                                const std::function<std::vector<double>(std::uint64_t)>& points) {
  std::vector<double> estimates;
  for (int r = 0; r < replicates; ++r) {
    const std::vector<double> x = points(1000 + static_cast<std::uint64_t>(r));
    const std::size_t n = x.size() / d;
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += test_integrand(&x[i * d], d);
    estimates.push_back(sum / static_cast<double>(n));
  }
  return estimates;
}

}  // namespace stratum::testing
