#pragma once
/// Kronecker (additive-recurrence, Weyl) sequences x_i = frac(s + i α) for a
/// vector α of irrationals (Weyl 1916, "Über die Gleichverteilung von Zahlen
/// mod. Eins"; Niederreiter 1992, "Random Number Generation and Quasi-Monte
/// Carlo Methods", Sec. 5.1). The default α is R_d (Roberts 2018, "The
/// unreasonable effectiveness of quasirandom sequences"): α_k = φ_d^-k,
/// k = 1 … d, with φ_d the generalized golden ratio, the positive root of
/// x^(d+1) = x + 1 (φ_1 the golden ratio, φ_2 the plastic number). In 1D the
/// N first points split the circle into gaps of at most three lengths
/// (Sós 1958, the three-gap theorem).
///
/// Arithmetic. α_k and s are 128-bit binary fractions and a coordinate is
/// s + i·α_k modulo 2^128 (the multiplication wraps exactly), so the phase
/// of index i is off by at most i·2^-128 ≤ 2^-64 from that of the rounded α:
/// index-addressable to full double precision for every 64-bit index (a
/// double-precision i·α loses log2(i) bits: 40 of 53 at i = 2^40). R_d's α
/// is computed at construction in the same fixed point (bisection on
/// g^d (1 + g) = 1 with g = 1/φ_d, then powers of g), within d·2^-127.
/// A user's α is taken as given (a double: a dyadic rational, whose
/// sequence is the one computed here, exactly).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "stratum/util/error.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

class Kronecker {
 public:
  using u128 = unsigned __int128;
  static constexpr unsigned max_dimensions = 4096;

  /// R_d of Roberts 2018 in d dimensions, offset s in [0, 1) in every one.
  explicit Kronecker(unsigned dimensions, double offset = 0.0) : offset_(require_offset(offset)) {
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions,
            "Kronecker supports 1 to " + std::to_string(max_dimensions) + " dimensions");
    alpha_.resize(dimensions);
    const u128 g = inverse_golden_ratio(dimensions);
    u128 power = g;
    for (unsigned k = 0; k < dimensions; ++k) {
      alpha_[k] = power;
      power = multiply_fractions(power, g);
    }
  }

  /// A user's α: one entry per dimension, each in (0, 1).
  explicit Kronecker(std::span<const double> alpha, double offset = 0.0) : offset_(require_offset(offset)) {
    require(!alpha.empty() && alpha.size() <= max_dimensions, "alpha", alpha.size(),
            "needs 1 to " + std::to_string(max_dimensions) + " entries, one per dimension");
    for (std::size_t k = 0; k < alpha.size(); ++k) {
      const double a = alpha[k];
      if (!(a > 0.0 && a < 1.0) || to_fraction(a) == 0)  // message built only on failure
        throw invalid_argument("alpha", "entry " + std::to_string(k) + " = " + std::to_string(a),
                               "entries must be real numbers in (0, 1) (irrationals, ideally)");
      alpha_.push_back(to_fraction(a));
    }
  }

  unsigned dimensions() const noexcept { return static_cast<unsigned>(alpha_.size()); }
  /// α of dimension dim as a 128-bit binary fraction, and as a double.
  u128 alpha_fraction(unsigned dim) const noexcept { return alpha_[dim]; }
  double alpha(unsigned dim) const noexcept { return to_double(alpha_[dim]); }
  double offset() const noexcept { return to_double(offset_); }

  /// frac(s + index·α_dim) as a 128-bit binary fraction (exact modulo 2^128).
  constexpr u128 phase(std::uint64_t index, unsigned dim) const noexcept {
    return offset_ + static_cast<u128>(index) * alpha_[dim];
  }

  /// The coordinate, truncated to 53 (or 24) bits, so always < 1.
  template <class Real = double>
  constexpr Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return coordinate<Real>(index, offset_, alpha_[dim]);
  }
  /// sample's coordinate for an offset and one α alone (the pixel sampler's pairs keep two α, not the vector).
  template <class Real = double>
  STRATUM_HOST_DEVICE static constexpr Real coordinate(std::uint64_t index, u128 offset, u128 alpha) noexcept {
    return to_unit<Real>(to_double(offset + static_cast<u128>(index) * alpha));
  }

  /// φ_d, the positive root of x^(d+1) = x + 1, in double precision.
  static double generalized_golden_ratio(unsigned d) { return 1.0 / to_double(inverse_golden_ratio(d)); }

  /// ⌊a·b / 2^128⌋ for 128-bit fractions a, b: their product, truncated.
  static constexpr u128 multiply_fractions(u128 a, u128 b) noexcept {
    const auto a0 = static_cast<std::uint64_t>(a), a1 = static_cast<std::uint64_t>(a >> 64);
    const auto b0 = static_cast<std::uint64_t>(b), b1 = static_cast<std::uint64_t>(b >> 64);
    const u128 low = static_cast<u128>(a0) * b0, cross1 = static_cast<u128>(a0) * b1;
    const u128 cross2 = static_cast<u128>(a1) * b0, high = static_cast<u128>(a1) * b1;
    const u128 middle = (low >> 64) + static_cast<std::uint64_t>(cross1) + static_cast<std::uint64_t>(cross2);
    return high + (cross1 >> 64) + (cross2 >> 64) + (middle >> 64);
  }

  /// g = 1/φ_d as a 128-bit fraction: the root in (1/2, 1) of g^d (1 + g) = 1
  /// (x^(d+1) = x + 1 divided by x^(d+1)), by bisection on the 128-bit grid;
  /// g^d (1 + g) − 1 is increasing in g, and its truncated evaluation errs
  /// by at most (d + 1)·2^-128.
  static constexpr u128 inverse_golden_ratio(unsigned d) noexcept {
    u128 low = u128{1} << 127, high = ~u128{0};  // f(1/2) < 0 < f(1 − 2^-128)
    while (high - low > 1) {
      const u128 middle = low + (high - low) / 2;
      u128 power = middle;  // g^d
      for (unsigned k = 1; k < d; ++k) power = multiply_fractions(power, middle);
      const u128 sum = power + multiply_fractions(power, middle);  // g^d + g^(d+1), wraps when ≥ 1
      (sum < power ? high : low) = middle;
    }
    return low;
  }

  /// A fraction's 53 leading bits as a double in [0, 1).
  static constexpr double to_double(u128 fraction) noexcept {
    return static_cast<double>(static_cast<std::uint64_t>(fraction >> 75)) * 0x1.0p-53;
  }

  /// A double in [0, 1) as a 128-bit fraction (exact for x ≥ 2^-75).
  static constexpr u128 to_fraction(double x) noexcept {
    const double scaled = x * 0x1.0p64;
    const auto high = static_cast<std::uint64_t>(scaled);
    const auto low = static_cast<std::uint64_t>((scaled - static_cast<double>(high)) * 0x1.0p64);
    return (static_cast<u128>(high) << 64) | low;
  }

 private:
  static u128 require_offset(double offset) {
    require(offset >= 0.0 && offset < 1.0, "offset", offset, "the offset s must be in [0, 1)");
    return to_fraction(offset);
  }

  u128 offset_;
  std::vector<u128> alpha_;
};

}  // namespace stratum
