#include "stratum/sequences/lattice_sequence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/registry.hpp"
#include "../registry/registry_points.hpp"
#include "stratum/sequences/lattice.hpp"
#include "stratum/sequences/radical_inverse.hpp"
#include "../patterns/unbiased.hpp"

namespace stratum {
namespace {

using Points = std::vector<std::vector<double>>;

Points sorted_points(Points points) {
  std::sort(points.begin(), points.end());
  return points;
}

// Every prefix of 2^m points is the rank-1 lattice with n = 2^m and
// z = g mod 2^m (as sets; Rank1Lattice computes frac(k z / n) its own way),
// and the next 2^m points are that lattice shifted by φ_2(2^m)·g = g/2^(m+1).
TEST(LatticeSequence, PrefixesOfTwoToTheMAreRankOneLattices) {
  for (unsigned d : {1u, 3u, 8u}) {
    const LatticeSequence sequence(d);
    for (unsigned m = 1; m <= 14; ++m) {
      const std::uint64_t n = std::uint64_t{1} << m;
      std::vector<std::uint64_t> z(d);
      for (unsigned j = 0; j < d; ++j) z[j] = sequence.generator(j) % n;
      const Rank1Lattice lattice(n, z);
      Points prefix(n, std::vector<double>(d)), rule(n, std::vector<double>(d)), next(n, std::vector<double>(d));
      for (std::uint64_t i = 0; i < n; ++i)
        for (unsigned j = 0; j < d; ++j) {
          prefix[i][j] = sequence.sample(i, j);
          rule[i][j] = lattice.sample(i, j);
          // Shift by g_j / 2n mod 1 (exact: a dyadic with m + 1 bits).
          const double shifted = rule[i][j] + static_cast<double>(sequence.generator(j) % (2 * n)) / (2.0 * n);
          next[i][j] = shifted - std::floor(shifted);
        }
      ASSERT_EQ(sorted_points(prefix), sorted_points(rule)) << "d " << d << " m " << m;
      Points second(n, std::vector<double>(d));
      for (std::uint64_t i = 0; i < n; ++i)
        for (unsigned j = 0; j < d; ++j) second[i][j] = sequence.sample(n + i, j);
      ASSERT_EQ(sorted_points(second), sorted_points(next)) << "d " << d << " m " << m;
    }
  }
}

// Reference values. By hand: φ_2(1) = 1/2, φ_2(3) = 3/4, φ_2(5) = 5/8, and
// g_1 = 182667: frac(g/2) = 1/2, frac(3g/4) = 1/4, frac(5g/8) = 7/8. Then
// frac(φ_2(i) g) in long double (φ_2(i) has ≤ 20 bits and g ≤ 2^19, so the
// product is exact) for every i < 2^12 and all 32 default components.
TEST(LatticeSequence, ReferenceValues) {
  const LatticeSequence sequence(32);
  EXPECT_EQ(sequence.generator(0), 1u);
  EXPECT_EQ(sequence.generator(1), 182667u);
  EXPECT_EQ(sequence.generator(31), 511893u);
  EXPECT_EQ(sequence.sample(1, 1), 0.5);
  EXPECT_EQ(sequence.sample(3, 1), 0.25);
  EXPECT_EQ(sequence.sample(5, 1), 0.875);
  for (std::uint64_t i = 0; i < 4096; ++i)
    for (unsigned j = 0; j < 32; ++j) {
      const long double x = static_cast<long double>(radical_inverse(2, i)) * sequence.generator(j);
      ASSERT_EQ(sequence.sample(i, j), static_cast<double>(x - std::floor(x))) << i << " " << j;
      ASSERT_LT(sequence.sample<float>(i, j), 1.0f);
    }
  for (unsigned j = 0; j < 32; ++j) EXPECT_EQ(sequence.generator(j) % 2, 1u) << j;  // Latin prefixes
}

// Large indices: the fraction is exact, so the point of index 2^40 + k is
// frac(φ_2(k) g + g / 2^41) for k < 2^40: check it against the small-index
// value plus the shift, in 64-bit fractions.
TEST(LatticeSequence, LargeIndicesAreExact) {
  const std::vector<std::uint64_t> g = {1, 0x9e3779b97f4a7c15ULL, 3};
  const LatticeSequence sequence(g);
  for (std::uint64_t k : {std::uint64_t{0}, std::uint64_t{5}, std::uint64_t{123456789}})
    for (unsigned j = 0; j < 3; ++j) {
      const std::uint64_t shift = g[j] << 23;  // φ_2(2^40) = 2^-41: g_j · 2^23 in 64-bit fractions
      EXPECT_EQ(sequence.fraction((std::uint64_t{1} << 40) + k, j), sequence.fraction(k, j) + shift) << k << " " << j;
    }
}

TEST(LatticeSequence, RejectsBadArguments) {
  EXPECT_THROW(LatticeSequence(0u), invalid_argument);
  EXPECT_THROW(LatticeSequence(33u), invalid_argument);
  try {
    LatticeSequence(std::vector<std::uint64_t>{1, 0});
    FAIL() << "accepted a zero entry";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "generator");
  }
  EXPECT_THROW(LatticeSequence(std::vector<std::uint64_t>{}), invalid_argument);
}

// ---- The registry's lattice-sequence ----

PointSet registry_points(std::uint64_t n, unsigned d, const std::string& randomize, std::uint64_t seed,
                         std::map<std::string, std::string> params = {}, std::uint64_t start = 0) {
  return testing::sampler_points("lattice-sequence", n, d, randomize, seed, start, std::move(params));
}

TEST(LatticeSequenceRegistry, IsTheHeadersSequenceWithCranleyPatterson) {
  const SamplerInfo& info = find_sampler("lattice-sequence");
  EXPECT_EQ(info.kind, "sequence");
  EXPECT_EQ(info.randomizers, (std::vector<std::string>{"none", "cp"}));
  const LatticeSequence sequence(5);
  const CranleyPattersonRotation rotation(11);
  const PointSet plain = registry_points(64, 5, "none", 11, {}, 100);
  const PointSet rotated = registry_points(64, 5, "cp", 11, {}, 100);
  for (std::size_t i = 0; i < 64; ++i)
    for (unsigned j = 0; j < 5; ++j) {
      ASSERT_EQ(plain(i, j), sequence.sample(100 + i, j));
      ASSERT_EQ(rotated(i, j), rotation(sequence.sample(100 + i, j), j));
    }
  const PointSet user = registry_points(4, 2, "none", 0, {{"generator", "1,3"}});
  EXPECT_EQ(user(3, 1), 0.25);  // φ_2(3) · 3 = 9/4
  // More dimensions than the default vector has, with a user's vector.
  std::string forty = "1";
  for (int j = 1; j < 40; ++j) forty += "," + std::to_string(2 * j + 1);
  EXPECT_EQ(registry_points(4, 40, "none", 0, {{"generator", forty}})(1, 39), 0.5);
}

TEST(LatticeSequenceRegistry, RejectsBadParameters) {
  for (const auto& [d, value] :
       std::vector<std::pair<unsigned, std::string>>{{2, "1"}, {2, "1,0"}, {2, "1,-3"}, {2, "1,x"}, {40, ""}}) {
    try {
      registry_points(4, d, "none", 0,
                      value.empty() ? std::map<std::string, std::string>{}
                                    : std::map<std::string, std::string>{{"generator", value}});
      FAIL() << "d " << d << " generator=" << value;
    } catch (const invalid_argument& e) {
      EXPECT_TRUE(e.argument().rfind("generator", 0) == 0 || e.argument() == "d") << e.argument();
    }
  }
}

// Unbiasedness of cp: over 400 seeds the mean of Q = (1/64) Σ f(x_k), f =
// x0 · x1² · exp(x2), ∫f = (e − 1)/6, matches the integral (two-sided
// t-test, α = 1e-3).
TEST(LatticeSequenceRegistry, CranleyPattersonEstimatesAreUnbiased) {
  std::vector<double> estimates;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    const PointSet p = registry_points(64, 3, "cp", seed + 900);
    estimates.push_back(testing::product_test_mean(p.data.get(), p.n, p.d));
  }
  testing::expect_unbiased("lattice-sequence:cp", estimates, testing::product_test_integral(), 1e-3);
}

}  // namespace
}  // namespace stratum
