// The registry's Hammersley entry (src/registry/samplers_sequences.cpp):
// coordinate 0, i/N, is randomized by every randomizer but none, so the
// estimates are unbiased and replicate standard errors are not a false 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../patterns/unbiased.hpp"
#include "error_of.hpp"
#include "registry_points.hpp"
#include "stratum/analysis/convergence.hpp"

namespace stratum {
namespace {

using testing::sampler_points;

// N = 4 points, fraction with x_0 < 0.3: 1/2 for the unrandomized i/N, 0.3 in
// expectation once x_0 is uniform. 2000 seeds per randomizer, Šidák level for
// a family level of 0.001 over the four randomizers.
TEST(HammersleyRegistry, FirstCoordinateIsRandomizedAndUnbiased) {
  const double alpha = testing::sidak(0.001, 4);
  for (const std::string randomize : {"permute", "xor", "owen", "cp"}) {
    std::vector<double> estimates;
    for (std::uint64_t seed = 0; seed < 2000; ++seed) {
      const PointSet points = sampler_points("hammersley", 4, 2, randomize, seed);
      double below = 0;
      for (std::size_t i = 0; i < 4; ++i) below += points.data[i * 2] < 0.3 ? 1 : 0;
      estimates.push_back(below / 4);
    }
    testing::expect_unbiased("hammersley:" + randomize + " x_0", estimates, 0.3, alpha);
  }
  // d = 1 (i/N alone) is randomized too.
  EXPECT_NE(sampler_points("hammersley", 8, 1, "owen", 1).data[0],
            sampler_points("hammersley", 8, 1, "owen", 2).data[0]);
}

// At N = 2^k every randomizer keeps coordinate 0 Latin and the (0, k, 2)-net
// of (i/N, φ_2(i)): each 2^a × 2^(k−a) elementary box holds one point.
TEST(HammersleyRegistry, NetSurvivesAtPowersOfTwo) {
  const unsigned k = 6;
  const std::uint64_t n = 1u << k;
  for (const std::string randomize : {"permute", "xor", "owen", "none"}) {
    const PointSet points = sampler_points("hammersley", n, 2, randomize, 7);
    for (unsigned a = 0; a <= k; ++a) {
      std::vector<int> count(n, 0);
      for (std::uint64_t i = 0; i < n; ++i) {
        const auto x = static_cast<std::uint64_t>(points.data[i * 2] * static_cast<double>(1u << a));
        const auto y = static_cast<std::uint64_t>(points.data[i * 2 + 1] * static_cast<double>(1u << (k - a)));
        ++count[x * (1u << (k - a)) + y];
      }
      EXPECT_TRUE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; })) << randomize << " a = " << a;
    }
  }
}

// The issue's case: step, hammersley:owen, n = 64, 16 runs gave "standard
// error 0" with an error of 0.0098. Now the runs differ and the replicate
// t-test (t_15 at α = 0.001: 4.07) holds; a sampler that is not randomized
// reports no standard error (NaN, "identical-runs"), never 0.
TEST(HammersleyRegistry, ReplicateStandardErrorIsNeverAFalseZero) {
  analysis::IntegrationRequest request;
  request.integrand.name = "step";
  request.sampler = analysis::parse_sampler_choice("hammersley:owen");
  request.n = 64;
  request.runs = 16;
  const auto owen = analysis::integrate(request);
  EXPECT_EQ(owen.standard_error_kind, "replicates");
  EXPECT_GT(owen.standard_error, 0.0);
  EXPECT_LT(std::abs(owen.error), 4.07 * owen.standard_error);
  for (const char* spec : {"grid", "zaremba", "hammersley:none", "fibonacci"}) {
    request.sampler = analysis::parse_sampler_choice(spec);
    const auto fixed = analysis::integrate(request);
    EXPECT_EQ(fixed.standard_error_kind, "identical-runs") << spec;
    EXPECT_TRUE(std::isnan(fixed.standard_error)) << spec;
  }
}

