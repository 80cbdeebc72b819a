#include "stratum/randomizers/digit_permutation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <numeric>
#include <vector>

namespace stratum {
namespace {

const std::vector<std::uint32_t> kBases = {2, 3, 5, 7, 8161};

// Oracle: Σ_j π_j(a_j) b^-(j+1) over K(b) positions in long double, with the
// permutations read one image at a time (traced through the shuffle, no tables).
long double oracle(const RandomDigitPermutations& s, unsigned dim, std::uint64_t index) {
  const std::uint32_t b = s.base(dim);
  long double value = 0, scale = 1.0L / b;
  for (unsigned j = 0; j < digits_detail::digit_count(b); ++j) {
    value += static_cast<long double>(s.permute_digit(dim, j, static_cast<std::uint32_t>(index % b))) * scale;
    index /= b;
    scale /= b;
  }
  return value;
}

// P(χ²_{dof} ≥ statistic).
double chi_squared_p(double statistic, double dof) {
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), statistic));
}

// Per-test level for a family of m tests at overall level α (Šidák).
double sidak(double alpha, int m) { return 1 - std::pow(1 - alpha, 1.0 / m); }

TEST(RandomDigitPermutations, EachPositionGetsADifferentPermutation) {
  const RandomDigitPermutations a(1, kBases), b(2, kBases);
  for (unsigned dim = 0; dim < 4; ++dim)  // bases 2..7 (one image of 8161 costs 8161 hashes)
    for (unsigned j : {0u, 1u, 4u}) {
      std::vector<std::uint32_t> images(kBases[dim]);
      for (std::uint32_t x = 0; x < kBases[dim]; ++x) images[x] = a.permute_digit(dim, j, x);
      std::vector<std::uint32_t> sorted = images;
      std::sort(sorted.begin(), sorted.end());
      std::vector<std::uint32_t> identity(kBases[dim]);
      std::iota(identity.begin(), identity.end(), 0u);
      ASSERT_EQ(sorted, identity) << "not a permutation: dim " << dim << " position " << j;
    }
  // Base 8161: different seeds and positions give different permutations
  // (compared on 20 digits: one image costs 8161 hashes).
  auto differs = [](auto f, auto g) {
    for (std::uint32_t x = 0; x < 20; ++x)
      if (f(x) != g(x)) return true;
    return false;
  };
  EXPECT_TRUE(
      differs([&](auto x) { return a.permute_digit(4, 0, x); }, [&](auto x) { return b.permute_digit(4, 0, x); }));
  EXPECT_TRUE(
      differs([&](auto x) { return a.permute_digit(4, 0, x); }, [&](auto x) { return a.permute_digit(4, 1, x); }));
}

TEST(RandomDigitPermutations, MatchesTheDigitOracleAtAnyIndex) {
  const RandomDigitPermutations full(42, kBases);         // tables for every index
  const RandomDigitPermutations small(42, kBases, 1000);  // slow path past 1000
  for (unsigned dim = 0; dim < kBases.size(); ++dim)
    for (std::uint64_t index : {0ull, 1ull, 2ull, 999ull, 1000ull, 1001ull, 4096ull, 123456789ull, (1ull << 32) - 1,
                                1ull << 32, (1ull << 32) + 1, (1ull << 40) + 12345, (1ull << 53) + 3, ~0ull}) {
      const long double expected = oracle(full, dim, index);
      EXPECT_LE(full.sample(index, dim), expected) << dim << " " << index;
      EXPECT_GT(full.sample(index, dim), expected - 0x1.0p-53L - 0x1.0p-60L) << dim << " " << index;
      EXPECT_EQ(full.fraction(index, dim), small.fraction(index, dim)) << dim << " " << index;
    }
  // No wrap at 2^32: indices 2^32 + i and i differ.
  EXPECT_NE(full.sample((1ull << 32) + 1, 1), full.sample(1, 1));
}

// The digit 0 past an index's last digit is permuted too: index 0 maps to
// Σ π_j(0) b^-(j+1), which is 0 only if every π_j(0) = 0.
TEST(RandomDigitPermutations, TrailingZeroDigitsArePermuted) {
  int zeros = 0;
  for (std::uint64_t seed = 0; seed < 100; ++seed) zeros += RandomDigitPermutations(seed, {2}, 0).sample(0, 0) == 0.0;
  EXPECT_EQ(zeros, 0);
  // Index 1 in base 3 and index 1 + 3^5 share the first five output digits.
  const RandomDigitPermutations s(5, {3});
  EXPECT_LT(std::fabs(s.sample(1, 0) - s.sample(1 + 243, 0)), std::pow(3.0, -5));
}

TEST(RandomDigitPermutations, FirstBToTheKPointsStratifyTheUnitInterval) {
  for (std::uint64_t seed : {0ull, 9ull}) {
    const RandomDigitPermutations s(seed, kBases);
    for (unsigned dim = 0; dim < 4; ++dim)
      for (std::uint64_t count = kBases[dim]; count <= 3000; count *= kBases[dim]) {
        std::vector<int> hits(count, 0);
        for (std::uint64_t i = 0; i < count; ++i) ++hits[static_cast<std::size_t>(s.sample(i, dim) * count)];
        for (int h : hits) ASSERT_EQ(h, 1) << "base " << kBases[dim] << " count " << count;
      }
  }
}

