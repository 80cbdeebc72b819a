// pmj02bn (sequences/pmj02bn.hpp): every 2^k prefix and aligned block a
// (0,k,2)-net for any candidate count, deterministic and consistent with the
// registry's start, unbiased over seeds (t-tests, Šidák-corrected), and its
// points spread further apart than the same construction without candidates
// (a paired t-test over seeds).
#include "stratum/sequences/pmj02bn.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <bit>
#include <cmath>
#include <vector>

#include "../patterns/unbiased.hpp"
#include "stratum/registry.hpp"
#include "zero_net.hpp"

namespace {

using stratum::Pmj02Bn;

std::vector<std::array<double, 2>> as_points(const std::vector<double>& xy, std::size_t first, std::size_t n) {
  std::vector<std::array<double, 2>> points;
  for (std::size_t i = first; i < first + n; ++i) points.push_back({xy[2 * i], xy[2 * i + 1]});
  return points;
}

std::vector<double> generate(std::uint64_t seed, unsigned candidates, std::uint64_t n) {
  std::vector<double> xy(2 * n);
  Pmj02Bn(seed, candidates).generate(n, xy.data());
  return xy;
}

TEST(Pmj02Bn, EveryPrefixAndAlignedBlockIsANet) {
  for (unsigned candidates : {1u, 10u, 50u})
    for (std::uint64_t seed : {0u, 1u, 2u}) {
      const std::vector<double> xy = generate(seed, candidates, 4096);
      for (std::size_t n = 1; n <= 4096; n *= 2)
        for (std::size_t first = 0; first + n <= 4096; first += std::max<std::size_t>(n, 512))
          EXPECT_TRUE(stratum::testing::is_zero_net(as_points(xy, first, n)))
              << "candidates " << candidates << " seed " << seed << " block [" << first << ", " << first + n << ")";
    }
}

// The construction replayed by brute force: each point's fixed digits from
// the point PMJ02 pairs it with, and of its candidates the first farthest
// (toroidally) from every earlier point, all of them measured. Past
// Pmj02Bn's grid-free prefix the grid must not change a single choice.
std::vector<double> brute_force(std::uint64_t seed, unsigned candidates, std::uint64_t n) {
  std::vector<std::uint64_t> bits(2 * n);
  std::vector<double> xy(2 * n);
  for (std::uint64_t p = 0; p < n; ++p) {
    std::uint64_t top[2] = {0, 0}, free = ~std::uint64_t{0};
    if (p != 0) {
      const unsigned m = 63u - static_cast<unsigned>(std::countl_zero(p));
      const std::uint64_t kept = ~std::uint64_t{0} << (63 - m);
      for (unsigned c = 0; c < 2; ++c) {
        const std::uint64_t j = (p ^ (std::uint64_t{1} << m)) ^ stratum::Pmj02::xor_value(c, m);
        top[c] = (bits[2 * j + c] & kept) ^ (std::uint64_t{1} << (63 - m));
      }
      free = ~kept;
    }
    double best = -1;
    for (unsigned k = 0; k < (p == 0 ? 1u : candidates); ++k) {
      std::uint64_t candidate[2];
      for (unsigned c = 0; c < 2; ++c) candidate[c] = top[c] | (Pmj02Bn::candidate_bits(seed, p, k, c) & free);
      double nearest = 0;
      if (p != 0) {
        nearest = 1e300;
        for (std::uint64_t q = 0; q < p; ++q) {
          const double dx = std::abs(stratum::bits_to_double(candidate[0]) - xy[2 * q]);
          const double dy = std::abs(stratum::bits_to_double(candidate[1]) - xy[2 * q + 1]);
          nearest = std::min(nearest, std::pow(std::min(dx, 1 - dx), 2) + std::pow(std::min(dy, 1 - dy), 2));
        }
      }
      if (nearest > best) best = nearest, bits[2 * p] = candidate[0], bits[2 * p + 1] = candidate[1];
    }
    xy[2 * p] = stratum::bits_to_double(bits[2 * p]), xy[2 * p + 1] = stratum::bits_to_double(bits[2 * p + 1]);
  }
  return xy;
}

TEST(Pmj02Bn, MatchesBruteForce) {
  for (unsigned candidates : {1u, 10u})
    for (std::uint64_t seed : {0u, 7u}) EXPECT_EQ(generate(seed, candidates, 700), brute_force(seed, candidates, 700));
}

TEST(Pmj02Bn, DeterministicAndProgressive) {
  EXPECT_EQ(generate(5, 10, 300), generate(5, 10, 300));
  EXPECT_NE(generate(5, 10, 300), generate(6, 10, 300));
  const std::vector<double> long_run = generate(5, 10, 1000);
  const std::vector<double> prefix = generate(5, 10, 300);
  EXPECT_TRUE(std::equal(prefix.begin(), prefix.end(), long_run.begin()));  // prefixes are the sequence's
  stratum::SamplerRequest request;
  request.n = 100;
  request.d = 2;
  request.seed = 5;
  request.start = 200;
  const stratum::PointSet tail = stratum::generate_points("pmj02bn", request);  // candidates=10, the default
  for (std::size_t i = 0; i < 100; ++i) {
    EXPECT_EQ(tail(i, 0), long_run[2 * (200 + i)]);
    EXPECT_EQ(tail(i, 1), long_run[2 * (200 + i) + 1]);
  }
  EXPECT_THROW(Pmj02Bn(0, 0), stratum::invalid_argument);
  EXPECT_THROW(Pmj02Bn(0, 1001), stratum::invalid_argument);
  request.start = (std::uint64_t{1} << 31) - 50;
  EXPECT_THROW(stratum::generate_points("pmj02bn", request), stratum::invalid_argument);
}

TEST(Pmj02Bn, UnbiasedOverSeeds) {
  // f(x, y) = exp(x)(1 + y²), integral (e − 1)·4/3; 3 counts = 3 t-tests at family level 0.01.
  const double alpha = stratum::testing::sidak(0.01, 3);
  for (std::uint64_t n : {1u, 16u, 100u}) {
    const std::vector<double> estimates =
        stratum::testing::estimates_over_seeds(400, 2, [&](std::uint64_t seed) { return generate(seed, 10, n); });
    stratum::testing::expect_unbiased("pmj02bn n " + std::to_string(n), estimates, stratum::testing::test_integral(2),
                                      alpha);
  }
}

/// The mean over points of the toroidal distance to the nearest other point, times √n.
double mean_nearest(const std::vector<double>& xy) {
  const std::size_t n = xy.size() / 2;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double best = 1e9;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      double dx = std::abs(xy[2 * i] - xy[2 * j]), dy = std::abs(xy[2 * i + 1] - xy[2 * j + 1]);
      dx = std::min(dx, 1 - dx), dy = std::min(dy, 1 - dy);
      best = std::min(best, dx * dx + dy * dy);
    }
    sum += std::sqrt(best);
  }
  return sum / double(n) * std::sqrt(double(n));
}

TEST(Pmj02Bn, CandidatesSpreadThePointsApart) {
  // Paired over 20 seeds at 128 points: the mean nearest-neighbour distance
  // with 10 candidates against 1 (the plain stochastic PMJ02 digits), a
  // one-sided paired t-test at level 0.001. (Measured: 0.68 against 0.65 in
  // units of 1/√n; random points 0.49.)
  std::vector<double> gain;
  for (std::uint64_t seed = 0; seed < 20; ++seed)
    gain.push_back(mean_nearest(generate(seed, 10, 128)) - mean_nearest(generate(seed, 1, 128)));
  double mean = 0, ss = 0;
  for (double g : gain) mean += g;
  mean /= double(gain.size());
  for (double g : gain) ss += (g - mean) * (g - mean);
  const double se = std::sqrt(ss / double(gain.size() - 1) / double(gain.size()));
  const boost::math::students_t t(double(gain.size() - 1));
  EXPECT_GT(mean / se, boost::math::quantile(boost::math::complement(t, 0.001))) << "mean gain " << mean;
}

}  // namespace
