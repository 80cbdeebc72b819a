#pragma once
/// Nested uniform scrambling in base b for radical-inverse sequences (Owen
/// 1995, "Randomly permuted (t,m,s)-nets and (t,s)-sequences"): the output
/// digit at position j is π_{j, a_0…a_(j−1)}(a_j), a permutation chosen
/// afresh for every prefix of higher output digits (the index's lower
/// digits). Nets stay nets (Halton's mixed-base elementary intervals
/// survive), every point is uniform and, unlike a permutation per position,
/// the scrambling randomizes within every elementary interval, which gives
/// Owen's variance bounds (Owen 1997, "Monte Carlo variance of scrambled net
/// quadrature").
///
/// There are too many prefixes to tabulate, so each node's permutation comes
/// from a 64-bit word w = hash64(hash64(seed, dim, j), prefix), the prefix
/// coded as index mod b^j; every one of the K(b) positions of digits.hpp is
/// scrambled, including the 0 digits past the index's last one.
///  - b = 2: π(a) = a ⊕ (top bit of w), exactly uniform.
///  - 3 ≤ b ≤ 24: a uniform permutation decoded from w (and two more words
///    when b > 12) read as fractions: their mixed-radix digits in radices
///    2, 3, …, b drive a Fisher–Yates shuffle (Durstenfeld 1964). Total-
///    variation distance to uniform < 2^-34 (b!/2^64 for b ≤ 12): exact for
///    every practical purpose.
///  - b > 24: π(a) = (m·σ(a) + s) mod b, σ a keyed bijection of {0..b−1}
///    by cycle walking (Black, Rogaway 2002, "Ciphers with arbitrary finite
///    domains"; as Kensler 2013's permute), m uniform in {1..b−1} (only for
///    prime b; m = 1 otherwise) and s uniform in {0..b−1}. Each image is
///    exactly uniform, and for prime b every pair of images is uniform over
///    distinct pairs, which is all that the variance of scrambled-net
///    quadrature depends on (Owen 1997: it is a sum over pairs of points),
///    so the variance is that of nested uniform scrambling; the full law of
///    a permutation is not uniform on all b! permutations.
/// Cost: one hash per digit position (K(b) of them, 64 in base 2), so this
/// is tens of times slower than the tabulated digit permutations.
///
/// Device code (docs/gpu.md): a sample reads the keys and weights through a
/// View (pointers, trivially copyable) that a kernel takes by value; view()
/// points into the scrambler, view(copy) into copies that `copy` makes.
#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

#include "stratum/randomizers/digits.hpp"
#include "stratum/util/bits.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

/// Nested uniform (Owen) scrambling of radical inverses in any base ("owen"):
/// dimension `dim` uses base bases[dim]; sample(index, dim) depends only on
/// (seed, dim, index). Construction computes K(b) keys and weights per
/// dimension; a sample allocates nothing.
class BaseBOwenScrambler {
 public:
  BaseBOwenScrambler(std::uint64_t seed, std::vector<std::uint32_t> bases) {
    digits_detail::require_digit_bases(bases);
    const std::uint64_t key = hash64(seed, 0x6f77656e62ULL /* "owenb" */);
    for (unsigned dim = 0; dim < bases.size(); ++dim) {
      const std::uint32_t base = bases[dim];
      Dimension d{base, digits_detail::digit_count(base), keys_.size(), digits_detail::FastDivider(base),
                  is_prime(base)};
      // hash64(key, dim, j) by extending the chain of hash64(key, dim) (the
      // same words, one mix a position), each with the first mixing step of
      // hash64(position_key, prefix) done here; the weights from the base's
      // cached table (computing W_j is a 128-bit division and j products).
      const std::uint64_t dimension_key = hash64(key, dim);
      for (unsigned j = 0; j < d.positions; ++j) keys_.push_back(mix64(hash64_extend(dimension_key, j) + golden));
      const std::vector<digits_detail::u128>& weights = digits_detail::digit_weights(base);
      weights_.insert(weights_.end(), weights.begin(), weights.end());
      dims_.push_back(d);
    }
  }

  unsigned dimensions() const noexcept { return static_cast<unsigned>(dims_.size()); }
  std::uint32_t base(unsigned dim) const noexcept { return dims_[dim].base; }

  /// The scrambled radical inverse of `index` as a 64-bit binary fraction.
  std::uint64_t fraction(std::uint64_t index, unsigned dim) const noexcept { return view().fraction(index, dim); }

