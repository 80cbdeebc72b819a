#include "stratum/sequences/halton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace stratum {
namespace {

TEST(Halton, UsesTheFirstPrimesAsBases) {
  EXPECT_EQ(Halton::base(0), 2u);
  EXPECT_EQ(Halton::base(1), 3u);
  EXPECT_EQ(Halton::base(2), 5u);
  EXPECT_EQ(Halton::base(999), 7919u);  // the 1000th prime
  const Halton halton(3);
  EXPECT_DOUBLE_EQ(halton.sample(5, 0), 0.625);
  EXPECT_DOUBLE_EQ(halton.sample(5, 1), 2.0 / 3 + 1.0 / 9);
  EXPECT_DOUBLE_EQ(halton.sample(5, 2), 1.0 / 25);
}

TEST(Halton, RejectsBadDimensions) {
  EXPECT_THROW(Halton(0), invalid_argument);
  EXPECT_THROW(Halton(Halton::max_dimensions + 1), invalid_argument);
  EXPECT_NO_THROW(Halton(1000));
}

// Halton in bases (2, 3): the first 2^i 3^j points have one point in every
// box of size 2^-i × 3^-j (mixed-base elementary intervals).
TEST(Halton, MixedBaseElementaryIntervals) {
  const Halton halton(2);
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 4; ++j) {
      const int nx = 1 << i, ny = static_cast<int>(std::pow(3, j));
      std::vector<int> hits(static_cast<std::size_t>(nx * ny), 0);
      for (int k = 0; k < nx * ny; ++k) {
        // Points lie on the grid corners exactly; nudge by 1e-9 so a value
        // rounded just below a boundary k / 3^j is counted in its own box.
        const int bx = static_cast<int>(halton.sample(k, 0) * nx + 1e-9);
        const int by = static_cast<int>(halton.sample(k, 1) * ny + 1e-9);
        ++hits[static_cast<std::size_t>(by * nx + bx)];
      }
      for (int h : hits) ASSERT_EQ(h, 1) << "2^" << i << " x 3^" << j;
    }
}

TEST(Hammersley, FirstDimensionIsIOverN) {
  const Hammersley hammersley(16, 3);
  EXPECT_EQ(hammersley.sample(4, 0), 0.25);
  EXPECT_EQ(hammersley.sample(4, 1), 0.125);
  EXPECT_DOUBLE_EQ(hammersley.sample(4, 2), 1.0 / 3 + 1.0 / 9);
  EXPECT_THROW(Hammersley(0, 2), invalid_argument);
}

// Hammersley with N = 2^i 3^j in dimensions (0, 2): every 2^-a × 3^-b box
// with 2^a 3^b = N... dimension 0 is i/N, so any box of N equal columns and
// one row holds one point; with dimension 1 (base 2) at N = 2^k it is a (0,k,2)-net.
TEST(Hammersley, BaseTwoNetAtPowersOfTwo) {
  for (int k = 1; k <= 10; ++k) {
    const std::uint64_t n = 1ull << k;
    const Hammersley hammersley(n, 2);
    for (int i = 0; i <= k; ++i) {
      const std::uint64_t nx = 1ull << i, ny = 1ull << (k - i);
      std::vector<int> hits(n, 0);
      for (std::uint64_t p = 0; p < n; ++p)
        ++hits[static_cast<std::size_t>(hammersley.sample(p, 1) * ny) * nx +
               static_cast<std::size_t>(hammersley.sample(p, 0) * nx)];
      for (int h : hits) ASSERT_EQ(h, 1);
    }
  }
}

}  // namespace
}  // namespace stratum
