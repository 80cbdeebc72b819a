#include "stratum/patterns/latin_square.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <map>
#include <vector>

#include "unbiased.hpp"

namespace stratum {
namespace {

std::vector<std::uint32_t> square_of(const LatinSquare& square) {
  std::vector<std::uint32_t> symbols(square.count()), scratch(square.scratch_size());
  square.fill_symbols(symbols.data(), scratch.data());
  return symbols;
}

void expect_latin(const std::vector<std::uint32_t>& symbols, std::uint64_t m, const std::string& what) {
  ASSERT_EQ(symbols.size(), m * m);
  for (std::uint64_t r = 0; r < m; ++r) {
    std::vector<int> in_row(m, 0), in_col(m, 0);
    for (std::uint64_t c = 0; c < m; ++c) {
      ASSERT_LT(symbols[r * m + c], m) << what;
      ASSERT_EQ(++in_row[symbols[r * m + c]], 1) << what << ": row " << r;
      ASSERT_EQ(++in_col[symbols[c * m + r]], 1) << what << ": column " << r;
    }
  }
}

using Method = LatinSquare::Method;

TEST(LatinSquare, EveryMethodGivesALatinSquare) {
  for (std::uint64_t m : {1ull, 2ull, 3ull, 4ull, 5ull, 7ull, 16ull, 33ull})
    for (std::uint64_t seed : {0ull, 1ull, 2ull}) {
      expect_latin(square_of(LatinSquare(m, seed, Method::jacobson_matthews)), m, "jm m=" + std::to_string(m));
      expect_latin(square_of(LatinSquare(m, seed, Method::permuted_cyclic)), m, "cyclic m=" + std::to_string(m));
    }
}

// After any number of moves, including ones that stop in an improper state
// (the chain then runs on to the next proper square), the result is Latin.
TEST(LatinSquare, ChainStopsOnlyAtProperSquares) {
  for (std::uint64_t steps = 0; steps <= 60; ++steps) {
    expect_latin(square_of(LatinSquare(6, 3, Method::jacobson_matthews, steps)), 6, "steps=" + std::to_string(steps));
  }
  // Zero steps leave the cyclic start.
  const auto start = square_of(LatinSquare(5, 3, Method::jacobson_matthews, 0));
  for (std::uint64_t r = 0; r < 5; ++r)
    for (std::uint64_t c = 0; c < 5; ++c) EXPECT_EQ(start[r * 5 + c], (r + c) % 5);
}

// Jacobson–Matthews samples all 576 Latin squares of order 4 uniformly:
// chi-square over 576 cells with 11520 seeds (20 per square), level 0.001,
// with the default chain length of m^2 = 16 proper moves.
TEST(LatinSquare, JacobsonMatthewsIsUniformOnOrderFour) {
  const int seeds = 11520;
  std::map<std::vector<std::uint32_t>, int> counts;
  for (int s = 0; s < seeds; ++s)
    ++counts[square_of(LatinSquare(4, static_cast<std::uint64_t>(s), Method::jacobson_matthews))];
  ASSERT_EQ(counts.size(), 576u);
  const double expected = seeds / 576.0;
  double chi2 = 0;
  for (const auto& [square, c] : counts) chi2 += (c - expected) * (c - expected) / expected;
  const boost::math::chi_squared dist(575);
  EXPECT_LT(chi2, boost::math::quantile(boost::math::complement(dist, 0.001)));
}

TEST(LatinSquare, PermutedCyclicReachesOnlyIsotopesOfTheCyclicGroup) {
  // Order 4 has 576 Latin squares in two isotopy classes: 3 of the 4 reduced
  // squares are isotopes of Z_4 (3 x 4! x 3! = 432 squares), 1 of Z_2 x Z_2
  // (144). 6000 seeds reach all 432 (each missed with probability e^-13.9).
  std::map<std::vector<std::uint32_t>, int> counts;
  for (int s = 0; s < 6000; ++s)
    ++counts[square_of(LatinSquare(4, static_cast<std::uint64_t>(s), Method::permuted_cyclic))];
  EXPECT_EQ(counts.size(), 432u);
}

// The m² points form an orthogonal array of strength 2: each 2D projection
// has one point per m × m cell.
TEST(LatinSquare, EveryTwoDimensionalProjectionIsAJitteredGrid) {
  for (Method method : {Method::jacobson_matthews, Method::permuted_cyclic}) {
    const std::uint64_t m = 12;
    const LatinSquare square(m, 9, method);
    const auto symbols = square_of(square);
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = a + 1; b < 3; ++b) {
        std::vector<int> hits(m * m, 0);
        for (std::uint64_t i = 0; i < m * m; ++i) {
          const double u = square.coordinate(i, a, symbols[i]), v = square.coordinate(i, b, symbols[i]);
          ASSERT_TRUE(u >= 0 && u < 1 && v >= 0 && v < 1);
          ++hits[static_cast<std::size_t>(std::floor(u * m)) * m + static_cast<std::size_t>(std::floor(v * m))];
        }
        for (int h : hits) ASSERT_EQ(h, 1) << "projection (" << a << ", " << b << ")";
      }
    // Symbol coordinate lies in the cell of the symbol.
    EXPECT_EQ(static_cast<std::uint32_t>(square.coordinate(5, 2, symbols[5]) * m), symbols[5]);
  }
}

// coordinate() as written out: row, column or symbol, jittered by
// uniform01(hash64(seed, tag), index, dim) (the chained jitter key gives it).
TEST(LatinSquare, CoordinatesEqualTheJitteredCellsWrittenOut) {
  for (const std::uint64_t m : {1ull, 2ull, 5ull, 12ull})
    for (const std::uint64_t seed : {0ull, 4ull, 0xfeedfacecafebeefull}) {
      const LatinSquare square(m, seed);
      const std::vector<std::uint32_t> symbols = square_of(square);
      for (std::uint64_t index = 0; index < m * m; ++index)
        for (unsigned dim = 0; dim < 3; ++dim) {
          const std::uint64_t cell = dim == 0 ? index / m : dim == 1 ? index % m : symbols[index];
          const double expected =
              cell_coordinate(cell, uniform01<double>(hash64(seed, 0x4c534a4954ULL), index, dim), m);
          ASSERT_EQ(square.coordinate(index, dim, symbols[index]), expected) << m << " " << index << " " << dim;
          ASSERT_EQ(square.coordinate_from(square.jitter_key(), index, dim, symbols[index]), expected);
        }
    }
}

TEST(LatinSquare, RejectsBadOrders) {
  EXPECT_THROW(LatinSquare(0, 0), invalid_argument);
  EXPECT_THROW(LatinSquare(70000, 0), invalid_argument);
  EXPECT_EQ(LatinSquare(10, 0).steps(), 100u);
}

// Unbiased over 400 seeds for both methods: family level 0.001 (Šidák).
TEST(LatinSquare, UnbiasedOverSeeds) {
  const double alpha = testing::sidak(0.001, 2);
  for (Method method : {Method::jacobson_matthews, Method::permuted_cyclic}) {
    const auto estimates = testing::estimates_over_seeds(400, 3, [&](std::uint64_t seed) {
      const LatinSquare square(3, seed, method);
      const auto symbols = square_of(square);
      std::vector<double> x;
      for (std::uint64_t i = 0; i < 9; ++i)
        for (unsigned j = 0; j < 3; ++j) x.push_back(square.coordinate(i, j, symbols[i]));
      return x;
    });
    testing::expect_unbiased("latin-square", estimates, testing::test_integral(3), alpha);
  }
}

}  // namespace
}  // namespace stratum
