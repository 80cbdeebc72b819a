#include "stratum/randomizers/digital_shift_base_b.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <vector>

#include "stratum/util/bits.hpp"

namespace stratum {
namespace {

const std::vector<std::uint32_t> kBases = {2, 3, 5, 7, 8161};

double chi_squared_p(double statistic, double dof) {
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), statistic));
}
double sidak(double alpha, int m) { return 1 - std::pow(1 - alpha, 1.0 / m); }

// In base 2 the digital shift is the XOR with one word, and that word is the
// image of index 0: x(i) = reverse(i) ⊕ x(0).
TEST(BaseBDigitalShift, BaseTwoIsXorWithARandomWord) {
  const BaseBDigitalShift s(3, {2});
  const std::uint64_t word = s.fraction(0, 0);
  EXPECT_NE(word, 0u);
  for (std::uint64_t i : {1ull, 2ull, 12345ull, (1ull << 32) + 9, ~0ull})
    EXPECT_EQ(s.fraction(i, 0), reverse_bits64(i) ^ word) << i;
  for (unsigned j = 0; j < 64; ++j) EXPECT_EQ(s.shift(0, j), (word >> (63 - j)) & 1u) << j;
}

// Oracle: Σ_j ((a_j + s_j) mod b) b^-(j+1) in long double.
TEST(BaseBDigitalShift, AddsTheShiftDigitByDigitAtAnyIndex) {
  const BaseBDigitalShift full(11, kBases), small(11, kBases, 100);
  for (unsigned dim = 0; dim < kBases.size(); ++dim)
    for (std::uint64_t index :
         {0ull, 1ull, 99ull, 100ull, 101ull, 4096ull, 987654321ull, (1ull << 32) + 3, (1ull << 50) + 1, ~0ull}) {
      const std::uint32_t b = kBases[dim];
      long double expected = 0, scale = 1.0L / b;
      std::uint64_t rest = index;
      for (unsigned j = 0; j < digits_detail::digit_count(b); ++j) {
        expected += static_cast<long double>((rest % b + full.shift(dim, j)) % b) * scale;
        rest /= b;
        scale /= b;
      }
      EXPECT_LE(full.sample(index, dim), expected) << dim << " " << index;
      EXPECT_GT(full.sample(index, dim), expected - 0x1.0p-53L - 0x1.0p-60L) << dim << " " << index;
      EXPECT_EQ(full.fraction(index, dim), small.fraction(index, dim)) << dim << " " << index;
    }
}

TEST(BaseBDigitalShift, FirstBToTheKPointsStratifyTheUnitInterval) {
  const BaseBDigitalShift s(4, kBases, 5000);
  for (unsigned dim = 0; dim < 4; ++dim)
    for (std::uint64_t count = kBases[dim]; count <= 3000; count *= kBases[dim]) {
      std::vector<int> hits(count, 0);
      for (std::uint64_t i = 0; i < count; ++i) ++hits[static_cast<std::size_t>(s.sample(i, dim) * count)];
      for (int h : hits) ASSERT_EQ(h, 1) << "base " << kBases[dim] << " count " << count;
    }
}

// Shift digits are uniform over seeds: base 5, positions 0 and 27 (the last
// of K(5) = 28), 5000 seeds, χ² with 4 dof; and for fixed indices the
// coordinate is uniform (2000 seeds, 20 bins, χ² with 19 dof). 2 + 12 tests
// at family-wise α = 1e-3 (Šidák).
TEST(BaseBDigitalShift, ShiftsAndCoordinatesAreUniformOverSeeds) {
  const std::vector<std::uint32_t> bases = {2, 3, 7};
  const std::vector<std::uint64_t> indices = {0, 5, 1000, (1ull << 40) + 1};
  const double level = sidak(1e-3, 2 + static_cast<int>(bases.size() * indices.size()));
  std::vector<int> digit0(5, 0), digit27(5, 0);
  for (std::uint64_t seed = 0; seed < 5000; ++seed) {
    const BaseBDigitalShift s(seed, {5}, 0);
    ++digit0[s.shift(0, 0)];
    ++digit27[s.shift(0, 27)];
  }
  for (const auto& counts : {digit0, digit27}) {
    double x = 0;
    for (int c : counts) x += (c - 1000.0) * (c - 1000.0) / 1000.0;
    EXPECT_GT(chi_squared_p(x, 4), level) << x;
  }
  const int seeds = 2000, bins = 20;
  std::vector<std::vector<int>> counts(bases.size() * indices.size(), std::vector<int>(bins, 0));
  for (int seed = 0; seed < seeds; ++seed) {
    const BaseBDigitalShift s(static_cast<std::uint64_t>(seed), bases, 10);
    for (std::size_t k = 0; k < indices.size(); ++k)
      for (unsigned dim = 0; dim < bases.size(); ++dim)
        ++counts[k * bases.size() + dim][static_cast<std::size_t>(s.sample(indices[k], dim) * bins)];
  }
  for (std::size_t t = 0; t < counts.size(); ++t) {
    double x = 0;
    for (int c : counts[t]) x += (c - 100.0) * (c - 100.0) / 100.0;
    EXPECT_GT(chi_squared_p(x, bins - 1), level) << "test " << t << " chi2 " << x;
  }
}

TEST(BaseBDigitalShift, FloatIsTheRoundedDoubleAndStaysBelowOne) {
  const BaseBDigitalShift s(8, kBases, 3000);
  for (unsigned dim = 0; dim < kBases.size(); ++dim)
    for (std::uint64_t i = 0; i < 3000; i += 7) {
      const double x = s.sample(i, dim);
      ASSERT_EQ(s.sample<float>(i, dim), to_unit_float(x));
      ASSERT_LT(x, 1.0);
      ASSERT_GE(x, 0.0);
    }
}

}  // namespace
}  // namespace stratum
