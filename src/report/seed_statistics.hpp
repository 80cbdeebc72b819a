#pragma once
/// The report's words for statistics across seeds (analysis/paired_statistics.hpp:
/// paired ratio intervals, medians, means with their standard errors).
#include <string>

#include "stratum/analysis/paired_statistics.hpp"

namespace stratum::report {

using analysis::mean_and_error;
using analysis::MeanError;
using analysis::median;
using analysis::noise_percent;
using analysis::paired_ratio_interval;
using analysis::RatioInterval;

/// "1.23 (95% CI 1.10–1.38)".
std::string format_interval(const RatioInterval& interval);

/// "15.8× (95% CI 15.6–16.0)": the same as a factor, for running text.
std::string format_factor(const RatioInterval& interval);

}  // namespace stratum::report
