#include "stratum/patterns/strata.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <boost/math/distributions/chi_squared.hpp>

namespace stratum {
namespace {

// Exact membership: cell <= x * count < cell + 1 for the real product, which
// long double (64-bit mantissa) holds exactly for x with 53 bits and count < 2^11.
bool inside_exactly(double x, std::uint64_t cell, std::uint64_t count) {
  const long double p = static_cast<long double>(x) * static_cast<long double>(count);
  return p >= static_cast<long double>(cell) && p < static_cast<long double>(cell + 1);
}

TEST(CellCoordinate, OffsetCloseToOneStaysInItsCell) {
  const double almost_one = 0x1.fffffffffffffp-1;
  // 1 + (1 - 2^-53) rounds to 2 in double: the uncorrected value would leave cell 1.
  EXPECT_EQ(1.0 + almost_one, 2.0);
  for (std::uint64_t count : {1ull, 2ull, 3ull, 7ull, 10ull, 1000ull, 1023ull})
    for (std::uint64_t cell = 0; cell < count; cell += (count > 20 ? 37 : 1))
      for (double offset : {0.0, 0x1.0p-53, 0.5, almost_one}) {
        const double x = cell_coordinate(cell, offset, count);
        EXPECT_TRUE(inside_exactly(x, cell, count)) << cell << "/" << count << " offset " << offset;
        EXPECT_EQ(static_cast<std::uint64_t>(std::floor(x * static_cast<double>(count))), cell);
        const float xf = cell_coordinate<float>(cell, offset, count);
        EXPECT_TRUE(inside_exactly(xf, cell, count)) << "float " << cell << "/" << count;
        EXPECT_EQ(static_cast<std::uint64_t>(std::floor(xf * static_cast<float>(count))), cell);
        EXPECT_LT(xf, 1.0f);
      }
}

TEST(CellCoordinate, LargeCountsStillStratify) {
  const std::uint64_t count = 10'000'019;  // a prime: cell boundaries are not dyadic
  for (std::uint64_t cell : std::vector<std::uint64_t>{0, 1, 4999999, count - 2, count - 1})
    for (double offset : {0.0, 0.5, 0x1.fffffffffffffp-1}) {
      const double x = cell_coordinate(cell, offset, count);
      EXPECT_GE(std::fma(x, static_cast<double>(count), -static_cast<double>(cell)), 0.0);
      EXPECT_LT(std::fma(x, static_cast<double>(count), -static_cast<double>(cell + 1)), 0.0);
      EXPECT_EQ(static_cast<std::uint64_t>(x * static_cast<double>(count)), cell);
    }
}

/// below_exactly decides x·n < c with a multiply and, only on a tie, fma:
/// against fma's exact sign for x walked across c/n ulp by ulp (ties
/// included: fl(x·n) = c with x·n just below or above c).
TEST(CellCoordinate, BelowExactlyAgreesWithFmaAcrossBoundaries) {
  int ties = 0, checked = 0;
  for (double n : {3.0, 7.0, 10.0, 1000.0, 1023.0, 10000019.0, 0x1.0p40 + 1})
    for (double c : {1.0, 2.0, 5.0, 999.0, 4999999.0}) {
      double x = c / n;
      for (int step = 0; step < 32; ++step) x = std::nextafter(x, 0.0);
      for (int step = 0; step < 64; ++step, x = std::nextafter(x, 2.0)) {
        ties += x * n == c && std::fma(x, n, -c) != 0;
        EXPECT_EQ(strata_detail::below_exactly(x, n, c), std::fma(x, n, -c) < 0) << x << " " << n << " " << c;
        ++checked;
      }
    }
  EXPECT_GT(ties, 0);  // the case that needs fma was met
  EXPECT_EQ(checked, 7 * 5 * 64);
}

/// The same points as the correction written with fma on both sides
/// (stratum's rule before the multiply-first tests), over random offsets,
/// counts and cells, and offsets at the top of [0, 1).
TEST(CellCoordinate, SameAsTheFmaCorrection) {
  const auto with_fma = [](std::uint64_t cell, double offset, std::uint64_t count) {
    const double n = double(count), lo = double(cell), hi = double(cell + 1);
    double x = (lo + offset) / n;
    while (std::fma(x, n, -hi) >= 0 || x * n >= hi) x = std::nextafter(x, 0.0);
    while (std::fma(x, n, -lo) < 0) x = std::nextafter(x, 1.0);
    return x;
  };
  for (std::uint64_t i = 0; i < 200000; ++i) {
    const std::uint64_t count = 1 + hash64(i, 1) % (i % 2 ? 1000 : 100000000);
    const std::uint64_t cell = hash64(i, 2) % count;
    const double offset = i % 4 == 0 ? 0x1.fffffffffffffp-1 - double(i % 64) * 0x1.0p-53 : bits_to_double(hash64(i, 3));
    ASSERT_EQ(cell_coordinate(cell, offset, count), with_fma(cell, offset, count))
        << cell << "/" << count << " " << offset;
  }
}

TEST(CellCoordinate, CentreIsCorrectlyRounded) {
  for (std::uint64_t count : {3ull, 5ull, 6ull, 7ull, 100ull})
    for (std::uint64_t cell = 0; cell < count; ++cell)
      EXPECT_EQ(cell_coordinate(cell, 0.5, count),
                (2.0 * static_cast<double>(cell) + 1.0) / (2.0 * static_cast<double>(count)));
}

TEST(IntegerRoot, ExactAroundPerfectPowers) {
  EXPECT_EQ(integer_root(0, 3), 0u);
  EXPECT_EQ(integer_root(1, 7), 1u);
  EXPECT_EQ(integer_root(63, 2), 7u);
  EXPECT_EQ(integer_root(64, 2), 8u);
  EXPECT_EQ(integer_root(64, 3), 4u);
  EXPECT_EQ(integer_root(124, 3), 4u);
  EXPECT_EQ(integer_root(125, 3), 5u);
  EXPECT_EQ(integer_root(~std::uint64_t{0}, 2), 4294967295u);
  EXPECT_EQ(integer_root(~std::uint64_t{0}, 64), 1u);
  // pow(10^18, 1/3) may round below 10^6; the root must still be exact.
  EXPECT_EQ(integer_root(1'000'000'000'000'000'000ull, 3), 1'000'000u);
  EXPECT_EQ(integer_root(1'000'000'000'000'000'000ull - 1, 3), 999'999u);
  EXPECT_FALSE(checked_power(1ull << 32, 2).has_value());
  EXPECT_EQ(*checked_power(3, 4), 81u);
}

// Square roots (a hardware first guess): every n below 2^17 against counting,
// and around k^2 for k up to 2^32 - 1.
TEST(IntegerRoot, SquareRootsExact) {
  std::uint64_t root = 0;
  for (std::uint64_t n = 0; n < (1u << 17); ++n) {
    while ((root + 1) * (root + 1) <= n) ++root;
    ASSERT_EQ(integer_root(n, 2), root) << n;
  }
  for (std::uint64_t k : {3ull, 94906265ull, 94906266ull, (1ull << 26) + 1, (1ull << 32) - 2, (1ull << 32) - 1}) {
    EXPECT_EQ(integer_root(k * k, 2), k) << k;
    EXPECT_EQ(integer_root(k * k - 1, 2), k - 1) << k;
    if (k < (1ull << 32) - 1) EXPECT_EQ(integer_root(k * k + 2 * k, 2), k) << k;  // (k + 1)^2 - 1
  }
}

TEST(StrataShape, MixedRadixCellsWithDimensionZeroFastest) {
  const StrataShape shape({4, 3, 2});
  EXPECT_EQ(shape.count(), 24u);
  EXPECT_EQ(shape.dimensions(), 3u);
  // index 17 = 1 + 4 * (1 + 3 * 1)
  EXPECT_EQ(shape.cell(17, 0), 1u);
  EXPECT_EQ(shape.cell(17, 1), 1u);
  EXPECT_EQ(shape.cell(17, 2), 1u);
  EXPECT_EQ(shape.cell(23, 0), 3u);
  EXPECT_EQ(shape.cell(23, 1), 2u);
  EXPECT_EQ(shape.cell(23, 2), 1u);
  EXPECT_THROW(StrataShape({4, 0}), invalid_argument);
  EXPECT_THROW(StrataShape({1ull << 40, 1ull << 40}), invalid_argument);
}

TEST(StrataShape, EqualNeedsAPerfectPowerAndSaysWhichNAreAllowed) {
  EXPECT_EQ(StrataShape::equal(64, 3).strata(2), 4u);
  EXPECT_EQ(StrataShape::equal(1, 20).count(), 1u);
  try {
    StrataShape::equal(10, 2);
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.argument(), "n");
    EXPECT_NE(what.find("n = 10"), std::string::npos) << what;
    EXPECT_NE(what.find("9 = 3^2"), std::string::npos) << what;
    EXPECT_NE(what.find("16 = 4^2"), std::string::npos) << what;
  }
}

TEST(RandomPermutation, IsAPermutationAndDependsOnlyOnTheKey) {
  std::vector<std::uint32_t> a(1000), b(1000);
  random_permutation(a.data(), a.size(), 42);
  random_permutation(b.data(), b.size(), 42);
  EXPECT_EQ(a, b);
  std::vector<bool> seen(a.size(), false);
  for (auto v : a) {
    ASSERT_LT(v, a.size());
    ASSERT_FALSE(seen[v]);
    seen[v] = true;
  }
  random_permutation(b.data(), b.size(), 43);
  EXPECT_NE(a, b);
}

// All 24 permutations of 4 elements equally likely: chi-square over 24 cells,
// 4800 keys, level 0.001.
TEST(RandomPermutation, UniformOverAllPermutations) {
  std::map<std::array<std::uint32_t, 4>, int> counts;
  const int keys = 4800;
  for (int k = 0; k < keys; ++k) {
    std::array<std::uint32_t, 4> p{};
    random_permutation(p.data(), 4, hash64(7, k));
    ++counts[p];
  }
  ASSERT_EQ(counts.size(), 24u);
  const double expected = keys / 24.0;
  double chi2 = 0;
  for (const auto& [p, c] : counts) chi2 += (c - expected) * (c - expected) / expected;
  const boost::math::chi_squared dist(23);
  EXPECT_LT(chi2, boost::math::quantile(boost::math::complement(dist, 0.001)));
}

}  // namespace
}  // namespace stratum
