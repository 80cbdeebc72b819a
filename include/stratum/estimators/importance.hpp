#pragma once
/// The importance-sampling estimator (lecture §3): draw X ~ p and average
/// Y = f(X)/p(X); E[Y] = ∫ f whenever p > 0 wherever f ≠ 0, and V[Y] = 0 when
/// p ∝ f (Kahn and Marshall 1953, "Methods of reducing sample size in Monte
/// Carlo computations"; Veach 1997, thesis §2.5.2). Works for any (sample,
/// pdf) pair, e.g. the output of a warp (src/registry/include/stratum/warp_registry.hpp).
#include <cmath>
#include <cstddef>
#include <span>
#include <string>

#include "stratum/estimators/running_stats.hpp"
#include "stratum/util/error.hpp"

namespace stratum::estimators {

/// f(x)/p(x) for one sample. A sample with f = 0 contributes 0 whatever its
/// density (p = 0 there is legitimate: the sampler never draws it, or a warp
/// reports 0 outside its domain). p ≤ 0 with f ≠ 0 cannot come from sampling
/// p, so the caller's contract is broken; the result is then +inf or NaN,
/// which the batch functions below reject up front.
constexpr double importance_weighted(double f_value, double pdf) noexcept { return f_value == 0 ? 0.0 : f_value / pdf; }

/// Accumulates f(X_i)/p(X_i); estimate() is the mean, standard_error() its
/// standard error. add() is noexcept: the per-sample path.
class ImportanceEstimator {
 public:
  void add(double f_value, double pdf) noexcept { stats_.add(importance_weighted(f_value, pdf)); }
  void merge(const ImportanceEstimator& other) noexcept { stats_.merge(other.stats_); }
  double estimate() const noexcept { return stats_.mean(); }
  /// Variance of one weighted sample f/p (0 to rounding when p ∝ f).
  double variance() const noexcept { return stats_.variance(); }
  double standard_error() const noexcept { return stats_.standard_error(); }
  const RunningStats& stats() const noexcept { return stats_; }

 private:
  RunningStats stats_;
};

/// The estimator over paired arrays f_values[i] = f(X_i), pdfs[i] = p(X_i).
/// Checks every pair first (same length, at least one pair, finite values,
/// p > 0 where f ≠ 0), naming the index of the first bad one.
inline ImportanceEstimator importance_estimate(std::span<const double> f_values, std::span<const double> pdfs) {
  require(f_values.size() == pdfs.size(), "pdfs", pdfs.size(),
          "needs one density per value (" + std::to_string(f_values.size()) + " values)");
  require(!f_values.empty(), "n", 0, "needs at least one sample");
  for (std::size_t i = 0; i < f_values.size(); ++i) {
    require(std::isfinite(f_values[i]), "f[" + std::to_string(i) + "]", f_values[i], "must be finite");
    require(std::isfinite(pdfs[i]) && pdfs[i] >= 0, "pdf[" + std::to_string(i) + "]", pdfs[i],
            "must be finite and non-negative");
    require(f_values[i] == 0 || pdfs[i] > 0, "pdf[" + std::to_string(i) + "]", pdfs[i],
            "must be positive where f is not zero (that sample cannot have been drawn from p)");
  }
  ImportanceEstimator estimator;
  for (std::size_t i = 0; i < f_values.size(); ++i) estimator.add(f_values[i], pdfs[i]);
  return estimator;
}

}  // namespace stratum::estimators
