// The registry's Hammersley entry (src/registry/samplers_sequences.cpp):
// coordinate 0, i/N, is randomized by every randomizer but none, so the
// estimates are unbiased and replicate standard errors are not a false 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../patterns/unbiased.hpp"
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
  EXPECT_NE(sampler_points("hammersley", 8, 1, "owen", 1).data[0], sampler_points("hammersley", 8, 1, "owen", 2).data[0]);
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

}  // namespace
}  // namespace stratum
