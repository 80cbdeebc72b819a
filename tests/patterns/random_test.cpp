#include "stratum/patterns/random.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <vector>

namespace stratum {
namespace {

TEST(RandomPattern, PureFunctionOfSeedIndexAndDimension) {
  const RandomPattern a(3), b(3), c(4);
  EXPECT_EQ(a.sample(123456789012ull, 7), b.sample(123456789012ull, 7));
  EXPECT_NE(a.sample(5, 0), c.sample(5, 0));
  EXPECT_NE(a.sample(5, 0), a.sample(5, 1));
  // No wrap at 2^32: indices 2^32 apart differ.
  EXPECT_NE(a.sample(1, 0), a.sample((1ull << 32) + 1, 0));
  const float f = a.sample<float>(9, 2);
  EXPECT_GE(f, 0.0f);
  EXPECT_LT(f, 1.0f);
  EXPECT_NEAR(f, a.sample(9, 2), 1e-7);
}

// Uniform: chi-square over a 16 × 16 grid of pairs (x, y) from 25600 points,
// which also catches correlation between dimensions; level 0.001.
TEST(RandomPattern, UniformPairs) {
  const RandomPattern random(11);
  std::vector<int> hits(256, 0);
  const int n = 25600;
  for (int i = 0; i < n; ++i)
    ++hits[static_cast<std::size_t>(random.sample(i, 0) * 16) * 16 +
           static_cast<std::size_t>(random.sample(i, 1) * 16)];
  double chi2 = 0;
  for (int h : hits) chi2 += (h - 100.0) * (h - 100.0) / 100.0;
  const boost::math::chi_squared dist(255);
  EXPECT_LT(chi2, boost::math::quantile(boost::math::complement(dist, 0.001)));
}

}  // namespace
}  // namespace stratum
