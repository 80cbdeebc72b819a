#pragma once
/// Conversions between double and float that keep samples inside [0, 1).
#include <algorithm>

#include "stratum/util/host_device.hpp"

namespace stratum {

inline constexpr double one_minus_epsilon_double = 0x1.fffffffffffffp-1;
inline constexpr float one_minus_epsilon_float = 0x1.fffffep-1f;

/// Rounds a double in [0, 1) to a float, never reaching 1 (round-to-nearest
/// could turn 1 - 2^-30 into 1.0f).
STRATUM_HOST_DEVICE constexpr float to_unit_float(double value) noexcept {
  const float rounded = static_cast<float>(value);
  return one_minus_epsilon_float < rounded ? one_minus_epsilon_float : rounded;  // std::min, by value
}

/// A sample converted to the caller's precision.
template <class Real>
STRATUM_HOST_DEVICE constexpr Real to_unit(double value) noexcept {
  if constexpr (sizeof(Real) == sizeof(float)) return to_unit_float(value);
  else return value;
}

}  // namespace stratum
