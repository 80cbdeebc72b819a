#pragma once
/// Halton's first two dimensions (bases 2 and 3) under random digit
/// permutations ("permute", the default), built per seed into a small table
/// of what the points need: a renderer draws a new set per pixel and
/// dimension, and RandomDigitPermutations' tables (every digit position,
/// every digit) cost more to build than the few points drawn from them.
/// For n ≤ max_points (every index in the first digit chunk of both bases,
/// 3^7 = 2187) a set holds:
/// - base 2: the word whose bit 63 − j is π_j(0), j < 64. A permutation of
///   {0, 1} is the identity or the swap, π_j(a) = a ⊕ π_j(0), and every
///   weight W_j = 2^(127−j) is exact, so the point's fraction is
///   bit_reverse(index) ⊕ that word: no table of digits, no sums;
/// - base 3: π_j(a)·W_j for the positions j that indices < n use, the
///   128-bit sum of the rest of the first chunk (digit 0 everywhere) and the
///   truncated sums of the later chunks (digits.hpp's arithmetic);
/// built without allocation from RandomDigitPermutations' permutation rule and
/// equal to its points bit for bit (tests/registry/halton_pair_tables_test.cpp).
/// fill() covers every n: the table up to max_points, RandomDigitPermutations above.
/// The registry offers it where it applies (SamplerInfo::pair_tables) and
/// fills halton's small 2D sets under permute with it.
#include <array>
#include <cstdint>

#include "stratum/randomizers/digits.hpp"
#include "stratum/util/bits.hpp"

namespace stratum {

class HaltonPairTables {
 public:
  static constexpr std::uint64_t max_points = 2187;
  /// Base-3 positions an index < max_points uses (3^7 = max_points).
  static constexpr unsigned max_positions3 = 7;
  struct Set {
    std::uint64_t zero_bits2 = 0;                                         ///< base 2: bit 63 − j is π_j(0)
    std::array<std::array<unsigned __int128, 3>, max_positions3> low3{};  ///< base 3: [position][digit] π_j(a)·W_j
    unsigned __int128 first_chunk_rest3 = 0;  ///< base 3: Σ π_j(0)·W_j over the first chunk's unused positions
    std::uint64_t tail3 = 0;                  ///< base 3: the later chunks' truncated sums
    unsigned positions3 = 0;                  ///< base-3 positions that indices < n use
    unsigned coordinates = 0;                 ///< how many coordinates are built (0: none, stale)
  };

  /// The table of the set of `seed` for indices < n ≤ max_points, its first
  /// `coordinates` (1 or 2) coordinates.
  void build(std::uint64_t seed, std::uint64_t n, Set& set, unsigned coordinates = 2) const noexcept;
  /// Point `index` (< the n it was built for) of a built set (coordinates not built: 0).
  static std::array<double, 2> point(const Set& set, std::uint64_t index) noexcept {
    std::array<double, 2> point{0.0, 0.0};
    if (set.coordinates == 0) return point;
    point[0] = digits_detail::fraction_to_double(reverse_bits64(index) ^ set.zero_bits2);
    if (set.coordinates == 1) return point;
    unsigned __int128 sum = set.first_chunk_rest3;
    std::uint64_t rest = index;
    for (unsigned j = 0; j < set.positions3; ++j) sum += set.low3[j][rest % 3], rest /= 3;
    point[1] = digits_detail::fraction_to_double(static_cast<std::uint64_t>(sum >> 64) + set.tail3);
    return point;
  }
  /// Points start … start + n − 1 of the set of `seed`, into out[2i], out[2i + 1].
  void fill(std::uint64_t seed, std::uint64_t start, std::uint64_t n, double* out) const;

  /// The random part of one dimension's permutations, from its dimension
  /// key, at every position (most of build()'s time: 2–3 hashes a
  /// position), written without branches or 128-bit products so that the
  /// positions' hashes vectorize; an AVX-512 copy is chosen at run time
  /// where the CPU has AVX-512DQ. Base 2: π_j(0) as a word (bit 63 − j,
  /// j < 64). Base 3: the swaps j_1, j_2 of the rule's shuffle as codes
  /// j_1 + 2·j_2, one 64-bit word a position (a byte store halves GCC's
  /// vector width; j < 48, past its 41 positions for whole vectors), whose
  /// permutations code_permutations3 lists. The portable copies and the
  /// choice (vectorized()) are public for tests.
  static std::uint64_t zero_bits2(std::uint64_t dimension_key) noexcept;
  /// The base-2 word of seed's set (build's zero_bits2): RandomDigitPermutations' dimension 0 in base 2.
  static std::uint64_t base2_word(std::uint64_t seed) noexcept;
  static void swap_codes3(std::uint64_t dimension_key, std::uint64_t* out) noexcept;
  static std::uint64_t zero_bits2_portable(std::uint64_t dimension_key) noexcept;
  static void swap_codes3_portable(std::uint64_t dimension_key, std::uint64_t* out) noexcept;
  static bool vectorized() noexcept;
  /// The permutation [π(0), π(1), π(2)] of swap code j_1 + 2·j_2: the rule's
  /// Fisher–Yates shuffle of (0, 1, 2), swap 2 with j_2, then swap 1 with j_1.
  static constexpr std::array<std::array<std::uint8_t, 3>, 6> code_permutations3 = [] {
    std::array<std::array<std::uint8_t, 3>, 6> table{};
    for (unsigned code = 0; code < 6; ++code) {
      std::array<std::uint8_t, 3> images{0, 1, 2};
      const unsigned j1 = code % 2, j2 = code / 2;
      const std::uint8_t second = images[2];
      images[2] = images[j2], images[j2] = second;
      const std::uint8_t first = images[1];
      images[1] = images[j1], images[j1] = first;
      table[code] = images;
    }
    return table;
  }();
  /// ⌊3h / 2^64⌋ without a 128-bit product (swap_codes3's second swap).
  static constexpr std::uint32_t high_of_three_times(std::uint64_t h) noexcept {
    return std::uint32_t{h >= 0x5555555555555556ULL} + std::uint32_t{h >= 0xAAAAAAAAAAAAAAABULL};
  }
};

}  // namespace stratum
