#include "stratum/randomizers/digits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "stratum/sequences/radical_inverse.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

using digits_detail::u128;

// A rule of fixed, simple permutations: π_j(a) = (a + j) mod b, so a test
// can compute the value independently.
struct RotateByPositionRule {
  std::uint32_t image(unsigned /*dim*/, unsigned position, std::uint32_t base, std::uint32_t digit) const noexcept {
    return static_cast<std::uint32_t>((digit + position) % base);
  }
  void permutation(unsigned dim, unsigned position, std::uint32_t base, std::uint32_t* images) const {
    for (std::uint32_t a = 0; a < base; ++a) images[a] = image(dim, position, base, a);
  }
};

struct IdentityRule {
  std::uint32_t image(unsigned, unsigned, std::uint32_t, std::uint32_t digit) const noexcept { return digit; }
  void permutation(unsigned, unsigned, std::uint32_t base, std::uint32_t* images) const {
    for (std::uint32_t a = 0; a < base; ++a) images[a] = a;
  }
};

// Σ_{j<K} π_j(a_j) b^-(j+1) in long double (64-bit mantissa): an oracle
// independent of the chunk tables and the 128-bit weights.
long double rotated_value(std::uint32_t base, std::uint64_t index) {
  long double value = 0, scale = 1.0L / base;
  for (unsigned j = 0; j < digits_detail::digit_count(base); ++j) {
    value += static_cast<long double>((index % base + j) % base) * scale;
    index /= base;
    scale /= base;
  }
  return value;
}

TEST(Digits, DigitCountIsTheFirstPowerReachingTwoToThe64) {
  EXPECT_EQ(digits_detail::digit_count(2), 64u);
  EXPECT_EQ(digits_detail::digit_count(3), 41u);  // 3^40 < 2^64 ≤ 3^41
  EXPECT_EQ(digits_detail::digit_count(5), 28u);
  EXPECT_EQ(digits_detail::digit_count(7), 23u);
  EXPECT_EQ(digits_detail::digit_count(11), 19u);
  EXPECT_EQ(digits_detail::digit_count(16), 16u);
  EXPECT_EQ(digits_detail::digit_count(8161), 5u);
  EXPECT_EQ(digits_detail::digit_count(65536), 4u);
  for (std::uint32_t b : {2u, 3u, 10u, 97u, 7919u}) {
    const unsigned k = digits_detail::digit_count(b);
    EXPECT_LT(std::pow(static_cast<long double>(b), k - 1), 0x1.0p64L) << b;
    EXPECT_GE(std::pow(static_cast<long double>(b), k), 0x1.0p64L) << b;
  }
  // Every base the randomizers take, against the definition in 128 bits.
  for (std::uint32_t b = 2; b <= digits_detail::max_base; ++b) {
    unsigned k = 0;
    for (digits_detail::u128 power = 1; power < (digits_detail::u128{1} << 64); power *= b) ++k;
    ASSERT_EQ(digits_detail::digit_count(b), k) << b;
  }
}

TEST(Digits, ChunksHoldAtMost4096Entries) {
  EXPECT_EQ(digits_detail::chunk_digits(2), 12u);
  EXPECT_EQ(digits_detail::chunk_digits(3), 7u);  // 2187
  EXPECT_EQ(digits_detail::chunk_digits(5), 5u);  // 3125
  EXPECT_EQ(digits_detail::chunk_digits(64), 2u);
  EXPECT_EQ(digits_detail::chunk_digits(65), 1u);
  EXPECT_EQ(digits_detail::chunk_digits(8161), 1u);
}

TEST(Digits, WeightsAreFloorOfTwoToThe128OverPowers) {
  EXPECT_EQ(digits_detail::digit_weight(2, 0), u128{1} << 127);
  EXPECT_EQ(digits_detail::digit_weight(2, 63), u128{1} << 64);
  EXPECT_EQ(digits_detail::digit_weight(4, 1), u128{1} << 124);
  for (std::uint32_t b : {3u, 5u, 10u, 8161u})
    for (unsigned j = 0; j < digits_detail::digit_count(b); ++j) {
      u128 power = 1;
      for (unsigned t = 0; t <= j; ++t) power *= b;
      const u128 w = digits_detail::digit_weight(b, j);
      // w·b^(j+1) ≤ 2^128 − 1 < (w+1)·b^(j+1) (b^(j+1) is no power of two).
      EXPECT_EQ(w, ~u128{0} / power) << b << " " << j;
      EXPECT_LT(~u128{0} - w * power, power) << b << " " << j;
    }
}

