#include "stratum/sequences/radical_inverse.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stratum {
namespace {

// Exact value of φ_b(i) by summing digits with long double, an independent oracle.
long double reference_radical_inverse(std::uint32_t base, std::uint64_t index) {
  long double value = 0, scale = 1.0L / base;
  while (index) {
    value += (index % base) * scale;
    index /= base;
    scale /= base;
  }
  return value;
}

TEST(RadicalInverse, BaseTwoFirstValuesFromTheLecture) {
  EXPECT_EQ(radical_inverse(2, 0), 0.0);
  EXPECT_EQ(radical_inverse(2, 1), 0.5);
  EXPECT_EQ(radical_inverse(2, 2), 0.25);
  EXPECT_EQ(radical_inverse(2, 3), 0.75);
  EXPECT_EQ(radical_inverse(2, 4), 0.125);  // 100₂ → 0.001₂
  EXPECT_EQ(radical_inverse(2, 5), 0.625);
}

TEST(RadicalInverse, BaseThreeExactFractions) {
  EXPECT_DOUBLE_EQ(radical_inverse(3, 1), 1.0 / 3);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 2), 2.0 / 3);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 3), 1.0 / 9);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 5), 2.0 / 3 + 1.0 / 9);
}

TEST(RadicalInverse, MatchesLongDoubleDigitSumInManyBases) {
  for (std::uint32_t base : {2u, 3u, 5u, 7u, 10u, 97u, 7919u, 8161u})
    for (std::uint64_t index :
         {0ull, 1ull, 17ull, 123456789ull, (1ull << 32) + 5, (1ull << 40) + 12345, 0xffffffffffffffffull})
      EXPECT_NEAR(radical_inverse(base, index), static_cast<double>(reference_radical_inverse(base, index)), 4e-16)
          << "base " << base << " index " << index;
}

TEST(RadicalInverse, NoWrapAroundPastTwoToThe32) {
  // i = 2^32 + 1 has a different reversal from i = 1: no 32-bit truncation.
  EXPECT_NE(radical_inverse(2, (1ull << 32) + 1), radical_inverse(2, 1));
  EXPECT_EQ(radical_inverse(2, 1ull << 32), 0x1.0p-33);
  EXPECT_NE(radical_inverse(3, (1ull << 32) + 1), radical_inverse(3, 1));
}

TEST(RadicalInverse, StaysBelowOneInFloatAndDouble) {
  EXPECT_LT(radical_inverse(2, 0xffffffffffffffffull), 1.0);
  EXPECT_LT(radical_inverse_as<float>(2, 0xffffffffull), 1.0f);
  EXPECT_LT(radical_inverse_as<float>(3, 3486784400ull), 1.0f);  // 3^20 - 1: all digits 2
}

TEST(RadicalInverse, FirstBToTheKPointsHitEveryGridValueOnce) {
  for (std::uint32_t base : {2u, 3u, 5u, 13u}) {
    const std::uint64_t count = base * base * base;
    // Unscrambled points sit exactly on the grid j / b^k (up to rounding, so
    // round rather than floor); each j must appear once.
    std::vector<int> hits(count, 0);
    for (std::uint64_t i = 0; i < count; ++i) {
      const double scaled = radical_inverse(base, i) * static_cast<double>(count);
      const auto j = static_cast<std::size_t>(std::llround(scaled));
      ASSERT_NEAR(scaled, static_cast<double>(j), 1e-9);
      ++hits[j];
    }
    for (int h : hits) EXPECT_EQ(h, 1) << "base " << base;
  }
}

TEST(RadicalInverse, BaseValidation) {
  EXPECT_THROW(require_valid_base(1), invalid_argument);
  EXPECT_NO_THROW(require_valid_base(2));
}

}  // namespace
}  // namespace stratum
