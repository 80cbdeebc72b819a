#include "seed_statistics.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include "stratum/util/error.hpp"

namespace stratum::report {

std::string format_interval(const RatioInterval& interval) {
  const FormattedInterval text = format_alike(interval.estimate, interval.low, interval.high);
  return fmt::format("{} ({:g}% CI {}–{})", text.estimate, 100 * interval.confidence, text.low, text.high);
}

std::string format_factor(const RatioInterval& interval) {
  const FormattedInterval text = format_alike(interval.estimate, interval.low, interval.high);
  return fmt::format("{}× ({:g}% CI {}–{})", text.estimate, 100 * interval.confidence, text.low, text.high);
}

}  // namespace stratum::report
