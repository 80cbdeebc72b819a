#include "stratum/patterns/n_queens.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <set>
#include <vector>

#include "unbiased.hpp"

namespace stratum {
namespace {

// n cells (x[i], y[i]) in an n × n grid: distinct rows, columns, diagonals
// and anti-diagonals.
void expect_queens(const std::vector<std::uint64_t>& x, const std::vector<std::uint64_t>& y, const std::string& what) {
  const std::size_t n = x.size();
  std::vector<int> cols(n, 0), rows(n, 0), diag(2 * n, 0), anti(2 * n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_LT(x[i], n);
    ASSERT_LT(y[i], n);
    ASSERT_EQ(++cols[x[i]], 1) << what;
    ASSERT_EQ(++rows[y[i]], 1) << what;
    ASSERT_EQ(++diag[x[i] + n - y[i]], 1) << what;
    ASSERT_EQ(++anti[x[i] + y[i]], 1) << what;
  }
}

TEST(NQueens, ExplicitSolutionsAreSolutionsForEveryN) {
  for (std::uint64_t n = 4; n <= 600; ++n) {
    std::vector<std::uint64_t> x(n), y(n);
    for (std::uint64_t r = 0; r < n; ++r) {
      x[r] = r;
      y[r] = NQueens::explicit_column(r, n);
    }
    expect_queens(x, y, "explicit n=" + std::to_string(n));
  }
}

// The points themselves (after the random modular choice and symmetry, and
// jitter) satisfy the n-queens condition when binned into n × n cells.
TEST(NQueens, PointsSatisfyTheQueensCondition) {
  for (std::uint64_t n : {1ull, 4ull, 5ull, 6ull, 7ull, 8ull, 9ull, 12ull, 25ull, 35ull, 64ull, 100ull, 143ull, 256ull, 1001ull})
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
      const NQueens queens(n, seed);
      std::vector<std::uint64_t> x(n), y(n);
      for (std::uint64_t i = 0; i < n; ++i) {
        const double u = queens.sample(i, 0), v = queens.sample(i, 1);
        ASSERT_TRUE(u >= 0 && u < 1 && v >= 0 && v < 1) << u << ", " << v;
        x[i] = static_cast<std::uint64_t>(std::floor(u * static_cast<double>(n)));
        y[i] = static_cast<std::uint64_t>(std::floor(v * static_cast<double>(n)));
        ASSERT_EQ(x[i], queens.cell(i, 0));
        ASSERT_EQ(y[i], queens.cell(i, 1));
      }
      expect_queens(x, y, "n=" + std::to_string(n) + " seed=" + std::to_string(seed));
    }
}

TEST(NQueens, ModularWhenCoprimeToSixAndSeedsChooseAmongSolutions) {
  EXPECT_TRUE(NQueens(25, 0).modular());
  EXPECT_TRUE(NQueens(7, 0).modular());
  EXPECT_FALSE(NQueens(9, 0).modular());
  EXPECT_FALSE(NQueens(8, 0).modular());
  // 40 seeds reach all 8 symmetries, and for n = 11 several modular solutions.
  std::set<unsigned> symmetries;
  std::set<std::vector<std::uint64_t>> solutions;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    symmetries.insert(NQueens(8, seed).symmetry());
    const NQueens q(11, seed);
    std::vector<std::uint64_t> cells;
    for (std::uint64_t i = 0; i < 11; ++i) cells.push_back(q.base_column(i));
    solutions.insert(cells);
  }
  EXPECT_EQ(symmetries.size(), 8u);
  EXPECT_GT(solutions.size(), 20u);
}

TEST(NQueens, NoSolutionForTwoOrThreeSaysWhichNAreAllowed) {
  for (std::uint64_t n : {0ull, 2ull, 3ull}) {
    try {
      NQueens(n, 0);
      FAIL() << "no exception for n = " << n;
    } catch (const invalid_argument& e) {
      EXPECT_EQ(e.argument(), "n");
      EXPECT_NE(std::string(e.what()).find("n = " + std::to_string(n)), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("n = 1 or n >= 4"), std::string::npos) << e.what();
    }
  }
}

// With gcd(n, 6) = 1 every cell is occupied with probability 1/n, so the
// estimates are unbiased: n = 7, 400 seeds, level 0.001.
TEST(NQueens, UnbiasedWhenModular) {
  testing::expect_unbiased("n-queens 7", testing::estimates_over_seeds(400, 2, [](std::uint64_t seed) {
                             const NQueens q(7, seed);
                             std::vector<double> x;
                             for (std::uint64_t i = 0; i < 7; ++i) {
                               x.push_back(q.sample(i, 0));
                               x.push_back(q.sample(i, 1));
                             }
                             return x;
                           }),
                           testing::test_integral(2), 0.001);
}

}  // namespace
}  // namespace stratum
