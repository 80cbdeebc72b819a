#include "stratum/patterns/grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace stratum {
namespace {

TEST(Grid, CellCentresExactly) {
  const Grid grid(StrataShape({4, 3}));
  ASSERT_EQ(grid.count(), 12u);
  // index 7 = 3 + 4 * 1: cell (3, 1)
  EXPECT_EQ(grid.sample(7, 0), 0.875);
  EXPECT_EQ(grid.sample(7, 1), 0.5);
  EXPECT_EQ(grid.sample(0, 0), 0.125);
  EXPECT_EQ(grid.sample(0, 1), 1.0 / 6.0);
  EXPECT_EQ(grid.sample(11, 1), 5.0 / 6.0);
  for (std::uint64_t i = 0; i < 12; ++i) {
    EXPECT_EQ(grid.sample(i, 0), (static_cast<double>(i % 4) + 0.5) / 4.0);
    EXPECT_EQ(grid.sample(i, 1), (static_cast<double>(i / 4) + 0.5) / 3.0);
    EXPECT_EQ(grid.sample<float>(i, 1), static_cast<float>((static_cast<double>(i / 4) + 0.5) / 3.0));
  }
}

TEST(Grid, EqualStrataVisitEveryCellOnce) {
  for (unsigned d = 1; d <= 4; ++d) {
    const Grid grid(StrataShape::equal(std::uint64_t{1} << (2 * d), d));  // 4 strata per dimension
    std::set<std::vector<double>> points;
    for (std::uint64_t i = 0; i < grid.count(); ++i) {
      std::vector<double> p;
      for (unsigned j = 0; j < d; ++j) {
        const double x = grid.sample(i, j);
        ASSERT_TRUE(x == 0.125 || x == 0.375 || x == 0.625 || x == 0.875) << x;
        p.push_back(x);
      }
      points.insert(p);
    }
    EXPECT_EQ(points.size(), grid.count()) << "d = " << d;
  }
}

// The midpoint rule integrates x^2 with error -1/(12 n^2) per dimension: a
// closed form the grid must reproduce to rounding.
TEST(Grid, MidpointRuleErrorMatchesTheClosedForm) {
  for (std::uint64_t n : {5ull, 16ull, 101ull}) {
    const Grid grid(StrataShape({n}));
    double sum = 0;
    for (std::uint64_t i = 0; i < n; ++i) sum += grid.sample(i, 0) * grid.sample(i, 0);
    const double nd = static_cast<double>(n);
    EXPECT_NEAR(sum / nd - 1.0 / 3.0, -1.0 / (12.0 * nd * nd), 1e-15);
  }
}

}  // namespace
}  // namespace stratum
