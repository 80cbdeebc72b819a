#pragma once
/// Statistics across independent repeats (seeds) of a measurement: a ratio
/// of two positive quantities measured in pairs (the same seed for both)
/// gets a Student-t interval on the mean of the log ratios, exp'd back (a
/// geometric-mean ratio; the log makes the interval of b/a the reciprocal
/// of that of a/b, and tames the skew of an MSE). Timings are summarized by
/// their median; a time ratio whose interval contains 1 is unresolved: the
/// timing noise exceeds the difference.
#include <vector>

namespace stratum::analysis {

/// A positive ratio with its confidence interval from paired repeats.
struct RatioInterval {
  double estimate = 0;       ///< exp(mean of log(a_k / b_k)): the geometric mean of the ratios
  double low = 0, high = 0;  ///< exp(mean ± t·s/√K); equal to the estimate for K = 1
  unsigned count = 0;        ///< K pairs
  double confidence = 0.95;
  bool contains(double value) const { return low <= value && value <= high; }
};

/// The t interval (K − 1 degrees of freedom) on log(numerator_k /
/// denominator_k) over the K pairs; every value must be positive and finite.
RatioInterval paired_ratio_interval(const std::vector<double>& numerator, const std::vector<double>& denominator,
                                    double confidence = 0.95);

/// The half-width of a ratio interval around 1, as a percentage: how far
/// apart two timings may be and still be called equal ("±7%").
double noise_percent(const RatioInterval& interval);

/// The median (mean of the middle two for an even count); NaN when empty.
double median(std::vector<double> values);

/// The mean and its standard error (sample standard deviation / √K; 0 for K = 1).
struct MeanError {
  double mean = 0, standard_error = 0;
};
MeanError mean_and_error(const std::vector<double>& values);

}  // namespace stratum::analysis
