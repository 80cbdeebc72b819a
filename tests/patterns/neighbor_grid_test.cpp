#include "stratum/patterns/neighbor_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "brute_distance.hpp"

#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

std::vector<double> random_points(std::size_t n, unsigned d, std::uint64_t seed) {
  std::vector<double> points(n * d);
  for (std::size_t k = 0; k < points.size(); ++k) points[k] = uniform01(seed, k);
  return points;
}

// Squared distance from point p to the box [lo, hi], by brute force.
double brute_box_distance2(const double* p, const double* lo, const double* hi, unsigned d, bool periodic) {
  double sum = 0;
  for (unsigned j = 0; j < d; ++j) {
    double best = 1e9;
    for (double shift : {-1.0, 0.0, 1.0}) {
      if (!periodic && shift != 0.0) continue;
      const double q = p[j] + shift;
      best = std::min(best, std::max(0.0, std::max(lo[j] - q, q - hi[j])));
    }
    sum += best * best;
  }
  return sum;
}

// Every point within the radius of a query is visited (the grid may visit
// more; none is missed), for point and box queries, Euclidean and toroidal,
// radii below and above one cell, and grids of 1 and 2 cells per axis.
TEST(NeighborGrid, VisitsEveryPointWithinTheRadius) {
  for (unsigned d = 1; d <= 4; ++d)
    for (bool periodic : {false, true})
      for (std::uint64_t cells : {1u, 2u, 3u, 7u}) {
        const std::size_t n = 300;
        const std::vector<double> points = random_points(n, d, 11 + d);
        NeighborGrid grid(d, cells, periodic);
        for (std::size_t i = 0; i < n; ++i) grid.insert(static_cast<std::uint32_t>(i), points.data() + i * d);
        for (double radius : {0.05, 0.2, 0.45}) {
          for (int query = 0; query < 20; ++query) {
            double lo[4], hi[4];
            for (unsigned j = 0; j < d; ++j) {
              const double a = uniform01(99, query, j), b = uniform01(98, query, j) * 0.2;
              lo[j] = a;
              hi[j] = query % 2 == 0 ? a : std::min(1.0, a + b);  // points, then boxes
            }
            std::set<std::uint32_t> visited;
            grid.visit_near_box(lo, hi, radius, [&](std::uint32_t i) {
              EXPECT_TRUE(visited.insert(i).second) << "visited twice";
              return true;
            });
            for (std::size_t i = 0; i < n; ++i) {
              if (brute_box_distance2(points.data() + i * d, lo, hi, d, periodic) >= radius * radius) continue;
              ASSERT_TRUE(visited.count(static_cast<std::uint32_t>(i)))
                  << "d=" << d << " periodic=" << periodic << " cells=" << cells << " radius=" << radius;
            }
          }
        }
      }
}

TEST(NeighborGrid, StopsWhenTheVisitorSaysSo) {
  NeighborGrid grid(2, 4, false);
  const std::vector<double> points = random_points(50, 2, 3);
  for (std::uint32_t i = 0; i < 50; ++i) grid.insert(i, points.data() + 2 * i);
  const double x[2] = {0.5, 0.5};
  int calls = 0;
  EXPECT_FALSE(grid.visit_near(x, 1.0, [&](std::uint32_t) { return ++calls < 3; }));
  EXPECT_EQ(calls, 3);
}

TEST(NeighborGrid, ToroidalDistanceWraps) {
  NeighborGrid grid(2, 4, true);
  const double a[2] = {0.05, 0.95}, b[2] = {0.95, 0.05};
  EXPECT_NEAR(grid.distance_squared(a, b), 0.02, 1e-15);
  NeighborGrid flat(2, 4, false);
  EXPECT_NEAR(flat.distance_squared(a, b), 1.62, 1e-15);
  EXPECT_EQ(testing::distance2(a, b, 2, true), grid.distance_squared(a, b));
}

TEST(NeighborGrid, RejectsBadShapes) {
  EXPECT_THROW(NeighborGrid(0, 4, false), invalid_argument);
  EXPECT_THROW(NeighborGrid(9, 4, false), invalid_argument);
  EXPECT_THROW(NeighborGrid(2, 0, false), invalid_argument);
  EXPECT_THROW(NeighborGrid(4, 1u << 12, false), invalid_argument);  // 2^48 cells
}

}  // namespace
}  // namespace stratum