  /// The scrambled radical inverse as a double or float in [0, 1).
  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return view().template sample<Real>(index, dim);
  }

  /// π_{position, prefix}(digit) of dimension dim, where prefix = index mod
  /// b^position codes the index's digits below `position` (for tests and
  /// oracles).
  std::uint32_t permute_digit(unsigned dim, unsigned position, std::uint64_t prefix,
                              std::uint32_t digit) const noexcept {
    const Dimension& d = dims_[dim];
    return node_image(d, node_word(keys_[d.first + position], prefix), digit);
  }

 private:
  static constexpr std::uint64_t golden = 0x9e3779b97f4a7c15ULL;

  struct Dimension {
    std::uint32_t base;
    unsigned positions;  // K(b)
    std::size_t first;   // into keys_ and weights_
    digits_detail::FastDivider divider;
    bool prime;
  };

 public:
  /// The per-sample path: the scrambler's arrays by pointer.
  class View {
   public:
    STRATUM_HOST_DEVICE View(const Dimension* dims, const std::uint64_t* keys,
                             const digits_detail::u128* weights) noexcept
        : dims_(dims), keys_(keys), weights_(weights) {}

    /// The scrambled radical inverse of `index` as a 64-bit binary fraction.
    STRATUM_HOST_DEVICE std::uint64_t fraction(std::uint64_t index, unsigned dim) const noexcept {
      const Dimension& d = dims_[dim];
      const std::uint64_t* keys = keys_ + d.first;
      if (d.base == 2) {
        std::uint64_t flips = 0;
        for (unsigned j = 0; j < 64; ++j) {
          const std::uint64_t prefix = index & ((std::uint64_t{1} << j) - 1);
          flips |= (node_word(keys[j], prefix) >> 63) << (63 - j);
        }
        return reverse_bits64(index) ^ flips;
      }
      const digits_detail::u128* weights = weights_ + d.first;
      digits_detail::u128 sum = 0;
      std::uint64_t prefix = 0;
      std::uint64_t power = 1;  // b^j modulo 2^64: only multiplies digits 0 once it wraps
      for (unsigned j = 0; j < d.positions; ++j) {
        const std::uint64_t next = d.divider.quotient(index);
        const auto digit = static_cast<std::uint32_t>(index - next * d.base);
        index = next;
        sum += static_cast<digits_detail::u128>(node_image(d, node_word(keys[j], prefix), digit)) * weights[j];
        prefix += digit * power;
        power *= d.base;
      }
      return static_cast<std::uint64_t>(sum >> 64);
    }
    template <class Real = double>
    STRATUM_HOST_DEVICE Real sample(std::uint64_t index, unsigned dim) const noexcept {
      return to_unit<Real>(digits_detail::fraction_to_double(fraction(index, dim)));
    }

   private:
    const Dimension* dims_;
    const std::uint64_t* keys_;
    const digits_detail::u128* weights_;
  };

  /// The per-sample path reading this object's arrays.
  View view() const noexcept { return View(dims_.data(), keys_.data(), weights_.data()); }
  /// The per-sample path reading copies: copy(data, count) copies `count`
  /// elements (trivially copyable) and returns the copy's address.
  template <class Copy>
  View view(Copy&& copy) const {
    return View(copy(dims_.data(), dims_.size()), copy(keys_.data(), keys_.size()),
                copy(weights_.data(), weights_.size()));
  }

 private:
  STRATUM_HOST_DEVICE static constexpr bool is_prime(std::uint32_t n) noexcept {
    for (std::uint32_t f = 2; f * f <= n; ++f)
      if (n % f == 0) return false;
    return n >= 2;
  }

  // hash64(position key, prefix), the position key pre-mixed.
  STRATUM_HOST_DEVICE static constexpr std::uint64_t node_word(std::uint64_t mixed_key, std::uint64_t prefix) noexcept {
    return mix64((mixed_key ^ (prefix * 0xd1342543de82ef95ULL + 0x632be59bd9b4e019ULL)) + golden);
  }

  // Image of `digit` under the permutation of the node whose word is w.
  STRATUM_HOST_DEVICE static std::uint32_t node_image(const Dimension& d, std::uint64_t w,
                                                      std::uint32_t digit) noexcept {
    const std::uint32_t b = d.base;
    if (b == 2) return digit ^ static_cast<std::uint32_t>(w >> 63);
    if (b <= 24) {
      // Fisher–Yates (swap positions i and j_i for i = b−1 down to 1, from the
      // identity) with draws j_i ∈ [0, i] read off a 64-bit fraction u as
      // mixed-radix digits, j_i = ⌊u·(i+1)⌋, u ← frac(u·(i+1)), for
      // i = 1, 2, …: the order in which the image of `digit` is traced back
      // through the swaps, so no array is needed. Radices 2–12, 13–18 and
      // 19–24 read three words (products 2^28.8, 2^23.7, 2^26.5 ≪ 2^64).
      std::uint32_t position = digit;
      std::uint64_t u = w;
      for (std::uint32_t i = 1; i < b; ++i) {
        if (i == 12) u = mix64(w + golden);
        if (i == 18) u = mix64(w + 2 * golden);
        const digits_detail::u128 product = static_cast<digits_detail::u128>(u) * (i + 1);
        const auto j = static_cast<std::uint32_t>(product >> 64);
        u = static_cast<std::uint64_t>(product);
        position = position == i ? j : (position == j ? i : position);
      }
      return position;
    }
    // Keyed bijection of {0..b−1}: a bijection of k-bit words (xor, odd
    // multiply, xorshift and add are each invertible mod 2^k), iterated until
    // it lands below b (cycle walking).
    const std::uint64_t w2 = mix64(w + golden);
    const std::uint64_t w3 = mix64(w2 + golden);
    const unsigned bits = static_cast<unsigned>(bit_width64(b - 1));
    const std::uint32_t mask = (std::uint32_t{1} << bits) - 1;
    const auto flip = static_cast<std::uint32_t>(w3);
    const auto odd = static_cast<std::uint32_t>(w3 >> 32) | 1u;
    const auto offset = static_cast<std::uint32_t>(w);  // m takes w's leading bits
    std::uint32_t x = digit;
    do {
      x = (x ^ flip) & mask;
      x = (x * odd) & mask;
      x ^= x >> (bits / 2);
      x = (x + offset) & mask;
      x = (x * 0x2c1b3c6du) & mask;
      x ^= x >> ((bits + 2) / 3);
    } while (x >= b);
    const std::uint64_t m =
        d.prime ? 1 + static_cast<std::uint64_t>((static_cast<digits_detail::u128>(w) * (b - 1)) >> 64) : 1;
    const std::uint64_t s = static_cast<std::uint64_t>((static_cast<digits_detail::u128>(w2) * b) >> 64);
    return static_cast<std::uint32_t>((m * x + s) % b);
  }

  std::vector<Dimension> dims_;
  std::vector<std::uint64_t> keys_;
  std::vector<digits_detail::u128> weights_;
};

}  // namespace stratum