// Over seeds, the permutation of one position in base 3 is uniform on the
// 6 permutations, and independent of the next position's (36 pairs).
// 3600 seeds; χ² tests at α = 1e-3 each (two tests: family α ≈ 2e-3).
TEST(RandomDigitPermutations, PermutationsAreUniformAndIndependentAcrossPositions) {
  const int seeds = 3600;
  std::vector<int> single(6, 0), joint(36, 0);
  auto code = [](const RandomDigitPermutations& s, unsigned j) {
    // A permutation of {0,1,2} is fixed by π(0) and the rank of π(1) among the other two.
    const std::uint32_t p0 = s.permute_digit(0, j, 0), p1 = s.permute_digit(0, j, 1);
    return static_cast<int>(p0 * 2 + p1 - (p1 > p0 ? 1 : 0));
  };
  for (int seed = 0; seed < seeds; ++seed) {
    const RandomDigitPermutations s(static_cast<std::uint64_t>(seed), {3}, 0);
    const int p0 = code(s, 0), p1 = code(s, 1);
    ++single[static_cast<std::size_t>(p0)];
    ++joint[static_cast<std::size_t>(p0 * 6 + p1)];
  }
  double x1 = 0, x2 = 0;
  for (int c : single) x1 += (c - seeds / 6.0) * (c - seeds / 6.0) / (seeds / 6.0);
  for (int c : joint) x2 += (c - seeds / 36.0) * (c - seeds / 36.0) / (seeds / 36.0);
  EXPECT_GT(chi_squared_p(x1, 5), 1e-3) << x1;
  EXPECT_GT(chi_squared_p(x2, 35), 1e-3) << x2;
}

// For a fixed index, the scrambled coordinate is uniform on [0, 1) over
// seeds: 2000 seeds in 20 bins, χ² with 19 dof, for 5 indices × 5 bases (2, 3, 5,
// 7, 29) =
// 25 tests at family-wise α = 1e-3 (Šidák).
TEST(RandomDigitPermutations, EachCoordinateIsUniformOverSeeds) {
  const int seeds = 2000, bins = 20;
  const std::vector<std::uint32_t> bases = {2, 3, 5, 7, 29};
  const std::vector<std::uint64_t> indices = {0, 1, 17, 5000, (1ull << 33) + 17};
  const double level = sidak(1e-3, static_cast<int>(indices.size() * bases.size()));
  std::vector<std::vector<int>> counts(indices.size() * bases.size(), std::vector<int>(bins, 0));
  for (int seed = 0; seed < seeds; ++seed) {
    const RandomDigitPermutations s(static_cast<std::uint64_t>(seed), bases, 20);
    for (std::size_t k = 0; k < indices.size(); ++k)
      for (unsigned dim = 0; dim < bases.size(); ++dim)
        ++counts[k * bases.size() + dim][static_cast<std::size_t>(s.sample(indices[k], dim) * bins)];
  }
  for (std::size_t t = 0; t < counts.size(); ++t) {
    double x = 0;
    for (int c : counts[t]) x += (c - seeds / double(bins)) * (c - seeds / double(bins)) / (seeds / double(bins));
    EXPECT_GT(chi_squared_p(x, bins - 1), level)
        << "index " << indices[t / bases.size()] << " base " << bases[t % bases.size()] << " chi2 " << x;
  }
}

TEST(RandomDigitPermutations, DeterministicInAnyOrder) {
  std::vector<std::pair<std::uint64_t, unsigned>> queries;
  for (std::uint64_t k = 0; k < 300; ++k) queries.push_back({hash64(3, k) >> (k % 60), static_cast<unsigned>(k % 5)});
  const RandomDigitPermutations forward(77, kBases, 1u << 20);
  std::vector<double> first;
  for (auto [i, dim] : queries) first.push_back(forward.sample(i, dim));
  const RandomDigitPermutations backward(77, kBases);
  for (std::size_t k = queries.size(); k-- > 0;)
    ASSERT_EQ(backward.sample(queries[k].first, queries[k].second), first[k]);
  EXPECT_EQ(forward.sample(queries[0].first, queries[0].second), first[0]);  // repeated: same
}

TEST(RandomDigitPermutations, FloatIsTheRoundedDouble) {
  const RandomDigitPermutations s(8, kBases);
  for (unsigned dim = 0; dim < kBases.size(); ++dim)
    for (std::uint64_t i = 0; i < 2000; i += 13) {
      const double x = s.sample(i, dim);
      const float f = s.sample<float>(i, dim);
      ASSERT_EQ(f, to_unit_float(x));
      ASSERT_LT(f, 1.0f);
      ASSERT_LE(std::fabs(f - x), 0x1.0p-25);
    }
}

TEST(RandomDigitPermutations, DifferentSeedsDiffer) {
  const RandomDigitPermutations a(1, kBases), b(2, kBases);
  int same = 0;
  for (std::uint64_t i = 0; i < 100; ++i) same += a.sample(i, 1) == b.sample(i, 1);
  EXPECT_EQ(same, 0);
}

}  // namespace
}  // namespace stratum