TEST(Digits, FastDividerIsExactEverywhere) {
  std::vector<std::uint64_t> numerators = {
      0,     1,        2, 3, 4095, 4096, 0xffffffffull, 0x100000000ull, (1ull << 48) - 1, 1ull << 48, (1ull << 52) + 7,
      ~0ull, ~0ull - 1};
  for (std::uint64_t k = 0; k < 2000; ++k) numerators.push_back(hash64(11, k) >> (k % 64));
  for (std::uint64_t divisor :
       {2ull, 3ull, 5ull, 7ull, 243ull, 729ull, 2187ull, 3125ull, 4096ull, 4093ull, 8161ull, 65536ull, 65521ull}) {
    const FastDivider divider(divisor);
    EXPECT_GE(divider.limit(), std::uint64_t{1} << 48);
    for (std::uint64_t n : numerators) ASSERT_EQ(divider.quotient(n), n / divisor) << n << " / " << divisor;
    for (std::uint64_t n : {divider.limit() - 1, divider.limit(), divider.limit() + 1})
      ASSERT_EQ(divider.quotient(n), n / divisor) << n << " / " << divisor;
  }
}

TEST(Digits, FractionToDoubleKeeps53LeadingBits) {
  EXPECT_EQ(digits_detail::fraction_to_double(0), 0.0);
  EXPECT_EQ(digits_detail::fraction_to_double(std::uint64_t{1} << 63), 0.5);
  EXPECT_EQ(digits_detail::fraction_to_double(~std::uint64_t{0}), one_minus_epsilon_double);
  EXPECT_EQ(digits_detail::fraction_to_double(0x7ffull), 0.0);  // below 2^-53: dropped
}

TEST(Digits, ScramblerMatchesDigitSumOracleAtAnyIndex) {
  const std::vector<std::uint32_t> bases = {2, 3, 5, 7, 64, 65, 8161, 65536};
  const digits_detail::PositionalDigitScrambler<RotateByPositionRule> full({}, bases, ~0ull);
  const digits_detail::PositionalDigitScrambler<RotateByPositionRule> small({}, bases, 10);
  for (unsigned dim = 0; dim < bases.size(); ++dim)
    for (std::uint64_t index : {0ull, 1ull, 10ull, 11ull, 4095ull, 4096ull, 123456789ull, (1ull << 32) + 1,
                                (1ull << 48) + 99, (1ull << 62) + 12345, ~0ull}) {
      const long double expected = rotated_value(bases[dim], index);
      // Truncation to 64 bits (a few 2^-64 per chunk), then to 53: the value
      // is below, by less than 2^-53 + 2^-60.
      EXPECT_LE(full.sample(index, dim), expected) << dim << " " << index;
      EXPECT_GT(full.sample(index, dim), expected - 0x1.0p-53L - 0x1.0p-60L) << dim << " " << index;
      // Tables (full) and the slow path (small, past index 10) agree bit for bit.
      EXPECT_EQ(full.fraction(index, dim), small.fraction(index, dim)) << dim << " " << index;
    }
}

TEST(Digits, IdentityRuleIsTheRadicalInverseUpToTruncation) {
  const std::vector<std::uint32_t> bases = {2, 3, 5, 13};
  const digits_detail::PositionalDigitScrambler<IdentityRule> identity({}, bases, 1000);
  for (unsigned dim = 0; dim < bases.size(); ++dim)
    for (std::uint64_t index = 0; index < 3000; index += 7) {
      EXPECT_NEAR(identity.sample(index, dim), radical_inverse(bases[dim], index), 0x1.0p-52);
    }
  // Base 2 is exact: the fraction is the bit-reversed index.
  EXPECT_EQ(identity.fraction(0x123456789abcdefull, 0), reverse_bits64(0x123456789abcdefull));
}

