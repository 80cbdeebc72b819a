#include "stratum/patterns/zaremba.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "stratum/sequences/halton.hpp"

namespace stratum {
namespace {

// Digit by digit: y = sum_{r < k} ((a_r + r) mod 2) 2^-(r+1), k = ceil(log2 N).
double zaremba_oracle(std::uint64_t i, std::uint64_t n) {
  unsigned k = 0;
  while ((std::uint64_t{1} << k) < n) ++k;
  double y = 0, scale = 0.5;
  for (unsigned r = 0; r < k; ++r, scale /= 2) {
    const unsigned digit = static_cast<unsigned>((i >> r) & 1u);
    y += static_cast<double>((digit + r) % 2) * scale;
  }
  return y;
}

TEST(Zaremba, MatchesTheDigitByDigitDefinition) {
  for (std::uint64_t n : {1ull, 2ull, 3ull, 16ull, 100ull, 256ull, 1600ull}) {
    const Zaremba zaremba(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      ASSERT_EQ(zaremba.sample(i, 0), static_cast<double>(i) / static_cast<double>(n));
      ASSERT_EQ(zaremba.sample(i, 1), zaremba_oracle(i, n)) << "n=" << n << " i=" << i;
    }
  }
  // N = 16, i = 0: digits 0000 become 1010 (r = 1, 3 flipped): y = 0.0101b = 5/16.
  EXPECT_EQ(Zaremba(16).sample(0, 1), 0.3125);
  // i = 5 = 0101b becomes 1111b: y = 0.1111b = 15/16.
  EXPECT_EQ(Zaremba(16).sample(5, 1), 0.9375);
}

// Digital shifts keep the (0, k, 2)-net property of Hammersley in base 2.
TEST(Zaremba, IsANetAtPowersOfTwo) {
  for (unsigned k = 1; k <= 10; ++k) {
    const std::uint64_t n = std::uint64_t{1} << k;
    const Zaremba zaremba(n);
    for (unsigned a = 0; a <= k; ++a) {
      const std::uint64_t nx = std::uint64_t{1} << a, ny = std::uint64_t{1} << (k - a);
      std::vector<int> hits(n, 0);
      for (std::uint64_t i = 0; i < n; ++i)
        ++hits[static_cast<std::size_t>(zaremba.sample(i, 1) * static_cast<double>(ny)) * nx +
               static_cast<std::size_t>(zaremba.sample(i, 0) * static_cast<double>(nx))];
      for (int h : hits) ASSERT_EQ(h, 1) << "k=" << k << " a=" << a;
    }
  }
}

// Exact 2D star discrepancy by brute force over the boxes [0, x) × [0, y)
// with corners at point coordinates (open and closed counts).
double star_discrepancy(const std::vector<std::pair<double, double>>& points) {
  std::vector<double> xs{1.0}, ys{1.0};
  for (const auto& [x, y] : points) {
    xs.push_back(x);
    ys.push_back(y);
  }
  const double n = static_cast<double>(points.size());
  double worst = 0;
  for (double bx : xs)
    for (double by : ys) {
      int open = 0, closed = 0;
      for (const auto& [x, y] : points) {
        open += (x < bx && y < by);
        closed += (x <= bx && y <= by);
      }
      worst = std::max({worst, bx * by - open / n, closed / n - bx * by});
    }
  return worst;
}

// Zaremba's set has a lower star discrepancy than the plain Hammersley set;
// N·D* values from an independent Python brute force.
TEST(Zaremba, LowerStarDiscrepancyThanHammersley) {
  for (auto [n, zaremba_nd, hammersley_nd] : std::vector<std::tuple<std::uint64_t, double, double>>{
           {16, 2.25, 2.75}, {64, 2.6875, 3.4375}, {100, 2.875, 3.78125}}) {
    const Zaremba zaremba(n);
    const Hammersley hammersley(n, 2);
    std::vector<std::pair<double, double>> z, h;
    for (std::uint64_t i = 0; i < n; ++i) {
      z.emplace_back(zaremba.sample(i, 0), zaremba.sample(i, 1));
      h.emplace_back(hammersley.sample(i, 0), hammersley.sample(i, 1));
    }
    const double dz = star_discrepancy(z) * static_cast<double>(n), dh = star_discrepancy(h) * static_cast<double>(n);
    EXPECT_NEAR(dz, zaremba_nd, 1e-9) << n;
    EXPECT_NEAR(dh, hammersley_nd, 1e-9) << n;
    EXPECT_LT(dz, dh);
  }
}

TEST(Zaremba, RejectsZeroPoints) { EXPECT_THROW(Zaremba(0), invalid_argument); }

}  // namespace
}  // namespace stratum
