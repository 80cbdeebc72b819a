#include "stratum/patterns/jittered.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "unbiased.hpp"

namespace stratum {
namespace {

// Every point in its own cell, for stratum shapes in d = 1..4, and the cells
// of all points together cover the grid once.
TEST(Jittered, OnePointPerStratum) {
  const std::vector<std::vector<std::uint64_t>> shapes = {{7},    {1000},    {4, 8},    {5, 5},
                                                          {1, 9}, {3, 1, 5}, {4, 4, 4}, {2, 3, 2, 2}};
  for (const auto& strata : shapes) {
    for (std::uint64_t seed : {0ull, 1ull, 99ull}) {
      const Jittered jittered(StrataShape(strata), seed);
      const auto d = static_cast<unsigned>(strata.size());
      std::vector<int> hits(jittered.count(), 0);
      for (std::uint64_t i = 0; i < jittered.count(); ++i) {
        std::uint64_t cell = 0, stride = 1;
        for (unsigned j = 0; j < d; ++j) {
          const double x = jittered.sample(i, j);
          ASSERT_GE(x, 0.0);
          ASSERT_LT(x, 1.0);
          const auto c = static_cast<std::uint64_t>(std::floor(x * static_cast<double>(strata[j])));
          ASSERT_EQ(c, jittered.shape().cell(i, j));
          cell += c * stride;
          stride *= strata[j];
        }
        ++hits[cell];
      }
      for (int h : hits) ASSERT_EQ(h, 1);
    }
  }
}

TEST(Jittered, DependsOnSeedIndexAndDimensionOnly) {
  const Jittered a(StrataShape({8, 8}), 5), b(StrataShape({8, 8}), 5), c(StrataShape({8, 8}), 6);
  EXPECT_EQ(a.sample(13, 1), b.sample(13, 1));
  EXPECT_NE(a.sample(13, 1), c.sample(13, 1));
  EXPECT_FLOAT_EQ(a.sample<float>(13, 1), static_cast<float>(a.sample(13, 1)));
}

// Jittered estimates are unbiased: 400 seeds, 3 shapes, family level 0.001 (Šidák).
TEST(Jittered, UnbiasedOverSeeds) {
  const std::vector<std::vector<std::uint64_t>> shapes = {{5}, {4, 3}, {2, 3, 2}};
  const double alpha = testing::sidak(0.001, static_cast<int>(shapes.size()));
  for (const auto& strata : shapes) {
    const auto d = static_cast<unsigned>(strata.size());
    const auto estimates = testing::estimates_over_seeds(400, d, [&](std::uint64_t seed) {
      const Jittered jittered(StrataShape(strata), seed);
      std::vector<double> x;
      for (std::uint64_t i = 0; i < jittered.count(); ++i)
        for (unsigned j = 0; j < d; ++j) x.push_back(jittered.sample(i, j));
      return x;
    });
    testing::expect_unbiased("jittered d=" + std::to_string(d), estimates, testing::test_integral(d), alpha);
  }
}

}  // namespace
}  // namespace stratum
