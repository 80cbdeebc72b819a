#include "stratum/util/hash.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace stratum {
namespace {

TEST(Hash, CountersAreOrderSensitiveAndDeterministic) {
  EXPECT_EQ(hash64(1, 2, 3), hash64(1, 2, 3));
  EXPECT_NE(hash64(1, 2, 3), hash64(1, 3, 2));
  EXPECT_NE(hash64(1, 2), hash64(2, 2));
}

TEST(Hash, ExtendEqualsTheLongerHash) {
  // hash64_extend(hash64(s, c…), c') is hash64(s, c…, c') for any number of
  // leading counters (the chain the renderer caches per pixel).
  for (std::uint64_t s : {0ull, 1ull, 0x9e3779b97f4a7c15ull, ~0ull})
    for (std::uint64_t c : {0ull, 7ull, 1ull << 40, ~0ull}) {
      EXPECT_EQ(hash64_extend(hash64(s), c), hash64(s, c));
      EXPECT_EQ(hash64_extend(hash64(s, 3), c), hash64(s, 3, c));
      EXPECT_EQ(hash64_extend(hash64(s, c, 5), 9), hash64(s, c, 5, 9));
      EXPECT_EQ(hash64_extend(hash64_extend(hash64(s), c), 2), hash64(s, c, 2));
    }
}

TEST(Hash, UnitConversionsStayBelowOne) {
  EXPECT_EQ(bits_to_double(0), 0.0);
  EXPECT_LT(bits_to_double(~0ull), 1.0);
  EXPECT_LT(bits_to_float(~0ull), 1.0f);
}

// χ² on 64 equal bins of 64000 uniform01 draws: 63 degrees of freedom, the
// critical value at α = 1e-4 is 117.
TEST(Hash, Uniform01IsUniform) {
  std::vector<int> bins(64, 0);
  const int draws = 64000;
  for (int i = 0; i < draws; ++i) ++bins[static_cast<std::size_t>(uniform01(42, i) * 64)];
  double chi2 = 0;
  for (int b : bins) chi2 += (b - 1000.0) * (b - 1000.0) / 1000.0;
  EXPECT_LT(chi2, 117.0);
}

// uniform_below(7) hits every value with frequency 1/7: χ² with 6 degrees of
// freedom, critical value 27.9 at α = 1e-4; a bound of 1 is always 0.
TEST(Hash, UniformBelowIsUnbiased) {
  std::vector<int> counts(7, 0);
  for (int i = 0; i < 70000; ++i) {
    const auto v = uniform_below(7, 3, i);
    ASSERT_LT(v, 7u);
    ++counts[v];
  }
  double chi2 = 0;
  for (int c : counts) chi2 += (c - 10000.0) * (c - 10000.0) / 10000.0;
  EXPECT_LT(chi2, 27.9);
  EXPECT_EQ(uniform_below(1, 5, 9), 0u);
}

}  // namespace
}  // namespace stratum
