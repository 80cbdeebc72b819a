#include "stratum/patterns/poisson_disk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "brute_distance.hpp"

#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

using testing::distance2;
using testing::min_distance;

// Distance from q to the nearest point, by brute force.
double nearest(const std::vector<double>& points, const double* q, unsigned d, bool periodic) {
  double best = 1e300;
  for (std::size_t a = 0; a < points.size() / d; ++a) best = std::min(best, distance2(&points[a * d], q, d, periodic));
  return std::sqrt(best);
}

// Largest distance from a probe to the nearest point. Probes: a regular grid
// of `per_axis`^d points (cell centres and the cube's corners included) and
// 2000 random points. Maximality says *every* point of the cube is within r
// of a sample, and probes are points of the cube, so each probe must pass
// exactly (up to rounding); the spacing h = 1/per_axis only bounds the holes
// that could slip through: any hole containing a ball of radius h·√d/2
// contains a probe.
double largest_gap(const std::vector<double>& points, unsigned d, bool periodic, int per_axis) {
  double worst = 0, q[4];
  std::vector<int> index(d, 0);
  for (;;) {
    for (unsigned j = 0; j < d; ++j) q[j] = std::min(static_cast<double>(index[j]) / (per_axis - 1), 1.0);
    worst = std::max(worst, nearest(points, q, d, periodic));
    unsigned j = 0;
    while (j < d && ++index[j] == per_axis) index[j++] = 0;
    if (j == d) break;
  }
  for (int k = 0; k < 2000; ++k) {
    for (unsigned j = 0; j < d; ++j) q[j] = uniform01(4242, k, j);
    worst = std::max(worst, nearest(points, q, d, periodic));
  }
  return worst;
}

struct Case {
  unsigned d;
  double radius;
  int probes_per_axis;
};
// Radii giving a few hundred to ~2000 points, so that brute force stays fast.
const Case cases[] = {{1, 0.002, 2001}, {2, 0.03, 100}, {3, 0.12, 26}, {4, 0.25, 12}};

TEST(PoissonDisk, MinimumDistanceIsAtLeastTheRadius) {
  for (const Case& c : cases)
    for (bool periodic : {false, true})
      for (unsigned candidates : {1u, 30u}) {
        const std::vector<double> points = PoissonDisk(c.d, c.radius, 3, candidates, periodic).maximal_set();
        ASSERT_GE(points.size() / c.d, 2u);
        for (double v : points) {
          ASSERT_GE(v, 0.0);
          ASSERT_LT(v, 1.0);
        }
        EXPECT_GE(min_distance(points, c.d, periodic), c.radius)
            << "d=" << c.d << " periodic=" << periodic << " candidates=" << candidates;
      }
}

// candidates = 1 stresses the completion: Bridson with one candidate per
// step stops early and leaves many holes, which phase 2 must fill.
TEST(PoissonDisk, MaximalSetsLeaveNoPointFartherThanTheRadius) {
  for (const Case& c : cases)
    for (bool periodic : {false, true})
      for (unsigned candidates : {1u, 30u}) {
        const std::vector<double> points = PoissonDisk(c.d, c.radius, 5, candidates, periodic).maximal_set();
        EXPECT_LE(largest_gap(points, c.d, periodic, c.probes_per_axis), c.radius * (1 + 1e-12))
            << "d=" << c.d << " periodic=" << periodic << " candidates=" << candidates;
      }
}

// The probe test catches a set that is not maximal: drop one sample and
// probe its position, which is at distance >= r from every other sample.
TEST(PoissonDisk, ProbeTestDetectsAMissingSample) {
  std::vector<double> points = PoissonDisk(2, 0.05, 9).maximal_set();
  const double removed[2] = {points[20], points[21]};
  points.erase(points.begin() + 20, points.begin() + 22);
  EXPECT_GT(nearest(points, removed, 2, false), 0.05);
}

// Bridson alone with few candidates is far from maximal; the completion adds
// the missing points: more points with candidates = 1 are completion's.
TEST(PoissonDisk, CompletionFillsWhatBridsonLeaves) {
  const auto few = PoissonDisk(2, 0.02, 1, 1).maximal_set();
  const auto many = PoissonDisk(2, 0.02, 1, 30).maximal_set();
  // Maximal sets of either kind have similar sizes (within 15%).
  EXPECT_NEAR(static_cast<double>(few.size()) / static_cast<double>(many.size()), 1.0, 0.15);
}

TEST(PoissonDisk, SameSeedSameSetOtherSeedOtherSet) {
  const auto a = PoissonDisk(2, 0.03, 17).maximal_set();
  const auto b = PoissonDisk(2, 0.03, 17).maximal_set();
  const auto c = PoissonDisk(2, 0.03, 18).maximal_set();
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_EQ(PoissonDisk::with_count(100, 3, 4), PoissonDisk::with_count(100, 3, 4));
}

