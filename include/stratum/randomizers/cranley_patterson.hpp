#pragma once
/// Cranley–Patterson rotation (Cranley, Patterson 1976, "Randomization of
/// number theoretic methods for multiple integration"): add one random vector
/// u to every point, modulo 1. Each point becomes uniform, so estimates are
/// unbiased; lattices stay (shifted) lattices and every 1D projection keeps
/// its stratification into N equal intervals, but the elementary intervals of
/// digital nets are not preserved (use a digital randomizer for those).
#include <cstdint>

#include "stratum/util/hash.hpp"
#include "stratum/util/host_device.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

class CranleyPattersonRotation {
 public:
  STRATUM_HOST_DEVICE explicit constexpr CranleyPattersonRotation(std::uint64_t seed) noexcept : seed_(seed) {}

  /// The shift of dimension dim: uniform in [0, 1), a function of (seed, dim).
  STRATUM_HOST_DEVICE constexpr double shift(unsigned dim) const noexcept {
    return uniform01<double>(hash64(seed_, 0x43505f524f54ULL), dim);
  }

  /// (value + shift(dim)) mod 1, kept inside [0, 1).
  template <class Real = double>
  STRATUM_HOST_DEVICE constexpr Real operator()(double value, unsigned dim) const noexcept {
    return rotate<Real>(value, shift(dim));
  }

  /// (value + shift) mod 1, kept inside [0, 1): operator() with the shift computed once by the caller.
  template <class Real = double>
  STRATUM_HOST_DEVICE static constexpr Real rotate(double value, double shift) noexcept {
    double rotated = value + shift;
    if (rotated >= 1.0) rotated -= 1.0;
    return to_unit<Real>(rotated < one_minus_epsilon_double ? rotated : one_minus_epsilon_double);
  }

 private:
  std::uint64_t seed_;
};

}  // namespace stratum
