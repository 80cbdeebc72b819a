#pragma once
/// Progressive multi-jittered (0,2) sequences, PMJ02 (Christensen, Kensler,
/// Kilpatrick 2018, "Progressive multi-jittered sample sequences"): every
/// prefix of 2^k points has exactly one point in each of the k + 1 families
/// of 2^a × 2^(k−a) elementary intervals, so it is jittered (on the square
/// grid when k is even), Latin in both 1D projections, and stays so as
/// points are added. The original algorithm builds the sequence point by
/// point with tables of occupied strata; here every point is a pure function
/// of (seed, index, dimension), following the stateless stochastic
/// generation of Helmer, Christensen, Kensler (2021, "Stochastic generation
/// of (t, s) sample sequences", EGSR, Sec. 5.3 and supplement).
///
/// How. Point p ≥ 1 with m = msb(p) takes, in each coordinate, the 2^-(m+1)
/// stratum *beside* the one of an earlier point j = (p − 2^m) ⊕ x_m (same
/// first m digits, other (m+1)-th digit), and draws its remaining digits at
/// random; point 0 is uniform. The "xor values" x_m = A_m⁻¹ c_m come from
/// the generator matrix C of a digital (0,2)-sequence (A_m: its leading
/// m × m block, c_m: the top of column m). For PMJ02 Helmer et al. give the
/// matrices of unsigned Stirling numbers of the first kind mod 2:
/// C_x[r][c] = [c, r] and C_y[r][c] = [c + 1, r + 1]. The random digits are
/// counter-based hashes of (seed, dimension, point), so a point costs one hash
/// per link of its chain p → j → … → 0 (at most 64 links, about log2(p)/2
/// on average) and no table of earlier points.
///
/// Relation to Owen scrambling. Helmer et al. show that this stochastic
/// construction is distributed exactly as nested uniform (Owen 1995)
/// scrambling of the underlying digital (0,2)-sequence: every realization is
/// an Owen scrambling of it (the digits two points share are exactly those
/// their unscrambled points share), and each point is uniform on [0,1)^2. So
/// pmj02 is an Owen-scrambled (0,2)-sequence; with Sobol's first two
/// dimensions (C_x = I, C_y = Pascal) one gets the same kind of point sets
/// in another order within each power of two. It is unbiased, has Owen's
/// variance bounds, and keeps (unlike Cranley–Patterson rotation) every
/// elementary interval. The blue-noise variant (pmj02bn: best candidate
/// inside the chosen stratum) is not index-addressable: sequences/pmj02bn.hpp.
///
/// Higher dimensions (an extension, not in the papers): dimensions
/// (2t, 2t + 1) are a further pmj02 pair with independent random digits,
/// read at a shuffled index that permutes each block [2^k, 2^(k+1)) by a
/// seeded bijection. Shuffling keeps every 2^k prefix as a set, so every
/// pair is a (0,k,2)-net at every power-of-two prefix, while the pairing
/// between pairs is decorrelated (pbrt-v4 pads PMJ02BN the same way, by
/// permuting sample indices). Pair 0 is the (0,2)-sequence proper: every
/// aligned block [q 2^k, (q+1) 2^k) is a net, not only prefixes.
#include <array>
#include <bit>
#include <cstdint>
#include <type_traits>

#include "stratum/util/bits.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