// The estimate behind radius_for_count and the memory check is within 8%
// of the mean size (d = 1..4, both boundary kinds, a few seeds).
TEST(PoissonDisk, EstimatedCountMatchesMaximalSets) {
  for (const Case& c : cases)
    for (bool periodic : {false, true}) {
      double total = 0;
      for (std::uint64_t seed = 0; seed < 3; ++seed)
        total += static_cast<double>(PoissonDisk(c.d, c.radius, seed, 30, periodic).maximal_set().size() / c.d);
      const double estimate = PoissonDisk::estimated_count(c.d, c.radius, periodic);
      EXPECT_NEAR(total / 3 / estimate, 1.0, 0.08) << "d=" << c.d << " periodic=" << periodic;
      EXPECT_LT(total / 3, PoissonDisk::packing_bound(c.d, c.radius, periodic));
    }
}

TEST(PoissonDisk, WithCountReturnsExactlyN) {
  for (unsigned d = 1; d <= 4; ++d)
    for (bool periodic : {false, true})
      for (std::uint64_t n : {1ull, 2ull, 7ull, 100ull, d <= 2 ? 1000ull : 300ull}) {
        const auto points = PoissonDisk::with_count(n, d, 11, 30, periodic);
        ASSERT_EQ(points.size(), n * d) << "d=" << d << " n=" << n;
        for (double v : points) {
          ASSERT_GE(v, 0.0);
          ASSERT_LT(v, 1.0);
        }
        // Well spread: at least 40% of the densest packing's minimum
        // distance for n points (random points reach ~1/sqrt(n) of it).
        if (n >= 100) {
          EXPECT_GT(min_distance(points, d, periodic), 0.4 * largest_minimum_distance(n, d)) << d;
        }
      }
}

TEST(PoissonDisk, SubsetKeepsTheRadiusAndRefusesTooMany) {
  const PoissonDisk disk(2, 0.04, 2);
  const std::size_t maximal = disk.maximal_set().size() / 2;
  const auto some = disk.subset(maximal / 2);
  ASSERT_EQ(some.size(), (maximal / 2) * 2);
  EXPECT_GE(min_distance(some, 2, false), 0.04);
  EXPECT_EQ(disk.subset(maximal).size(), maximal * 2);
  try {
    disk.subset(maximal + 1);
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "n");
    EXPECT_NE(std::string(e.what()).find(std::to_string(maximal)), std::string::npos) << e.what();
  }
}

TEST(PoissonDisk, RadiusForCountInvertsTheEstimate) {
  for (unsigned d = 1; d <= 4; ++d) {
    const double r = PoissonDisk::radius_for_count(5000, d, false);
    EXPECT_NEAR(PoissonDisk::estimated_count(d, r, false), 5000, 1);
  }
  EXPECT_EQ(PoissonDisk::radius_for_count(1, 2, true), 1.0);
}

// The search stops once its bounds stop moving and the answer is cached per
// thread: both give what the full 200-step bisection of the estimate gives,
// for counts asked in turn (each a cache miss) and again (hits).
TEST(PoissonDisk, RadiusForCountIsTheFullBisection) {
  const auto full_bisection = [](double count, unsigned d, bool periodic) {
    double lo = 1e-12, hi = 1.0;
    if (PoissonDisk::estimated_count(d, hi, periodic) >= count) return hi;
    for (int step = 0; step < 200; ++step) {
      const double mid = std::sqrt(lo * hi);
      (PoissonDisk::estimated_count(d, mid, periodic) >= count ? lo : hi) = mid;
    }
    return lo;
  };
  for (unsigned d = 1; d <= 4; ++d)
    for (const bool periodic : {false, true})
      for (double count = 1.5; count < 1e7; count *= 3.7) {
        const double expected = full_bisection(count, d, periodic);
        EXPECT_EQ(PoissonDisk::search_radius(count, d, periodic), expected) << d << " " << periodic << " " << count;
        EXPECT_EQ(PoissonDisk::radius_for_count(count, d, periodic), expected);
        EXPECT_EQ(PoissonDisk::radius_for_count(count, d, periodic), expected);  // cached
      }
}

TEST(PoissonDisk, FloatOutputIsTheRoundedDoubleOutput) {
  const PoissonDisk disk(3, 0.1, 8);
  const auto d = disk.maximal_set<double>();
  const auto f = disk.maximal_set<float>();
  ASSERT_EQ(d.size(), f.size());
  for (std::size_t k = 0; k < d.size(); ++k) {
    EXPECT_EQ(f[k], to_unit_float(d[k]));
    EXPECT_LT(f[k], 1.0f);
  }
}

TEST(PoissonDisk, RejectsBadParameters) {
  EXPECT_THROW(PoissonDisk(0, 0.1, 0), invalid_argument);
  EXPECT_THROW(PoissonDisk(5, 0.1, 0), invalid_argument);
  EXPECT_THROW(PoissonDisk(2, 0.0, 0), invalid_argument);
  EXPECT_THROW(PoissonDisk(2, 1.5, 0), invalid_argument);
  EXPECT_THROW(PoissonDisk(2, 0.1, 0, 0), invalid_argument);
  EXPECT_THROW(PoissonDisk(4, 1e-4, 0), invalid_argument);  // grid beyond 2^40 bytes
  EXPECT_NO_THROW(PoissonDisk(2, 1.0, 0).maximal_set());
  EXPECT_EQ(PoissonDisk(2, 1.0, 0, 30, true).maximal_set().size(), 2u);  // one point: the torus is within 0.71
}

}  // namespace
}  // namespace stratum
