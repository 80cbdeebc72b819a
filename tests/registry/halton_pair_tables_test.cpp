// Halton's first two dimensions under permute in small per-seed tables
// (registry/halton_pair_tables.hpp) against the registry's sets, which
// come from RandomDigitPermutations' full tables.
#include "stratum/registry/halton_pair_tables.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/hash.hpp"

using namespace stratum;

TEST(HaltonPairTables, FillEqualsRandomDigitPermutationsOnBothSidesOfTheTableLimit) {
  const HaltonPairTables tables;
  for (const std::uint64_t n : {1ull, 2ull, 3ull, 16ull, 81ull, 100ull, 2187ull, 2188ull})
    for (const std::uint64_t start : {0ull, 7ull})
      for (const std::uint64_t seed : {0ull, 12345ull, 0xdeadbeefcafeull}) {
        // The oracle: the full tables, built for these bases and indices.
        const RandomDigitPermutations permutations(seed, {2, 3}, start + n - 1);
        std::vector<double> points(2 * n);
        tables.fill(seed, start, n, points.data());
        for (std::uint64_t i = 0; i < n; ++i) {
          ASSERT_EQ(points[2 * i], permutations.sample(start + i, 0)) << n << " " << start << " " << seed << " " << i;
          ASSERT_EQ(points[2 * i + 1], permutations.sample(start + i, 1)) << n << " " << start << " " << seed;
        }
      }
}

TEST(HaltonPairTables, ManySeedsAtARenderersCounts) {
  // The counts a renderer builds per pixel (spp, spp · shadow rays), over
  // many seeds: each seed's permutations differ at every position.
  const HaltonPairTables tables;
  for (std::uint64_t s = 0; s < 300; ++s)
    for (const std::uint64_t n : {4ull, 16ull, 64ull}) {
      const std::uint64_t seed = hash64(s, n);
      const RandomDigitPermutations permutations(seed, {2, 3}, n - 1);
      HaltonPairTables::Set set;
      tables.build(seed, n, set);
      for (std::uint64_t i = 0; i < n; ++i) {
        const std::array<double, 2> point = HaltonPairTables::point(set, i);
        ASSERT_EQ(point[0], permutations.sample(i, 0)) << seed << " " << n << " " << i;
        ASSERT_EQ(point[1], permutations.sample(i, 1)) << seed << " " << n << " " << i;
      }
    }
}

TEST(HaltonPairTables, TheRegistrysSmallSetsAreTheTablesAndEqualItsLargeOnes) {
  // d = 2 and start + n <= max_points: the registry fills from the tables;
  // d = 3 (bases 2, 3, 5) from RandomDigitPermutations, whose first two
  // coordinates are the same permutations.
  for (const std::uint64_t n : {5ull, 2000ull}) {
    SamplerRequest request;
    request.n = n, request.d = 2, request.seed = 77, request.start = 3;
    const PointSet pair = generate_points("halton", request);
    request.d = 3;
    const PointSet triple = generate_points("halton", request);
    for (std::uint64_t i = 0; i < n; ++i) {
      ASSERT_EQ(pair(i, 0), triple(i, 0)) << n << " " << i;
      ASSERT_EQ(pair(i, 1), triple(i, 1)) << n << " " << i;
    }
  }
}

TEST(HaltonPairTables, OneCoordinateBuildsTheFirstAlone) {
  const HaltonPairTables tables;
  HaltonPairTables::Set both, first;
  tables.build(99, 64, both);
  tables.build(99, 64, first, 1);
  for (std::uint64_t i = 0; i < 64; ++i) {
    EXPECT_EQ(HaltonPairTables::point(first, i)[0], HaltonPairTables::point(both, i)[0]);
    EXPECT_EQ(HaltonPairTables::point(first, i)[1], 0.0);
  }
}

TEST(HaltonPairTables, TheRegistryOffersThemForHaltonUnderPermuteOnly) {
  const SamplerInfo& halton = find_sampler("halton");
  ASSERT_TRUE(halton.pair_tables);
  EXPECT_TRUE(halton.pair_tables(Randomizer::permute).has_value());
  EXPECT_FALSE(halton.pair_tables(Randomizer::owen).has_value());
  int offered = 0;
  for (const SamplerInfo& info : samplers()) offered += static_cast<bool>(info.pair_tables);
  EXPECT_EQ(offered, 1);
}

/// The tables' permutations, computed without branches or 128-bit products
/// (base 2: the digit-0 images; base 3: the swap codes), against the
/// permutation rule's permutation() and image() at every position of both
/// bases, by both copies (the comparison of points cannot see positions past
/// the 53rd bit), and ⌊3h/2^64⌋ against the 128-bit product at its thresholds.
TEST(HaltonPairTables, PermutationsEqualTheRule) {
  using u128 = unsigned __int128;
  for (std::uint64_t h :
       {0ull, 1ull, 0x5555555555555555ull, 0x5555555555555556ull, 0xAAAAAAAAAAAAAAAAull, 0xAAAAAAAAAAAAAAABull, ~0ull})
    EXPECT_EQ(HaltonPairTables::high_of_three_times(h), std::uint32_t((u128{h} * 3) >> 64)) << h;
  for (std::uint64_t i = 0; i < 100000; ++i) {
    const std::uint64_t h = hash64(i);
    ASSERT_EQ(HaltonPairTables::high_of_three_times(h), std::uint32_t((u128{h} * 3) >> 64)) << h;
  }
  std::uint32_t moved[2] = {0, 0}, codes_seen[6] = {};
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const digits_detail::ShuffledPermutationRule rule(seed);
    const std::uint64_t bits = HaltonPairTables::zero_bits2(rule.dimension_key(0));
    ASSERT_EQ(bits, HaltonPairTables::zero_bits2_portable(rule.dimension_key(0))) << seed;
    for (unsigned j = 0; j < 64; ++j) {
      ASSERT_EQ((bits >> (63 - j)) & 1, rule.image(0, j, 2, 0)) << seed << " " << j;
      moved[0] += rule.image(0, j, 2, 0) != 0;
    }
    std::uint64_t code[48] = {}, portable[48] = {};
    HaltonPairTables::swap_codes3(rule.dimension_key(1), code);
    HaltonPairTables::swap_codes3_portable(rule.dimension_key(1), portable);
    for (unsigned j = 0; j < digits_detail::digit_count(3); ++j) {
      ASSERT_EQ(code[j], portable[j]) << seed << " " << j;
      ASSERT_LT(code[j], 6u) << seed << " " << j;
      std::uint32_t images[3];
      rule.permutation(1, j, 3, images);
      for (std::uint32_t a = 0; a < 3; ++a) {
        ASSERT_EQ(HaltonPairTables::code_permutations3[code[j]][a], images[a]) << seed << " " << j << " " << a;
        ASSERT_EQ(images[a], rule.image(1, j, 3, a)) << seed << " " << j << " " << a;
      }
      moved[1] += images[0] != 0;
      ++codes_seen[code[j]];
    }
  }
  for (unsigned code = 0; code < 6; ++code) EXPECT_GT(codes_seen[code], 0u) << code;  // all six permutations occur
  EXPECT_GT(moved[0], 0u);  // the images are not all 0 (or the test would pass for an identity rule)
  EXPECT_GT(moved[1], 0u);
  if (!HaltonPairTables::vectorized()) GTEST_LOG_(INFO) << "no AVX-512DQ here: only the portable copy was tested";
}
