#include "stratum/patterns/best_candidate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "brute_distance.hpp"

#include "stratum/patterns/random.hpp"

namespace stratum {
namespace {

using testing::distance2;
using testing::min_distance;

// Mitchell's algorithm by brute force, on the same candidate streams: the
// grids of the real implementation must not change a single choice.
std::vector<double> brute_force(std::uint64_t n, unsigned d, std::uint64_t seed, unsigned k, bool periodic) {
  std::vector<double> points(d);
  BestCandidate::first_point(seed, d, points.data());
  for (std::uint64_t i = 1; i < n; ++i) {
    double best = -1, x[4], winner[4];
    for (std::uint64_t c = 0; c < k * i; ++c) {
      BestCandidate::candidate(seed, d, i, c, x);
      double nearest = 1e300;
      for (std::uint64_t p = 0; p < i; ++p) nearest = std::min(nearest, distance2(&points[p * d], x, d, periodic));
      if (nearest > best) best = nearest, std::copy(x, x + d, winner);
    }
    for (unsigned j = 0; j < d; ++j)
      points.push_back(std::min(winner[j] + BestCandidate::low_bits(seed, i, j), one_minus_epsilon_double));
  }
  return points;
}

TEST(BestCandidate, MatchesBruteForceMitchell) {
  // Past BestCandidate::small_points the grids' engine, up to it the search without grids.
  for (unsigned d = 1; d <= 4; ++d)
    for (bool periodic : {true, false})
      for (unsigned k : {1u, 10u})
        for (const std::uint64_t n :
             {std::uint64_t{d <= 2 ? 150u : 80u}, BestCandidate::small_points, std::uint64_t{5}})
          EXPECT_EQ(BestCandidate(d, 21, k, periodic).generate(n), brute_force(n, d, 21, k, periodic))
              << "d=" << d << " periodic=" << periodic << " k=" << k << " n=" << n;
}

// The small sets (no grids) are the engine's first points, for many seeds.
TEST(BestCandidate, SmallSetsArePrefixesOfTheEngines) {
  const std::uint64_t large = BestCandidate::small_points + 1;  // the engine's
  for (unsigned d = 1; d <= 4; ++d)
    for (bool periodic : {true, false})
      for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const BestCandidate pattern(d, seed, 10, periodic);
        const auto engine = pattern.generate(large);
        for (const std::uint64_t n : {std::uint64_t{2}, std::uint64_t{4}, BestCandidate::small_points}) {
          const auto small = pattern.generate(n);
          ASSERT_TRUE(std::equal(small.begin(), small.end(), engine.begin()))
              << "d=" << d << " periodic=" << periodic << " seed=" << seed << " n=" << n;
        }
      }
}

// Every prefix is the smaller pattern (Mitchell's progressive property).
TEST(BestCandidate, PrefixesAreSmallerPatterns) {
  const auto large = BestCandidate(2, 4).generate(500);
  for (std::uint64_t n : {1ull, 2ull, 37ull, 256ull}) {
    const auto small = BestCandidate(2, 4).generate(n);
    EXPECT_TRUE(std::equal(small.begin(), small.end(), large.begin())) << n;
  }
}

TEST(BestCandidate, DeterministicAndSeeded) {
  const BestCandidate a(3, 9), b(3, 9), c(3, 10);
  EXPECT_EQ(a.generate(150), b.generate(150));
  EXPECT_NE(a.generate(150), c.generate(150));
  std::vector<float> f(600);
  BestCandidate(2, 9).generate(300, f.data());
  const auto d = BestCandidate(2, 9).generate(300);
  for (std::size_t k = 0; k < d.size(); ++k) EXPECT_EQ(f[k], to_unit_float(d[k]));
}

// Blue noise: over 10 seeds, the mean minimum (toroidal) distance of 512
// best-candidate points in 2D is far above that of 512 uniform random
// points. For n uniform points the minimum distance D has
// P(D > t) ≈ exp(-π t² n²/2), so E[D] ≈ sqrt(1/(2 n²)) ≈ 0.0014 for n = 512;
// best-candidate with k = 10 reaches about 0.8/sqrt(n) ≈ 0.035 (measured).
// Asserted: the mean is more than 8 times random's, and above 0.4/sqrt(n).
TEST(BestCandidate, MinimumDistanceFarAboveRandom) {
  const std::size_t n = 512;
  double pattern = 0, random = 0;
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    pattern += min_distance(BestCandidate(2, seed).generate(n), 2, true);
    std::vector<double> uniform(2 * n);
    const RandomPattern rng(seed);
    for (std::size_t i = 0; i < n; ++i) uniform[2 * i] = rng.sample(i, 0), uniform[2 * i + 1] = rng.sample(i, 1);
    random += min_distance(uniform, 2, true);
  }
  EXPECT_GT(pattern, 8 * random);
  EXPECT_GT(pattern / 10, 0.4 / std::sqrt(static_cast<double>(n)));
}

TEST(BestCandidate, UnitCubeAndValidation) {
  for (unsigned d = 1; d <= 4; ++d)
    for (double v : BestCandidate(d, 1, 3).generate(200)) {
      ASSERT_GE(v, 0.0);
      ASSERT_LT(v, 1.0);
    }
  EXPECT_THROW(BestCandidate(0), invalid_argument);
  EXPECT_THROW(BestCandidate(5), invalid_argument);
  EXPECT_THROW(BestCandidate(2, 0, 0), invalid_argument);
  EXPECT_THROW(BestCandidate(2).generate(0), invalid_argument);
  EXPECT_EQ(BestCandidate::candidate_count(4096, 10), 10ull * 4096 * 4095 / 2);
  EXPECT_EQ(BestCandidate::candidate_count(1, 10), 0u);
}

}  // namespace
}  // namespace stratum