namespace detail {

/// Columns of the PMJ02 generator matrices as row masks (bit r = row r,
/// i.e. the (r+1)-th binary digit of the coordinate). Column c of C_x is the
/// parity of the Stirling numbers [c, r] over r; column c of C_y those of
/// [c + 1, r + 1]. Recurrence [n, k] = [n−1, k−1] + (n−1) [n−1, k].
constexpr std::array<std::array<std::uint64_t, 64>, 2> pmj02_generator_columns() {
  std::array<std::array<std::uint64_t, 64>, 2> columns{};
  std::uint64_t stirling = 1;  // parities of [c, k] over k, for c = 0
  for (unsigned c = 0; c < 64; ++c) {
    columns[0][c] = stirling;
    // [c+1, k] ≡ [c, k−1] + c [c, k]; shifted down one row this is C_y's column.
    columns[1][c] = stirling ^ ((c & 1u) ? stirling >> 1 : 0);
    stirling = (stirling << 1) ^ ((c & 1u) ? stirling : 0);
  }
  return columns;
}

/// x_m = A_m⁻¹ c_m over GF(2), by back substitution (A_m is unit upper
/// triangular): the index j < 2^m whose first m digits equal those of 2^m.
constexpr std::array<std::array<std::uint64_t, 64>, 2> pmj02_xor_values() {
  const auto columns = pmj02_generator_columns();
  std::array<std::array<std::uint64_t, 64>, 2> xors{};
  for (unsigned coordinate = 0; coordinate < 2; ++coordinate)
    for (unsigned m = 0; m < 64; ++m) {
      const std::uint64_t below = m == 0 ? 0 : (~std::uint64_t{0} >> (64 - m));
      std::uint64_t rhs = columns[coordinate][m] & below;
      std::uint64_t solution = 0;
      for (unsigned r = m; r-- > 0;)
        if ((rhs >> r) & 1u) {
          solution |= std::uint64_t{1} << r;
          rhs ^= columns[coordinate][r];
        }
      xors[coordinate][m] = solution;
    }
  return xors;
}

inline constexpr auto pmj02_columns = pmj02_generator_columns();
inline constexpr auto pmj02_xors = pmj02_xor_values();
#if defined(__CUDACC__)
STRATUM_DEVICE_TABLE std::array<std::array<std::uint64_t, 64>, 2> device_pmj02_columns = pmj02_generator_columns();
STRATUM_DEVICE_TABLE std::array<std::array<std::uint64_t, 64>, 2> device_pmj02_xors = pmj02_xor_values();
#endif

/// Column c of coordinate `coordinate`'s generator matrix, from the table of
/// the side that runs (compile-time evaluation on the device recomputes).
STRATUM_HOST_DEVICE constexpr std::uint64_t pmj02_column(unsigned coordinate, unsigned c) noexcept {
#if defined(__CUDA_ARCH__)
  if (std::is_constant_evaluated()) return pmj02_generator_columns()[coordinate][c];
  return device_pmj02_columns[coordinate][c];
#else
  return pmj02_columns[coordinate][c];
#endif
}
/// x_m of coordinate `coordinate`, likewise.
STRATUM_HOST_DEVICE constexpr std::uint64_t pmj02_xor(unsigned coordinate, unsigned m) noexcept {
#if defined(__CUDA_ARCH__)
  if (std::is_constant_evaluated()) return pmj02_xor_values()[coordinate][m];
  return device_pmj02_xors[coordinate][m];
#else
  return pmj02_xors[coordinate][m];
#endif
}

}  // namespace detail

class Pmj02 {
 public:
  /// Dimensions 2t and 2t + 1 form pair t; 32 pairs.
  static constexpr unsigned max_dimensions = 64;