// Halton in the given bases (the radical inverse in any base, as the
// lecture's slide defines it): φ_b(i) by hand for b = 10 and 7, the prime
// bases reproduce the default bit for bit, and each randomizer keeps the
// one-point-per-b^-m-interval property of φ_b at n = b^m.
TEST(HaltonRegistry, GivenBasesAreRadicalInversesInThoseBases) {
  const PointSet decimal = sampler_points("halton", 130, 1, "none", 0, 0, {{"bases", "10"}});
  EXPECT_DOUBLE_EQ(decimal.data[123], 0.321);  // 123 -> 0.321
  EXPECT_DOUBLE_EQ(decimal.data[7], 0.7);
  EXPECT_DOUBLE_EQ(decimal.data[10], 0.01);
  const PointSet seven = sampler_points("halton", 60, 1, "none", 0, 0, {{"bases", "7"}});
  EXPECT_DOUBLE_EQ(seven.data[59], 3.0 / 7 + 1.0 / 49 + 1.0 / 343);  // 59 = (1 1 3)_7 -> 0.311_7
  const PointSet primes = sampler_points("halton", 500, 3, "none", 0, 0, {{"bases", "2,3,5"}});
  const PointSet standard = sampler_points("halton", 500, 3, "none", 0);
  for (std::size_t i = 0; i < 1500; ++i) EXPECT_EQ(primes.data[i], standard.data[i]) << i;
  for (const std::string randomize : {"permute", "owen", "xor"}) {
    const PointSet scrambled = sampler_points("halton", 500, 3, randomize, 9, 0, {{"bases", "2,3,5"}});
    const PointSet default_bases = sampler_points("halton", 500, 3, randomize, 9);
    for (std::size_t i = 0; i < 1500; ++i) ASSERT_EQ(scrambled.data[i], default_bases.data[i]) << randomize << " " << i;
  }
}

TEST(HaltonRegistry, EachRandomizerKeepsTheIntervalsOfAnyBase) {
  for (const std::uint32_t base : {6u, 7u, 10u}) {
    const std::uint64_t n = std::uint64_t(base) * base;  // m = 2
    for (const std::string randomize : {"none", "permute", "owen", "xor"}) {
      const PointSet points = sampler_points("halton", n, 1, randomize, 3, 0, {{"bases", std::to_string(base)}});
      std::vector<int> count(n, 0);
      // The unscrambled points sit on the intervals' left ends (k/n, which
      // base 7 and 10 do not represent exactly): 1e-9 keeps them inside.
      for (std::uint64_t i = 0; i < n; ++i) ++count[static_cast<std::size_t>(points.data[i] * double(n) + 1e-9)];
      EXPECT_TRUE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }))
          << "base " << base << " " << randomize;
    }
  }
  // Cranley–Patterson shifts the points: one per interval no longer, but a rotation of φ_b.
  const PointSet rotated = sampler_points("halton", 49, 1, "cp", 3, 0, {{"bases", "7"}});
  const PointSet plain = sampler_points("halton", 49, 1, "none", 0, 0, {{"bases", "7"}});
  const double shift = rotated.data[0] - plain.data[0];
  for (std::size_t i = 0; i < 49; ++i) {
    double expected = plain.data[i] + shift;
    expected -= std::floor(expected);
    EXPECT_NEAR(rotated.data[i], expected, 1e-15) << i;
  }
}

TEST(HaltonRegistry, BasesMustMatchTheDimension) {
  EXPECT_EQ(testing::error_of([] {
              sampler_points("halton", 4, 2, "none", 0, 0, {{"bases", "3"}});
            }),
            "invalid bases = (1 value): give one base per dimension: d = 2");
  EXPECT_EQ(testing::error_of([] {
              sampler_points("halton", 4, 1, "none", 0, 0, {{"bases", "1"}});
            }),
            "invalid bases[0] = 1: must be an integer in [2, 65536] (bases takes 1 to 1024 integers)");
}

}  // namespace
}  // namespace stratum
