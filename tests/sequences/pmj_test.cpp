#include "stratum/sequences/pmj.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <vector>

namespace stratum {
namespace {

// Stirling numbers of the first kind [n, k], exactly, by the recurrence, for
// an independent check of the generator matrices.
std::vector<std::vector<long double>> stirling_table(int size) {
  std::vector<std::vector<long double>> s(size + 1, std::vector<long double>(size + 1, 0));
  s[0][0] = 1;
  for (int n = 1; n <= size; ++n)
    for (int k = 1; k <= n; ++k) s[n][k] = s[n - 1][k - 1] + (n - 1) * s[n - 1][k];
  return s;
}

// Parity by Lucas: x(x+1)…(x+n−1) ≡ x^⌈n/2⌉ (x+1)^⌊n/2⌋ (mod 2), so
// [n, k] is odd iff binom(⌊n/2⌋, k − ⌈n/2⌉) is, iff that lower index is a
// submask of ⌊n/2⌋.
bool stirling_odd(unsigned n, unsigned k) {
  const unsigned half_up = (n + 1) / 2, half_down = n / 2;
  if (k < half_up || k > n) return false;
  const unsigned lower = k - half_up;
  return (lower & half_down) == lower;
}

TEST(Pmj02, GeneratorMatricesAreStirlingNumbersModTwo) {
  const auto s = stirling_table(20);
  for (unsigned c = 0; c < 20; ++c)
    for (unsigned r = 0; r < 20; ++r) {
      EXPECT_EQ((Pmj02::generator_column(0, c) >> r) & 1u, std::fmod(s[c][r], 2.0L) == 1.0L) << c << "," << r;
      EXPECT_EQ((Pmj02::generator_column(1, c) >> r) & 1u, std::fmod(s[c + 1][r + 1], 2.0L) == 1.0L) << c << "," << r;
    }
  for (unsigned c = 0; c < 64; ++c)
    for (unsigned r = 0; r < 64; ++r) {
      ASSERT_EQ((Pmj02::generator_column(0, c) >> r) & 1u, stirling_odd(c, r)) << c << "," << r;
      ASSERT_EQ((Pmj02::generator_column(1, c) >> r) & 1u, stirling_odd(c + 1, r + 1)) << c << "," << r;
    }
}

// Unscrambled digital point: digits C · (bits of index), as a row mask.
std::uint64_t digital(unsigned coordinate, std::uint64_t index) {
  std::uint64_t digits = 0;
  for (unsigned c = 0; c < 64; ++c)
    if ((index >> c) & 1u) digits ^= Pmj02::generator_column(coordinate, c);
  return digits;
}

TEST(Pmj02, XorValuesPointToThePointSharingTheFirstMDigits) {
  for (unsigned coordinate = 0; coordinate < 2; ++coordinate)
    for (unsigned m = 0; m < 64; ++m) {
      const std::uint64_t j = Pmj02::xor_value(coordinate, m);
      ASSERT_LT(j, std::uint64_t{1} << m) << m;
      const std::uint64_t first_m = m == 0 ? 0 : (~std::uint64_t{0} >> (64 - m));
      // Digits 1..m of point 2^m equal those of point x_m; digit m+1 differs.
      EXPECT_EQ(digital(coordinate, std::uint64_t{1} << m) & first_m, digital(coordinate, j) & first_m) << m;
      EXPECT_NE((digital(coordinate, std::uint64_t{1} << m) >> m) & 1u, (digital(coordinate, j) >> m) & 1u);
    }
}

// The first xor values agree with the table published with Helmer et al.'s
// reference code (sampling/xor_values.h, pmj02_xors), computed there from the
// same Stirling matrices by another method (numpy matrix inversion).
TEST(Pmj02, XorValuesMatchHelmersTable) {
  const std::uint64_t x[12] = {0x0, 0x0, 0x2, 0x6, 0x6, 0xe, 0x36, 0x4e, 0x16, 0x2e, 0x276, 0x6ce};
  const std::uint64_t y[12] = {0x0, 0x1, 0x3, 0x3, 0x7, 0x1b, 0x27, 0xb, 0x17, 0x13b, 0x367, 0x38b};
  for (unsigned m = 0; m < 12; ++m) {
    EXPECT_EQ(Pmj02::xor_value(0, m), x[m]) << m;
    EXPECT_EQ(Pmj02::xor_value(1, m), y[m]) << m;
  }
  EXPECT_EQ(Pmj02::xor_value(0, 31), 0x4000c0ceu);
  EXPECT_EQ(Pmj02::xor_value(1, 31), 0x808bu);
}

// Pinned output (regression guard: these bits are this implementation's
// choice of hash, so any change to them changes every user's samples).
TEST(Pmj02, PinnedValues) {
  const Pmj02 pmj(4, 2024);
  EXPECT_EQ(pmj.sample_bits(0, 0), 0xd5ff892408ea1503ull);
  EXPECT_EQ(pmj.sample_bits(1, 1), 0xb632030574c1989cull);
  EXPECT_EQ(pmj.sample_bits(5, 2), 0xba02d6ab7c6985e9ull);
  EXPECT_EQ(pmj.sample_bits(1000, 3), 0x229613cb70407e58ull);
  EXPECT_EQ(pmj.sample_bits((1ull << 40) + 3, 0), 0x65da3f9cd6b823a1ull);
  EXPECT_EQ(pmj.sample(1000, 3), static_cast<double>(0x229613cb70407e58ull >> 11) * 0x1.0p-53);
}

// Rank over GF(2) of rows given as 64-bit masks.
unsigned gf2_rank(std::vector<std::uint64_t> rows) {
  unsigned rank = 0;
  for (unsigned bit = 0; bit < 64 && rank < rows.size(); ++bit) {
    auto pivot = std::find_if(rows.begin() + rank, rows.end(), [&](std::uint64_t r) { return (r >> bit) & 1u; });
    if (pivot == rows.end()) continue;
    std::swap(*pivot, rows[rank]);
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (i != rank && ((rows[i] >> bit) & 1u)) rows[i] ^= rows[rank];
    ++rank;
  }
  return rank;
}

// Niederreiter's criterion: the pair (C_x, C_y) generates a digital
// (0,2)-sequence iff, for every m and a, the first a rows of C_x and the
// first m − a rows of C_y, restricted to the first m columns, are linearly
// independent. Checked for all m ≤ 64: the whole 64-bit index range.
TEST(Pmj02, StirlingMatricesGenerateADigitalZeroTwoSequence) {
  auto row = [](unsigned coordinate, unsigned r, unsigned m) {
    std::uint64_t mask = 0;
    for (unsigned c = 0; c < m; ++c) mask |= ((Pmj02::generator_column(coordinate, c) >> r) & 1u) << c;
    return mask;
  };
  for (unsigned m = 1; m <= 64; ++m)
    for (unsigned a = 0; a <= m; ++a) {
      std::vector<std::uint64_t> rows;
      for (unsigned r = 0; r < a; ++r) rows.push_back(row(0, r, m));
      for (unsigned r = 0; r < m - a; ++r) rows.push_back(row(1, r, m));
      ASSERT_EQ(gf2_rank(rows), m) << "m=" << m << " a=" << a;
    }
}

// One point in every 2^a × 2^(k−a) elementary interval of [begin, begin + 2^k).
void expect_net(const Pmj02& pmj, unsigned dx, unsigned dy, std::uint64_t begin, unsigned k) {
  const std::uint64_t n = std::uint64_t{1} << k;
  std::vector<std::uint64_t> x(n), y(n);
  for (std::uint64_t i = 0; i < n; ++i) x[i] = pmj.sample_bits(begin + i, dx), y[i] = pmj.sample_bits(begin + i, dy);
  std::vector<unsigned char> hits(n);
  for (unsigned a = 0; a <= k; ++a) {
    std::fill(hits.begin(), hits.end(), 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint64_t bx = a == 0 ? 0 : x[i] >> (64 - a);
      const std::uint64_t by = a == k ? 0 : y[i] >> (64 - (k - a));
      ASSERT_EQ(hits[(by << a) | bx]++, 0)
          << "seed " << pmj.seed() << " dims " << dx << "," << dy << " begin " << begin << " k=" << k << " a=" << a;
    }
  }
}

TEST(Pmj02, EveryPowerOfTwoPrefixIsAZeroKTwoNet) {
  for (std::uint64_t seed : {0ull, 1ull, 42ull, 0xdeadbeefull})
    for (unsigned k = 0; k <= 12; ++k) expect_net(Pmj02(2, seed), 0, 1, 0, k);
}

// The doubles (not only the 64-bit words) fall in the right strata, and
// 1D projections are stratified into 2^k intervals (the a = k and a = 0 cases).
TEST(Pmj02, DoublesAndFloatsKeepTheStrata) {
  const Pmj02 pmj(2, 7);
  const std::uint64_t n = 4096;
  std::vector<int> col(n), row(n), colf(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    ++col[static_cast<std::size_t>(pmj.sample(i, 0) * n)];
    ++row[static_cast<std::size_t>(pmj.sample(i, 1) * n)];
    ++colf[static_cast<std::size_t>(pmj.sample<float>(i, 0) * n)];
    ASSERT_LT(pmj.sample<float>(i, 1), 1.0f);
    ASSERT_NEAR(pmj.sample<float>(i, 1), pmj.sample(i, 1), 0x1.0p-24);
  }
  for (std::uint64_t c = 0; c < n; ++c) ASSERT_TRUE(col[c] == 1 && row[c] == 1 && colf[c] == 1) << c;
}

// A (0,2)-sequence: every aligned block [q 2^k, (q+1) 2^k) is a net, also
// far out in the 64-bit index range (no wrap at 2^32).
TEST(Pmj02, AlignedBlocksAreNetsAtLargeIndices) {
  const Pmj02 pmj(2, 3);
  expect_net(pmj, 0, 1, 256, 8);
  expect_net(pmj, 0, 1, 3 * 1024, 10);
  expect_net(pmj, 0, 1, std::uint64_t{5} << 32, 8);
  expect_net(pmj, 0, 1, 0xfffffffffffff000ull, 12);
  EXPECT_NE(pmj.sample_bits(std::uint64_t{1} << 32, 0), pmj.sample_bits(0, 0));
}

// Every realization is an Owen scrambling of the Stirling digital sequence:
// two points share exactly as many leading digits as their unscrambled
// points do (a nested scramble is a bijection of the digit tree).
TEST(Pmj02, SharesLeadingDigitsExactlyAsTheUnscrambledSequence) {
  for (std::uint64_t seed : {5ull, 6ull}) {
    const Pmj02 pmj(2, seed);
    for (unsigned coordinate = 0; coordinate < 2; ++coordinate)
      for (std::uint64_t p = 0; p < 256; ++p)
        for (std::uint64_t q = p + 1; q < 256; ++q) {
          // Row masks hold digit r at bit r; words hold digit r at bit 63 − r.
          const int unscrambled = std::countr_zero(digital(coordinate, p) ^ digital(coordinate, q));
          const int scrambled = std::countl_zero(pmj.sample_bits(p, coordinate) ^ pmj.sample_bits(q, coordinate));
          ASSERT_EQ(scrambled, unscrambled) << seed << " " << coordinate << " " << p << " " << q;
        }
  }
}

TEST(Pmj02, DependsOnlyOnSeedIndexAndDimension) {
  const Pmj02 a(4, 11), b(4, 11), c(4, 12);
  std::vector<std::uint64_t> forward;
  for (std::uint64_t i = 0; i < 512; ++i)
    for (unsigned j = 0; j < 4; ++j) forward.push_back(a.sample_bits(i, j));
  // Backwards and in a scrambled order on another instance: same bits.
  for (std::uint64_t i = 512; i-- > 0;)
    for (unsigned j = 4; j-- > 0;) ASSERT_EQ(b.sample_bits(i, j), forward[i * 4 + j]);
  for (std::uint64_t t = 0; t < 2048; ++t) {
    const std::uint64_t k = (t * 1237) % 2048;
    ASSERT_EQ(a.sample_bits(k / 4, static_cast<unsigned>(k % 4)), forward[k]);
  }
  int same = 0;
  for (std::uint64_t i = 0; i < 512; ++i) same += c.sample_bits(i, 0) == forward[i * 4];
  EXPECT_EQ(same, 0);
}

// Pairs (2,3), … are pmj02 sequences too (nets at power-of-two prefixes),
// and the first 2^k indices map onto themselves under the shuffle.
TEST(Pmj02, HigherPairsAreProgressiveNets) {
  const Pmj02 pmj(6, 9);
  for (unsigned k = 0; k <= 10; ++k) {
    expect_net(pmj, 2, 3, 0, k);
    expect_net(pmj, 4, 5, 0, k);
  }
  std::vector<std::uint64_t> image;
  for (std::uint64_t i = 0; i < 1024; ++i) image.push_back(pmj.shuffled_index(i, 1));
  std::sort(image.begin(), image.end());
  for (std::uint64_t i = 0; i < 1024; ++i) ASSERT_EQ(image[i], i);
  EXPECT_NE(pmj.shuffled_index(700, 1), pmj.shuffled_index(700, 2));
}

// Without the shuffle, dims 0 and 2 would share every leading digit pattern
// up to a fixed flip, putting all points in two diagonal quadrants. With
// it, the quadrant count of the (0, 2) projection over 64 seeds × 256 points
// is near 1/4 each: under independence each count is Binomial(16384, 1/4),
// sd 55; the bound ±8 sd is far beyond chance (p < 1e-14).
TEST(Pmj02, PairsAreDecorrelatedByTheShuffle) {
  std::array<int, 4> quadrants{};
  for (std::uint64_t seed = 0; seed < 64; ++seed) {
    const Pmj02 pmj(4, seed);
    for (std::uint64_t i = 0; i < 256; ++i)
      ++quadrants[(pmj.sample_bits(i, 0) >> 63) * 2 + (pmj.sample_bits(i, 2) >> 63)];
  }
  for (int q : quadrants) EXPECT_NEAR(q, 4096, 8 * 55.4) << q;
}

// Unbiasedness over seeds: 200 independent 16-point estimates of
// ∫∫ x y = 1/4 and ∫ x² = 1/3. Their mean is tested with a z-statistic
// against |z| < 4.42 (two-sided p = 1e-5, Šidák for two tests: 5e-6 each).
TEST(Pmj02, EstimatesAreUnbiasedOverSeeds) {
  const int seeds = 200, n = 16;
  std::vector<double> xy(seeds), xx(seeds);
  for (int s = 0; s < seeds; ++s) {
    const Pmj02 pmj(2, 1000 + static_cast<std::uint64_t>(s));
    double sum_xy = 0, sum_xx = 0;
    for (int i = 0; i < n; ++i) {
      const double x = pmj.sample(static_cast<std::uint64_t>(i), 0), y = pmj.sample(static_cast<std::uint64_t>(i), 1);
      sum_xy += x * y;
      sum_xx += x * x;
    }
    xy[static_cast<std::size_t>(s)] = sum_xy / n;
    xx[static_cast<std::size_t>(s)] = sum_xx / n;
  }
  auto z_score = [&](const std::vector<double>& v, double truth) {
    const double mean = std::accumulate(v.begin(), v.end(), 0.0) / seeds;
    double var = 0;
    for (double e : v) var += (e - mean) * (e - mean);
    var /= seeds - 1;
    EXPECT_GT(var, 0.0);
    // A 16-point (0,4,2)-net is far better than 16 random points (whose
    // variance for xy is 7/144/16 ≈ 3e-3).
    EXPECT_LT(var, 3e-4);
    return (mean - truth) / std::sqrt(var / seeds);
  };
  EXPECT_LT(std::abs(z_score(xy, 0.25)), 4.42);
  EXPECT_LT(std::abs(z_score(xx, 1.0 / 3)), 4.42);
}

TEST(Pmj02, RejectsBadDimensions) {
  EXPECT_THROW(Pmj02(0, 1), invalid_argument);
  EXPECT_THROW(Pmj02(65, 1), invalid_argument);
  EXPECT_NO_THROW(Pmj02(64, 1));
}

}  // namespace
}  // namespace stratum
