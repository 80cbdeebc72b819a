#include "stratum/analysis/paired_statistics.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>

#include "stratum/util/error.hpp"

namespace stratum::analysis {

RatioInterval paired_ratio_interval(const std::vector<double>& numerator, const std::vector<double>& denominator,
                                    double confidence) {
  require(numerator.size() == denominator.size() && !numerator.empty(), "repeats", numerator.size(),
          "must be as many numerators as denominators, at least one");
  require(confidence > 0 && confidence < 1, "confidence", confidence, "must be in (0, 1)");
  std::vector<double> logs;
  for (std::size_t k = 0; k < numerator.size(); ++k) {
    require(numerator[k] > 0 && denominator[k] > 0 && std::isfinite(numerator[k]) && std::isfinite(denominator[k]),
            "ratio", fmt::format("{}/{}", numerator[k], denominator[k]), "must be of positive finite values");
    logs.push_back(std::log(numerator[k] / denominator[k]));
  }
  const MeanError m = mean_and_error(logs);
  RatioInterval interval;
  interval.count = unsigned(logs.size());
  interval.confidence = confidence;
  interval.estimate = std::exp(m.mean);
  const double t = logs.size() < 2
                       ? 0
                       : boost::math::quantile(boost::math::students_t(double(logs.size() - 1)), (1 + confidence) / 2);
  interval.low = std::exp(m.mean - t * m.standard_error);
  interval.high = std::exp(m.mean + t * m.standard_error);
  return interval;
}

double noise_percent(const RatioInterval& interval) {
  return 100 * std::max(std::abs(interval.high - 1), std::abs(1 - interval.low));
}

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t half = values.size() / 2;
  return values.size() % 2 ? values[half] : (values[half - 1] + values[half]) / 2;
}

MeanError mean_and_error(const std::vector<double>& values) {
  MeanError result;
  if (values.empty()) return result;
  double sum = 0;
  for (const double v : values) sum += v;
  result.mean = sum / double(values.size());
  if (values.size() < 2) return result;
  double squares = 0;
  for (const double v : values) squares += (v - result.mean) * (v - result.mean);
  result.standard_error = std::sqrt(squares / double(values.size() - 1) / double(values.size()));
  return result;
}

}  // namespace stratum::analysis
