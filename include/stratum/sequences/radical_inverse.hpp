#pragma once
/// Radical inverse φ_b(i): the base-b digits of i mirrored about the radix
/// point (i = 4 = 100₂ gives 0.001₂ = 1/8). Van der Corput (1935) for b = 2;
/// the building block of Halton (1960) and Hammersley (1964) points.
#include <bit>
#include <cstdint>

#include "stratum/util/bits.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

/// ⌈2^64 / b⌉: the high word of index × this is ⌊index / b⌋ exactly for
/// index < 2^(64 − ⌈log2 b⌉) (Lemire, Kaser, Kurz 2019, "Faster remainder by
/// direct computation", Theorem 1), which spares a 64-bit division per digit.
STRATUM_HOST_DEVICE constexpr std::uint64_t radical_inverse_reciprocal(std::uint32_t base) noexcept {
  return ~std::uint64_t{0} / base + 1;
}

/// φ_b(index) with b's reciprocal precomputed (radical_inverse_reciprocal).
STRATUM_HOST_DEVICE constexpr double radical_inverse(std::uint32_t base, std::uint64_t index,
                                                     std::uint64_t reciprocal) noexcept {
  if (base == 2) return static_cast<double>(reverse_bits64(index) >> 11) * 0x1.0p-53;
  const std::uint64_t limit = (std::uint64_t{1} << 63) / base;
  const std::uint64_t exact_below = std::uint64_t{1} << (64 - bit_width64(base - 1));
  std::uint64_t reversed = 0;
  std::uint64_t power = 1;
  while (index != 0 && power <= limit) {
    const std::uint64_t next =
        index < exact_below ? static_cast<std::uint64_t>((static_cast<unsigned __int128>(index) * reciprocal) >> 64)
                            : index / base;
    reversed = reversed * base + (index - next * base);
    power *= base;
    index = next;
  }
  const double value = static_cast<double>(reversed) / static_cast<double>(power);
  return value < one_minus_epsilon_double ? value : one_minus_epsilon_double;
}

/// φ_b(index) in double precision, for any base ≥ 2 and any 64-bit index.
/// Digits are accumulated as an integer and divided once, so the result is
/// the correctly rounded value of the truncated expansion; digits below
/// b^-k with b^k ≥ 2^63 are dropped (they are below double resolution).
STRATUM_HOST_DEVICE constexpr double radical_inverse(std::uint32_t base, std::uint64_t index) noexcept {
  return radical_inverse(base, index, radical_inverse_reciprocal(base));
}

/// φ_b(index) for the caller's precision (double or float).
template <class Real>
STRATUM_HOST_DEVICE constexpr Real radical_inverse_as(std::uint32_t base, std::uint64_t index) noexcept {
  return to_unit<Real>(radical_inverse(base, index));
}

/// Validates a radical-inverse base (used by constructors and the registry).
inline void require_valid_base(std::uint64_t base) {
  require(base >= 2 && base <= 0xffffffffu, "base", base, "a base must be an integer in [2, 2^32)");
}

}  // namespace stratum