// Tables cover exactly the chunk values that indices ≤ max_index can take.
TEST(Digits, TablesCoverTheIndexRange) {
  using Scrambler = digits_detail::PositionalDigitScrambler<IdentityRule>;
  // 64 digits in chunks of 12; the top chunk holds bits 60..63 only.
  EXPECT_EQ(Scrambler({}, {2}, ~0ull).table_entries(), 5u * 4096 + 16);
  EXPECT_EQ(Scrambler({}, {2}, 100).table_entries(), 101u);               // chunk 0 up to 100
  EXPECT_EQ(Scrambler({}, {2}, 4096ull * 5).table_entries(), 4096u + 6);  // chunk 1 up to 5
  // 41 digits in chunks of 7: the top chunk takes ⌊(2^64 − 1) / 3^35⌋ = 368 at most.
  EXPECT_EQ(Scrambler({}, {3}, ~0ull).table_entries(), 5u * 2187 + 369);
  EXPECT_EQ(Scrambler({}, {8161}, ~0ull).table_entries(), 4u * 8161 + 4159);
  EXPECT_EQ(Scrambler({}, {2, 3}, 0).table_entries(), 2u);
}

// Small index ranges build only the table rows they keep; those rows equal
// the full tables' bit for bit (chunks straddled, partly and fully covered).
TEST(Digits, TruncatedTablesEqualFullTables) {
  const std::vector<std::uint32_t> bases = {2, 3, 5, 67, 8161};
  const digits_detail::PositionalDigitScrambler<RotateByPositionRule> full({}, bases, ~0ull);
  for (std::uint64_t max_index : {0ull, 1ull, 2ull, 3ull, 4ull, 15ull, 16ull, 100ull, 4095ull, 4097ull, 20000ull}) {
    const digits_detail::PositionalDigitScrambler<RotateByPositionRule> small({}, bases, max_index);
    for (unsigned dim = 0; dim < bases.size(); ++dim)
      for (std::uint64_t index = 0; index <= std::min<std::uint64_t>(max_index, 300); ++index)
        ASSERT_EQ(small.fraction(index, dim), full.fraction(index, dim)) << max_index << " " << dim << " " << index;
  }
}

TEST(Digits, FillEqualsSampleAcrossRunsAndTableEdges) {
  const std::vector<std::uint32_t> bases = {2, 3, 67, 8161};
  const digits_detail::PositionalDigitScrambler<RotateByPositionRule> scrambler({}, bases, 20000);
  std::vector<double> out(3 * 9000, -1.0);
  for (unsigned dim = 0; dim < bases.size(); ++dim)
    for (std::uint64_t first : {0ull, 1ull, 4090ull, 11000ull, 19000ull /* runs past max_index */}) {
      scrambler.fill(first, 9000, dim, out.data() + 1, 3);
      for (std::uint64_t k = 0; k < 9000; ++k)
        ASSERT_EQ(out[1 + 3 * k], scrambler.sample(first + k, dim)) << dim << " " << first + k;
      EXPECT_EQ(out[0], -1.0);  // nothing written outside the column
    }
  // Partial tables (max_index < b^m − 1) fall back to per-sample.
  const digits_detail::PositionalDigitScrambler<RotateByPositionRule> tiny({}, bases, 5);
  tiny.fill(0, 100, 0, out.data(), 1);
  for (std::uint64_t k = 0; k < 100; ++k) ASSERT_EQ(out[k], scrambler.sample(k, 0));
}

TEST(Digits, RejectsBadBases) {
  using Scrambler = digits_detail::PositionalDigitScrambler<IdentityRule>;
  EXPECT_THROW(Scrambler({}, {}, 10), invalid_argument);
  EXPECT_THROW(Scrambler({}, {2, 1}, 10), invalid_argument);
  EXPECT_THROW(Scrambler({}, {65537}, 10), invalid_argument);
  EXPECT_NO_THROW(Scrambler({}, {65536}, 10));
  try {
    Scrambler({}, {3, 0}, 10);
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "base");
    EXPECT_NE(std::string(e.what()).find("65536"), std::string::npos);
  }
}

}  // namespace
}  // namespace stratum
