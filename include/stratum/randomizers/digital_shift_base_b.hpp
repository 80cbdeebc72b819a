#pragma once
/// Digital shift in base b for radical-inverse sequences: digit j of the
/// index becomes (a_j + s_j) mod b with s_j uniform on {0..b−1}, one shift
/// per (dimension, position) (the base-b digital shift of digital nets:
/// Dick, Pillichshammer 2010, "Digital Nets and Sequences"; in base 2 it is
/// the XOR with a random word). A translation of the digit space: the
/// first b^k points keep one point per interval [t/b^k, (t+1)/b^k), Halton's
/// mixed-base elementary intervals survive, and each point is uniform
/// (positions past the index's last digit are shifted too), so estimates are
/// unbiased. Cheaper randomness than digit permutations (b choices per
/// position instead of b!), hence usually a larger variance.
#include <cstdint>
#include <utility>
#include <vector>

#include "stratum/randomizers/digits.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

namespace digits_detail {

/// The permutations a ↦ (a + s_j) mod b of BaseBDigitalShift.
class DigitShiftRule {
 public:
  STRATUM_HOST_DEVICE explicit constexpr DigitShiftRule(std::uint64_t seed) noexcept
      : key_(hash64(seed, 0x736869667462ULL /* "shiftb" */)) {}

  /// s_j of (dim, position), uniform on {0..b−1}.
  STRATUM_HOST_DEVICE constexpr std::uint32_t shift(unsigned dim, unsigned position,
                                                    std::uint32_t base) const noexcept {
    return static_cast<std::uint32_t>(uniform_below(base, key_, dim, position));
  }
  STRATUM_HOST_DEVICE constexpr std::uint32_t image(unsigned dim, unsigned position, std::uint32_t base,
                                                    std::uint32_t digit) const noexcept {
    const std::uint32_t sum = digit + shift(dim, position, base);
    return sum >= base ? sum - base : sum;
  }
  void permutation(unsigned dim, unsigned position, std::uint32_t base, std::uint32_t* images) const noexcept {
    const std::uint32_t s = shift(dim, position, base);
    for (std::uint32_t a = 0; a < base; ++a) images[a] = a + s >= base ? a + s - base : a + s;
  }

 private:
  std::uint64_t key_;
};

}  // namespace digits_detail

/// Scrambled radical inverses by a base-b digital shift ("xor"): dimension
/// `dim` uses base bases[dim]; sample(index, dim) depends only on (seed, dim,
/// index). Tabulated as in digits.hpp for indices up to max_index.
class BaseBDigitalShift : public digits_detail::PositionalDigitScrambler<digits_detail::DigitShiftRule> {
 public:
  BaseBDigitalShift(std::uint64_t seed, std::vector<std::uint32_t> bases, std::uint64_t max_index = ~std::uint64_t{0})
      : PositionalDigitScrambler(digits_detail::DigitShiftRule(seed), std::move(bases), max_index) {}

  /// s_position of dimension dim.
  std::uint32_t shift(unsigned dim, unsigned position) const noexcept { return rule().shift(dim, position, base(dim)); }
};

}  // namespace stratum
