#include "stratum/patterns/sample_elimination.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

double min_distance(const std::vector<double>& points, const std::vector<std::uint32_t>& keep, unsigned d,
                    bool periodic) {
  double best = 1e9;
  for (std::size_t a = 0; a < keep.size(); ++a)
    for (std::size_t b = a + 1; b < keep.size(); ++b) {
      double sum = 0;
      for (unsigned j = 0; j < d; ++j) {
        double delta = std::abs(points[keep[a] * d + j] - points[keep[b] * d + j]);
        if (periodic) delta = std::min(delta, 1 - delta);
        sum += delta * delta;
      }
      best = std::min(best, sum);
    }
  return std::sqrt(best);
}

TEST(SampleElimination, PackingConstants) {
  EXPECT_NEAR(unit_ball_volume(1), 2.0, 1e-15);
  EXPECT_NEAR(unit_ball_volume(2), std::numbers::pi, 1e-15);
  EXPECT_NEAR(unit_ball_volume(3), 4 * std::numbers::pi / 3, 1e-14);
  EXPECT_NEAR(densest_packing_density(2), std::numbers::pi / std::sqrt(12.0), 1e-15);
  EXPECT_NEAR(densest_packing_density(3), std::numbers::pi / std::sqrt(18.0), 1e-15);
  // Yuksel's 2D value: 2 r_max = 2 sqrt(1 / (2 sqrt(3) n)).
  EXPECT_NEAR(largest_minimum_distance(100, 2), 2 * std::sqrt(1 / (2 * std::sqrt(3.0) * 100)), 1e-15);
}

// Thinning 5n random points to n keeps exactly n distinct indices, in
// ascending order, and spreads them far better than keeping a random n: the
// minimum distance of 200 uniform points is about sqrt(1/(2·200²)) ≈ 0.0035
// in 2D, while elimination keeps more than half of the hexagonal optimum
// (0.076 for 200 points). Asserted: above 0.5·optimum and twice random.
TEST(SampleElimination, KeepsExactlyNWellSpreadPoints) {
  for (bool periodic : {false, true}) {
    const unsigned d = 2;
    const std::size_t count = 1000, keep = 200;
    std::vector<double> points(count * d);
    for (std::size_t k = 0; k < points.size(); ++k) points[k] = uniform01(5, k);
    const auto kept = eliminate_samples(points.data(), count, d, keep, periodic);
    ASSERT_EQ(kept.size(), keep);
    EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
    EXPECT_TRUE(std::adjacent_find(kept.begin(), kept.end()) == kept.end());
    std::vector<std::uint32_t> first(keep);
    for (std::size_t i = 0; i < keep; ++i) first[i] = static_cast<std::uint32_t>(i);
    const double eliminated = min_distance(points, kept, d, periodic);
    const double random = min_distance(points, first, d, periodic);
    EXPECT_GT(eliminated, 0.5 * largest_minimum_distance(keep, d)) << periodic;
    EXPECT_GT(eliminated, 2 * random) << periodic;
    EXPECT_EQ(kept, eliminate_samples(points.data(), count, d, keep, periodic));  // deterministic
  }
}

TEST(SampleElimination, KeepingAllIsTheIdentity) {
  std::vector<double> points = {0.1, 0.2, 0.3};
  const auto kept = eliminate_samples(points.data(), 3, 1, 3, false);
  EXPECT_EQ(kept, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_THROW(eliminate_samples(points.data(), 3, 1, 4, false), invalid_argument);
  EXPECT_THROW(eliminate_samples(points.data(), 3, 1, 0, false), invalid_argument);
}

}  // namespace
}  // namespace stratum
