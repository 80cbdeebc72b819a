// Tests of the local-discrepancy picture and the box of the supremum
// (local_discrepancy.hpp). Oracles: the exact 2D star-discrepancy sweep
// (an independent algorithm), direct counting of every corner, and hand
// computed one- and two-point sets.
#include "stratum/analysis/local_discrepancy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

PointSet points_of(const std::string& sampler, std::size_t n, std::uint64_t seed, const std::string& randomize = "") {
  SamplerRequest request;
  request.n = n;
  request.d = 2;
  request.seed = seed;
  request.randomize = randomize;
  return generate_points(sampler, request);
}

std::size_t count_open(const PointView& p, double x, double y) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < p.n; ++i) count += p(i, 0) < x && p(i, 1) < y;
  return count;
}

std::size_t count_closed(const PointView& p, double x, double y) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < p.n; ++i) count += p(i, 0) <= x && p(i, 1) <= y && p(i, 0) < 1 && p(i, 1) < 1;
  return count;
}

TEST(StarDiscrepancyBox, ValueEqualsTheExactSweepAndTheBoxReproducesIt) {
  for (const auto& [sampler, randomize] : {std::pair<std::string, std::string>{"random", ""},
                                           {"jittered", ""},
                                           {"hammersley", "none"},
                                           {"halton", "none"},
                                           {"n-rooks", ""}})
    for (std::size_t n : {1u, 2u, 7u, 16u, 64u, 200u}) {
      if (sampler == "jittered" && std::sqrt(n) != std::floor(std::sqrt(n))) continue;
      const PointSet points = points_of(sampler, n, 3 + n, randomize);
      const PointView view{points.data.get(), points.n, 2};
      const auto box = star_discrepancy_box(view);
      EXPECT_NEAR(box.value, star_discrepancy_2d(view), 1e-13) << sampler << " " << n;
      // The reported box, counted directly, gives the reported value.
      const std::size_t count = box.closed ? count_closed(view, box.x, box.y) : count_open(view, box.x, box.y);
      EXPECT_EQ(count, box.count);
      const double local =
          box.closed ? static_cast<double>(count) / n - box.x * box.y : box.x * box.y - static_cast<double>(count) / n;
      EXPECT_NEAR(local, box.value, 1e-15);
    }
}

TEST(StarDiscrepancyBox, OnePointByHand) {
  // One point at (0.3, 0.6): too few in [0,1)² minus... the largest of
  // 1·1 − 0 (open box at (1,1) holds it: n = 1, so 1 − 1 = 0), 0.3·1 − 0 at
  // (0.3, 1), 1·0.6 − 0 at (1, 0.6), and the closed box at (0.3, 0.6):
  // 1 − 0.18 = 0.82.
  const double xy[2] = {0.3, 0.6};
  const auto box = star_discrepancy_box({xy, 1, 2});
  EXPECT_DOUBLE_EQ(box.value, 0.82);
  EXPECT_TRUE(box.closed);
  EXPECT_EQ(box.x, 0.3);
  EXPECT_EQ(box.y, 0.6);
  // A point at x = 1 lies in no box (half-open boxes, x ≤ 1): D* = 1 at (1, 1).
  const double edge[2] = {1.0, 0.5};
  const auto empty = star_discrepancy_box({edge, 1, 2});
  EXPECT_DOUBLE_EQ(empty.value, 1.0);
  EXPECT_FALSE(empty.closed);
}

TEST(LocalDiscrepancyGrid, MatchesDirectCountsAtEveryCorner) {
  const PointSet points = points_of("random", 50, 11);
  const PointView view{points.data.get(), points.n, 2};
  for (std::size_t r : {1u, 3u, 10u, 17u}) {
    const auto grid = local_discrepancy_grid(view, r);
    ASSERT_EQ(grid.values.size(), (r + 1) * (r + 1));
    double max_abs = 0;
    for (std::size_t j = 0; j <= r; ++j)
      for (std::size_t i = 0; i <= r; ++i) {
        const double x = static_cast<double>(i) / r, y = static_cast<double>(j) / r;
        const double expected = static_cast<double>(count_open(view, x, y)) / 50 - x * y;
        EXPECT_NEAR(grid.values[j * (r + 1) + i], expected, 1e-15) << r << " " << i << " " << j;
        max_abs = std::max(max_abs, std::fabs(expected));
      }
    EXPECT_NEAR(grid.max_abs, max_abs, 1e-15);
    EXPECT_LE(grid.max_abs, star_discrepancy_2d(view) + 1e-15);  // a lower bound on the supremum
  }
}

TEST(LocalDiscrepancyGrid, PointsOnGridLinesCountOnTheCorrectSide) {
  // x = 0.5 exactly lies in [0, 0.75) but not in [0, 0.5).
  const double xy[4] = {0.5, 0.25, 0.25, 0.5};
  const auto grid = local_discrepancy_grid({xy, 2, 2}, 4);
  const auto at = [&](int i, int j) { return grid.values[j * 5 + i]; };
  EXPECT_DOUBLE_EQ(at(2, 2), 0.0 - 0.25);    // neither point in [0,.5)²
  EXPECT_DOUBLE_EQ(at(3, 2), 0.5 - 0.375);   // (0.5, 0.25) in [0,.75)×[0,.5)
  EXPECT_DOUBLE_EQ(at(3, 3), 1.0 - 0.5625);  // both
}

TEST(LocalDiscrepancy, RejectsBadInput) {
  const double xyz[3] = {0.1, 0.2, 0.3};
  EXPECT_THROW(local_discrepancy_grid({xyz, 1, 3}, 8), invalid_argument);
  EXPECT_THROW(local_discrepancy_grid({xyz, 1, 2}, 0), invalid_argument);
  EXPECT_THROW(local_discrepancy_grid({xyz, 1, 2}, 5000), invalid_argument);
  EXPECT_THROW(star_discrepancy_box({xyz, 1, 3}), invalid_argument);
  EXPECT_THROW(star_discrepancy_box({xyz, 0, 2}), invalid_argument);
}

}  // namespace
}  // namespace stratum::analysis
