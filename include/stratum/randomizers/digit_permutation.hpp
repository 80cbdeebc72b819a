#pragma once
/// Random digit permutations for radical-inverse sequences (Owen 2017, "A
/// randomized Halton algorithm in R", Algorithm 1; what
/// scipy.stats.qmc.Halton(scramble=True) does): each (dimension, digit
/// position) gets its own independent, uniformly random permutation of
/// {0..b−1}, applied to the index's digit at that position, the same for
/// every index. Because the permutation at a position does not depend on the
/// other digits, the first b^k points still put one point in each interval
/// [t/b^k, (t+1)/b^k) and Halton's mixed-base elementary intervals survive;
/// each point is uniform on [0, 1)^d (the positions beyond the index's last
/// digit are permuted too), so estimates are unbiased.
///
/// The permutation of (seed, dim, position) is a Fisher–Yates shuffle
/// (Durstenfeld 1964) of the identity: swap positions i and j_i for
/// i = b−1 down to 1, with j_i = ⌊h_i·(i+1) / 2^64⌋, h_i = mix64(k + (i+1)·γ)
/// (the SplitMix64 stream at key k = hash64(seed, dim, position)). The tables
/// run the shuffle (b hashes); a single image traces one digit back through
/// the swaps in O(b) time and no memory, the slow path for indices past the
/// tables. Uniform up to the multiply-shift bias, total variation
/// < b²/2^64.
#include <cstdint>
#include <utility>
#include <vector>

#include "stratum/randomizers/digits.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

namespace digits_detail {

/// The permutations of RandomDigitPermutations (see digits.hpp for Rule).
class ShuffledPermutationRule {
 public:
  STRATUM_HOST_DEVICE explicit constexpr ShuffledPermutationRule(std::uint64_t seed) noexcept
      : key_(hash64(seed, 0x7065726d757465ULL /* "permute" */)) {}

  STRATUM_HOST_DEVICE constexpr std::uint32_t image(unsigned dim, unsigned position, std::uint32_t base,
                                                    std::uint32_t digit) const noexcept {
    // Trace the digit's final position back through swaps 1, 2, …, b−1.
    const std::uint64_t key = hash64_extend(dimension_key(dim), position);
    std::uint32_t at = digit;
    for (std::uint32_t i = 1; i < base; ++i) {
      const std::uint32_t j = draw(key, i);
      at = at == i ? j : (at == j ? i : at);
    }
    return at;
  }

  /// The hash chain of (seed, dim): position `position`'s key is
  /// hash64_extend(dimension_key(dim), position) (= hash64(key, dim, position)).
  STRATUM_HOST_DEVICE constexpr std::uint64_t dimension_key(unsigned dim) const noexcept { return hash64(key_, dim); }
  /// h_i, the random word of swap i of the permutation with key `key`
  /// (j_i = ⌊h_i·(i+1) / 2^64⌋).
  STRATUM_HOST_DEVICE static constexpr std::uint64_t swap_word(std::uint64_t key, std::uint32_t i) noexcept {
    return mix64(key + (static_cast<std::uint64_t>(i) + 1) * 0x9e3779b97f4a7c15ULL);
  }

  void permutation(unsigned dim, unsigned position, std::uint32_t base, std::uint32_t* images) const noexcept {
    const std::uint64_t key = hash64_extend(dimension_key(dim), position);
    for (std::uint32_t x = 0; x < base; ++x) images[x] = x;
    for (std::uint32_t i = base - 1; i >= 1; --i) std::swap(images[i], images[draw(key, i)]);
  }

 private:
  // j_i, uniform on [0, i] up to a bias < (i+1)/2^64.
  STRATUM_HOST_DEVICE static constexpr std::uint32_t draw(std::uint64_t key, std::uint32_t i) noexcept {
    const std::uint64_t h = swap_word(key, i);
    return static_cast<std::uint32_t>((static_cast<unsigned __int128>(h) * (i + 1)) >> 64);
  }

  std::uint64_t key_;
};

}  // namespace digits_detail

/// Scrambled radical inverses with random digit permutations ("permute"):
/// dimension `dim` uses base bases[dim]; sample(index, dim) depends only on
/// (seed, dim, index). Tables (built here, for indices up to max_index) make
/// a sample a few table loads; see digits.hpp for the digits kept.
class RandomDigitPermutations : public digits_detail::PositionalDigitScrambler<digits_detail::ShuffledPermutationRule> {
 public:
  RandomDigitPermutations(std::uint64_t seed, std::vector<std::uint32_t> bases,
                          std::uint64_t max_index = ~std::uint64_t{0})
      : PositionalDigitScrambler(digits_detail::ShuffledPermutationRule(seed), std::move(bases), max_index) {}

  /// π_position(digit) of dimension dim (b hashes, no table; for tests and
  /// oracles).
  std::uint32_t permute_digit(unsigned dim, unsigned position, std::uint32_t digit) const noexcept {
    return rule().image(dim, position, base(dim), digit);
  }
};

}  // namespace stratum