  Pmj02(unsigned dimensions, std::uint64_t seed) : dimensions_(dimensions), seed_(seed) {
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions,
            "pmj02 supports 1 to 64 dimensions (pairs (0,1), (2,3), ... of independent pmj02 sequences)");
  }
  STRATUM_HOST_DEVICE unsigned dimensions() const noexcept { return dimensions_; }
  STRATUM_HOST_DEVICE std::uint64_t seed() const noexcept { return seed_; }

  /// Column c of the generator matrix of coordinate 0 (x) or 1 (y), as a
  /// mask of rows (bit r: digit r + 1).
  STRATUM_HOST_DEVICE static constexpr std::uint64_t generator_column(unsigned coordinate, unsigned c) noexcept {
    return detail::pmj02_column(coordinate, c);
  }
  /// x_m of coordinate 0 or 1 (see the header comment).
  STRATUM_HOST_DEVICE static constexpr std::uint64_t xor_value(unsigned coordinate, unsigned m) noexcept {
    return detail::pmj02_xor(coordinate, m);
  }

  /// The coordinate as a 64-bit binary fraction (bit 63 is the first digit).
  STRATUM_HOST_DEVICE constexpr std::uint64_t sample_bits(std::uint64_t index, unsigned dim) const noexcept {
    const unsigned pair = dim / 2;
    if (pair != 0) index = shuffle(index, hash64(seed_, 0x706d6a3032736875ULL, pair));
    return keyed_bits(index, dim & 1u, digit_key(seed_, dim));
  }

  /// What sample_bits needs of (seed, dim) alone, for callers that take
  /// many points of one dimension (the renderer's per-pixel sets): with it,
  /// keyed_bits(index, dim & 1, digit_key(seed, dim)) = sample_bits(index, dim)
  /// for dimensions 0 and 1 (pair 0, read without a shuffle).
  STRATUM_HOST_DEVICE static constexpr std::uint64_t digit_key(std::uint64_t seed, unsigned dim) noexcept {
    return hash64(hash64(seed, 0x706d6a3032646967ULL, dim));
  }
  /// Digits of point `index` in coordinate 0 or 1 of a pair's sequence:
  /// walk the chain index → j → … → 0; the link at msb m fixes digits m+2 …
  /// (those of the link before) from its own random word hash64(k, link) and
  /// flips digit m+1 relative to the next link. `key` is hash64(k)
  /// (digit_key), so each word is one hash64_extend.
  STRATUM_HOST_DEVICE static constexpr std::uint64_t keyed_bits(std::uint64_t index, unsigned coordinate,
                                                                std::uint64_t key) noexcept {
    std::uint64_t value = 0;
    std::uint64_t flips = 0;
    std::uint64_t unset = ~std::uint64_t{0};  // digits still to fill (high bits)
    while (index != 0) {
      const unsigned m = 63u - static_cast<unsigned>(countl_zero64(index));
      const std::uint64_t deeper = m == 63 ? 0 : (~std::uint64_t{0} >> (m + 1));  // digits m+2 …
      value |= hash64_extend(key, index) & deeper & unset;
      flips |= std::uint64_t{1} << (63 - m);  // digit m+1
      unset &= ~deeper;
      index = (index ^ (std::uint64_t{1} << m)) ^ detail::pmj02_xor(coordinate, m);
    }
    value |= hash64_extend(key, 0) & unset;
    return value ^ flips;
  }

  template <class Real = double>
  STRATUM_HOST_DEVICE constexpr Real sample(std::uint64_t index, unsigned dim) const noexcept {
    const std::uint64_t bits = sample_bits(index, dim);
    if constexpr (sizeof(Real) == sizeof(float)) return bits_to_float(bits);
    else return bits_to_double(bits);
  }

  /// The index at which pair `pair` ≥ 1 reads its sequence: a seeded
  /// bijection of each block [2^k, 2^(k+1)) onto itself (0 and 1 are fixed).
  STRATUM_HOST_DEVICE constexpr std::uint64_t shuffled_index(std::uint64_t index, unsigned pair) const noexcept {
    return pair == 0 ? index : shuffle(index, hash64(seed_, 0x706d6a3032736875ULL, pair));
  }

 private:
  /// Bijection of [2^k, 2^(k+1)) for k = msb(index): add, multiply by odd
  /// and xor-shift modulo 2^k, each invertible, with seeded constants.
  STRATUM_HOST_DEVICE static constexpr std::uint64_t shuffle(std::uint64_t index, std::uint64_t key) noexcept {
    if (index < 2) return index;
    const unsigned k = 63u - static_cast<unsigned>(countl_zero64(index));
    const std::uint64_t mask = (std::uint64_t{1} << k) - 1;
    const std::uint64_t a = hash64(key, k), b = hash64(a, k) | 1u, c = hash64(b, k) | 1u;
    const unsigned shift = (k + 1) / 2;
    std::uint64_t x = index & mask;
    x = (x + a) & mask;
    x ^= x >> shift;
    x = (x * b) & mask;
    x ^= x >> shift;
    x = (x * c) & mask;
    x ^= x >> shift;
    return (std::uint64_t{1} << k) | x;
  }

  unsigned dimensions_;
  std::uint64_t seed_;
};

}  // namespace stratum
