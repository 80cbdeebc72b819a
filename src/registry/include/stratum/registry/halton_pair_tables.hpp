#pragma once
/// Halton's first two dimensions (bases 2 and 3) under random digit
/// permutations ("permute", the default), built per seed into a small table
/// of what the points need: a renderer draws a new set per pixel and
/// dimension, and RandomDigitPermutations' tables (every digit position,
/// every digit) cost more to build than the few points drawn from them.
/// For n ≤ max_points (every index in the first digit chunk of both bases,
/// 3^7 = 2187) a set holds, per coordinate, π_j(a)·W_j for the positions j
/// that indices < n use, the 128-bit sum of the rest of the first chunk
/// (digit 0 everywhere) and the truncated sums of the later chunks; built
/// without allocation from RandomDigitPermutations' permutation rule and
/// equal to its points bit for bit (tests/registry/halton_pair_tables_test.cpp).
/// fill() covers every n: the table up to max_points, RandomDigitPermutations above.
/// The registry offers it where it applies (SamplerInfo::pair_tables) and
/// fills halton's small 2D sets under permute with it.
#include <array>
#include <cstdint>
#include <vector>

namespace stratum {

class HaltonPairTables {
 public:
  static constexpr std::uint64_t max_points = 2187;
  struct Set {
    std::array<std::array<std::array<unsigned __int128, 3>, 12>, 2> low;  ///< [coordinate][position < 12][digit]
    std::array<unsigned __int128, 2> first_chunk_rest{};
    std::array<std::uint64_t, 2> tail{};
    std::array<unsigned, 2> positions{};
    unsigned coordinates = 0;  ///< how many coordinates are built (0: none, stale)
  };

  HaltonPairTables();
  /// The table of the set of `seed` for indices < n ≤ max_points, its first
  /// `coordinates` (1 or 2) coordinates.
  void build(std::uint64_t seed, std::uint64_t n, Set& set, unsigned coordinates = 2) const noexcept;
  /// Point `index` (< the n it was built for) of a built set (coordinates not built: 0).
  static std::array<double, 2> point(const Set& set, std::uint64_t index) noexcept;
  /// Points start … start + n − 1 of the set of `seed`, into out[2i], out[2i + 1].
  void fill(std::uint64_t seed, std::uint64_t start, std::uint64_t n, double* out) const;

  /// π_j(0) for positions j < 64 (base 2) or j < 48 (base 3) of one
  /// dimension, from its dimension key (most of build()'s time: ≈ 100
  /// positions past the digits the indices use, 2–3 hashes each), written
  /// without branches or 128-bit products so that the positions' hashes
  /// vectorize; an AVX-512 copy is chosen at run time where the CPU has
  /// AVX-512DQ. The portable copy and the choice are public for tests.
  static void zero_images(std::uint64_t dimension_key, std::uint32_t base, std::uint8_t* out) noexcept;
  static void zero_images_portable(std::uint64_t dimension_key, std::uint32_t base, std::uint8_t* out) noexcept;
  static bool zero_images_vectorized() noexcept;
  /// ⌊3h / 2^64⌋ without a 128-bit product (zero_images' base-3 swap).
  static constexpr std::uint32_t high_of_three_times(std::uint64_t h) noexcept {
    return std::uint32_t{h >= 0x5555555555555556ULL} + std::uint32_t{h >= 0xAAAAAAAAAAAAAAABULL};
  }

 private:
  std::vector<unsigned __int128> weights_[2];  ///< W_j of bases 2 and 3 (digits.hpp)
};

}  // namespace stratum
