#include "stratum/sequences/faure.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/randomizers/digital_shift_base_b.hpp"
#include "stratum/randomizers/owen_base_b.hpp"
#include "stratum/registry.hpp"
#include "../registry/registry_points.hpp"
#include "stratum/sequences/sobol.hpp"
#include "../patterns/unbiased.hpp"

namespace stratum {
namespace {

using Matrix = std::vector<std::vector<std::uint64_t>>;

// P^j mod b by repeated matrix multiplication of the Pascal matrix
// P[r][c] = binom(c, r) mod b, itself built by the recurrence
// binom(c, r) = binom(c−1, r−1) + binom(c−1, r): independent of the
// header's closed form binom(c, r)·j^(c−r).
Matrix pascal_power(std::uint32_t b, unsigned size, unsigned j) {
  Matrix pascal(size, std::vector<std::uint64_t>(size, 0)), power(size, std::vector<std::uint64_t>(size, 0));
  for (unsigned c = 0; c < size; ++c)
    for (unsigned r = 0; r <= c; ++r)
      pascal[r][c] = (r == 0 || r == c) ? 1 : (pascal[r - 1][c - 1] + pascal[r][c - 1]) % b;
  for (unsigned k = 0; k < size; ++k) power[k][k] = 1;
  for (unsigned step = 0; step < j; ++step) {
    Matrix next(size, std::vector<std::uint64_t>(size, 0));
    for (unsigned r = 0; r < size; ++r)
      for (unsigned c = 0; c < size; ++c)
        for (unsigned k = 0; k < size; ++k) next[r][c] = (next[r][c] + power[r][k] * pascal[k][c]) % b;
    power = next;
  }
  return power;
}

// The point's coordinate by definition: digits a of i, y = C a mod b,
// Σ y_r b^-(r+1) in long double.
long double brute_force_coordinate(const Matrix& c, std::uint32_t b, std::uint64_t i, std::uint64_t* word) {
  std::vector<std::uint64_t> a;
  for (; i != 0; i /= b) a.push_back(i % b);
  long double x = 0, weight = 1.0L / b;
  std::uint64_t w = 0, place = 1;
  for (std::size_t r = 0; r < a.size(); ++r) {
    std::uint64_t y = 0;
    for (std::size_t k = 0; k < a.size(); ++k) y = (y + c[r][k] * a[k]) % b;
    x += weight * y;
    weight /= b;
    w += y * place;
    place *= b;
  }
  *word = w;
  return x;
}

TEST(Faure, BaseIsTheSmallestPrimeAtLeastS) {
  const std::vector<std::pair<unsigned, std::uint32_t>> cases = {{1, 2}, {2, 2},  {3, 3},   {4, 5},      {5, 5},
                                                                 {6, 7}, {8, 11}, {14, 17}, {1024, 1031}};
  for (const auto& [s, b] : cases) {
    EXPECT_EQ(Faure::base_for(s), b) << s;
    EXPECT_EQ(Faure(s).base(), b) << s;
  }
  EXPECT_EQ(Faure(2).output_digits(), 64u);
  EXPECT_EQ(Faure(3).index_digits(), 41u);  // 3^40 < 2^64 < 3^41
  EXPECT_EQ(Faure(3).output_digits(), 40u);
}

// By hand in base 3: index 1 = (1) gives 1/3 in every coordinate; index
// 3 = (0, 1) gives column 1 of P^j, (j, 1): x_j = j/3 + 1/9.
TEST(Faure, FirstPointsByHand) {
  const Faure faure(3);
  for (unsigned j = 0; j < 3; ++j) {
    EXPECT_DOUBLE_EQ(faure.sample(1, j), 1.0 / 3);
    EXPECT_DOUBLE_EQ(faure.sample(3, j), j / 3.0 + 1.0 / 9);
    EXPECT_EQ(faure.sample(0, j), 0.0);
  }
  EXPECT_EQ(faure.digit_word(3, 2), 2u + 1u * 3u);
}

TEST(Faure, EqualsTheBruteForceMatrixConstruction) {
  for (unsigned s : {2u, 3u, 5u, 7u, 12u}) {
    const Faure faure(s);
    const std::uint32_t b = faure.base();
    const unsigned size = faure.index_digits();
    for (unsigned j = 0; j < s; ++j) {
      const Matrix c = pascal_power(b, size, j);
      for (unsigned r = 0; r < faure.output_digits(); ++r)
        for (unsigned k = 0; k < size; ++k) ASSERT_EQ(faure.generator(j, r, k), c[r][k]) << s << " " << j;
      std::vector<std::uint64_t> indices;
      for (std::uint64_t i = 0; i < 600; ++i) indices.push_back(i);
      // Up to b^R − 1, the last index whose digits all stay (past 2^60: the
      // digits' quotients change from the reciprocal to a division).
      unsigned __int128 last = 1;
      for (unsigned r = 0; r < faure.output_digits(); ++r) last *= b;
      const auto largest = static_cast<std::uint64_t>(last - 1);
      for (std::uint64_t i : {std::uint64_t{1} << 30, (std::uint64_t{1} << 40) + 77, std::uint64_t{123456789012345},
                              largest / 3 * 2, largest - 5, largest})
        indices.push_back(i);
      for (std::uint64_t i : indices) {
        std::uint64_t word = 0;
        const long double x = brute_force_coordinate(c, b, i, &word);
        ASSERT_EQ(faure.digit_word(i, j), word) << "s " << s << " j " << j << " i " << i;
        ASSERT_NEAR(faure.sample(i, j), static_cast<double>(x), 0x1.0p-52) << "s " << s << " j " << j << " i " << i;
        ASSERT_LT(faure.sample<float>(i, j), 1.0f);
      }
    }
  }
}

// In base 2 the Pascal matrix is the generator of Sobol's dimension 1
// (Sobol' 1967's second coordinate; Niederreiter 1992, Sec. 4.5): Faure
// with s = 2 is the (0, 2)-sequence of Sobol's first two dimensions in the
// natural (non-Gray) index order.
TEST(Faure, TwoDimensionsAreSobolsFirstTwo) {
  const Faure faure(2);
  const Sobol sobol(2, Sobol::Order::natural);
  for (std::uint64_t i = 0; i < 4096; ++i)
    for (unsigned j = 0; j < 2; ++j) ASSERT_EQ(faure.sample(i, j), sobol.sample(i, j)) << i << " " << j;
  EXPECT_EQ(faure.sample((std::uint64_t{1} << 50) + 3, 1), sobol.sample((std::uint64_t{1} << 50) + 3, 1));
}

TEST(Faure, RejectsBadDimensions) {
  EXPECT_THROW(Faure(0), invalid_argument);
  EXPECT_THROW(Faure(Faure::max_dimensions + 1), invalid_argument);
}

// ---- The (0, m, s)-net property ----

std::uint64_t power(std::uint64_t b, unsigned k) {
  std::uint64_t p = 1;
  for (unsigned t = 0; t < k; ++t) p *= b;
  return p;
}

// Every composition (k_0, …, k_(s−1)) of m into s parts ≥ 0.
void for_each_composition(unsigned m, unsigned s, const std::function<void(const std::vector<unsigned>&)>& visit) {
  std::vector<unsigned> parts(s, 0);
  std::function<void(unsigned, unsigned)> place = [&](unsigned dim, unsigned left) {
    if (dim + 1 == s) {
      parts[dim] = left;
      visit(parts);
      return;
    }
    for (unsigned k = 0; k <= left; ++k) {
      parts[dim] = k;
      place(dim + 1, left - k);
    }
  };
  place(0, m);
}

// Checks that points first … first + b^m − 1 put exactly one point in each
// elementary interval of volume b^-m; cell(i, j, k) is point i's interval
// index at resolution b^-k in dimension j (its first k digits).
void expect_net(unsigned s, std::uint32_t b, unsigned m, std::uint64_t first,
                const std::function<std::uint64_t(std::uint64_t, unsigned, unsigned)>& cell, const std::string& what) {
  const std::uint64_t n = power(b, m);
  for_each_composition(m, s, [&](const std::vector<unsigned>& k) {
    std::vector<int> hits(n, 0);
    for (std::uint64_t i = first; i < first + n; ++i) {
      std::uint64_t box = 0;
      for (unsigned j = 0; j < s; ++j) box = box * power(b, k[j]) + cell(i, j, k[j]);
      ++hits[box];
    }
    for (int h : hits) ASSERT_EQ(h, 1) << what << " m " << m << " first " << first;
  });
}

// The first k digits of a digit word (y_0 first) as an interval index.
std::uint64_t leading_digits(std::uint64_t word, std::uint32_t b, unsigned k) {
  std::uint64_t box = 0;
  for (unsigned r = 0; r < k; ++r, word /= b) box = box * b + word % b;
  return box;
}

// The interval index of a 64-bit binary fraction at resolution b^-k, exactly.
std::uint64_t fraction_cell(std::uint64_t fraction, std::uint32_t b, unsigned k) {
  return static_cast<std::uint64_t>((static_cast<unsigned __int128>(fraction) * power(b, k)) >> 64);
}

// Exhaustive over every elementary interval, for blocks at 0, at b^m and at
// a large multiple of b^m (the sequence property, not only the first net).
TEST(Faure, BlocksOfBToTheMPointsAreZeroMSNets) {
  for (const auto& [s, max_m] : std::vector<std::pair<unsigned, unsigned>>{{2, 10}, {3, 6}, {4, 4}, {5, 4}, {7, 3}}) {
    const Faure faure(s);
    const std::uint32_t b = faure.base();
    for (unsigned m = 0; m <= max_m; ++m)
      for (std::uint64_t block : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{1} << 20}) {
        expect_net(
            s, b, m, block * power(b, m),
            [&](std::uint64_t i, unsigned j, unsigned k) { return leading_digits(faure.digit_word(i, j), b, k); },
            "faure s " + std::to_string(s));
      }
  }
}

// The base-b randomizers, applied to the digit word, keep every block a
// (0, m, s)-net (checked on their exact 64-bit fractions).
TEST(Faure, RandomizedNetsStayNets) {
  for (const auto& [s, max_m] : std::vector<std::pair<unsigned, unsigned>>{{3, 5}, {5, 4}}) {
    const Faure faure(s);
    const std::uint32_t b = faure.base();
    const std::vector<std::uint32_t> bases(s, b);
    const BaseBOwenScrambler owen(42, bases);
    const BaseBDigitalShift shift(42, bases);
    const RandomDigitPermutations permute(42, bases);
    for (unsigned m = 1; m <= max_m; ++m)
      for (std::uint64_t block : {std::uint64_t{0}, std::uint64_t{7}}) {
        const std::uint64_t first = block * power(b, m);
        expect_net(
            s, b, m, first,
            [&](std::uint64_t i, unsigned j, unsigned k) {
              return fraction_cell(owen.fraction(faure.digit_word(i, j), j), b, k);
            },
            "owen");
        expect_net(
            s, b, m, first,
            [&](std::uint64_t i, unsigned j, unsigned k) {
              return fraction_cell(shift.fraction(faure.digit_word(i, j), j), b, k);
            },
            "xor");
        expect_net(
            s, b, m, first,
            [&](std::uint64_t i, unsigned j, unsigned k) {
              return fraction_cell(permute.fraction(faure.digit_word(i, j), j), b, k);
            },
            "permute");
      }
  }
}

// ---- The registry's faure ----

PointSet registry_points(std::uint64_t n, unsigned d, const std::string& randomize, std::uint64_t seed,
                         std::uint64_t start = 0) {
  return testing::sampler_points("faure", n, d, randomize, seed, start);
}

TEST(FaureRegistry, IsTheHeadersSequenceUnderEachRandomizer) {
  const SamplerInfo& info = find_sampler("faure");
  EXPECT_EQ(info.kind, "sequence");
  EXPECT_EQ(info.randomizers, (std::vector<std::string>{"owen", "permute", "none", "xor", "cp"}));
  const unsigned d = 4;
  const Faure faure(d);
  const std::vector<std::uint32_t> bases(d, faure.base());
  const std::uint64_t start = 3000, n = 200, seed = 9;
  const BaseBOwenScrambler owen(seed, bases);
  const BaseBDigitalShift shift(seed, bases);
  const RandomDigitPermutations permute(seed, bases);
  const PointSet none = registry_points(n, d, "none", seed, start),
                 by_owen = registry_points(n, d, "owen", seed, start);
  const PointSet by_shift = registry_points(n, d, "xor", seed, start);
  const PointSet by_permute = registry_points(n, d, "permute", seed, start);
  const PointSet by_default = registry_points(n, d, "", seed, start);
  for (std::uint64_t i = 0; i < n; ++i)
    for (unsigned j = 0; j < d; ++j) {
      const std::uint64_t word = faure.digit_word(start + i, j);
      ASSERT_EQ(none(i, j), faure.sample(start + i, j));
      ASSERT_EQ(by_owen(i, j), owen.sample(word, j));
      ASSERT_EQ(by_default(i, j), by_owen(i, j));
      ASSERT_EQ(by_shift(i, j), shift.sample(word, j));
      ASSERT_EQ(by_permute(i, j), permute.sample(word, j));
    }
}

// Unbiasedness over seeds: the mean of Q = (1/125) Σ f(x_k), f = x0 · x1² ·
// exp(x2), ∫f = (e − 1)/6, over 300 seeds, two-sided t-tests for the four
// randomizers at family-wise α = 1e-3 (Šidák).
TEST(FaureRegistry, EstimatesAreUnbiasedOverSeeds) {
  const std::vector<std::string> randomizers = {"owen", "permute", "xor", "cp"};
  const double level = testing::sidak(1e-3, static_cast<int>(randomizers.size()));
  for (const std::string& randomize : randomizers) {
    std::vector<double> estimates;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
      const PointSet p = registry_points(125, 3, randomize, seed + 77);
      estimates.push_back(testing::product_test_mean(p.data.get(), p.n, p.d));
    }
    testing::expect_unbiased("faure:" + randomize, estimates, testing::product_test_integral(), level);
  }
}

}  // namespace
}  // namespace stratum
