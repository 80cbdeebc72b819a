#include "stratum/sequences/kronecker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <set>
#include <vector>

#include "stratum/analysis/l2_discrepancy.hpp"
#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/registry.hpp"
#include "../registry/registry_points.hpp"
#include "stratum/util/hash.hpp"
#include "../patterns/unbiased.hpp"

namespace stratum {
namespace {

using u128 = Kronecker::u128;
using Big = boost::multiprecision::cpp_bin_float_50;  // 166 bits

// φ_d by Newton's method on x^(d+1) − x − 1 in 166-bit arithmetic: an oracle
// independent of the header's fixed-point bisection.
Big golden_ratio_oracle(unsigned d) {
  Big x = 1 + Big(1) / d;  // right of the root ≈ 1 + ln 2 / d: Newton converges monotonically (f convex)
  for (int step = 0; step < 400; ++step) {
    const Big power = boost::multiprecision::pow(x, d);  // x^d
    const Big f = power * x - x - 1, slope = (d + 1) * power - 1;
    x -= f / slope;
  }
  return x;
}

// frac(offset + i·φ_d^-(k+1)) in 166-bit arithmetic.
Big coordinate_oracle(unsigned d, unsigned k, std::uint64_t i, double offset = 0) {
  const Big alpha = 1 / boost::multiprecision::pow(golden_ratio_oracle(d), k + 1);
  const Big x = Big(offset) + Big(i) * alpha;
  return x - boost::multiprecision::floor(x);
}

TEST(Kronecker, GeneralizedGoldenRatiosAreTheClosedForms) {
  EXPECT_DOUBLE_EQ(Kronecker::generalized_golden_ratio(1), (1 + std::sqrt(5.0)) / 2);
  // The plastic number: cbrt((9 + √69)/18) + cbrt((9 − √69)/18).
  const double plastic = std::cbrt((9 + std::sqrt(69.0)) / 18) + std::cbrt((9 - std::sqrt(69.0)) / 18);
  EXPECT_NEAR(Kronecker::generalized_golden_ratio(2), plastic, 4e-16);
  for (unsigned d : {3u, 7u, 64u, 4096u}) {
    const double phi = Kronecker::generalized_golden_ratio(d);
    EXPECT_NEAR(std::pow(phi, d + 1), phi + 1, 1e-14 * d) << d;
    EXPECT_NEAR(phi, static_cast<double>(golden_ratio_oracle(d)), 4e-16) << d;
  }
}

// Roberts 2018's R_2: α = (1/ρ, 1/ρ²), ρ the plastic number, whose decimal
// expansions he gives as 0.7548776662466927… and 0.5698402909980532….
TEST(Kronecker, RdFirstPointIsAlpha) {
  const Kronecker r2(2);
  EXPECT_EQ(r2.sample(0, 0), 0.0);
  EXPECT_NEAR(r2.sample(1, 0), 0.7548776662466927, 2e-16);
  EXPECT_NEAR(r2.sample(1, 1), 0.5698402909980532, 2e-16);
  const Kronecker r1(1, 0.5);
  EXPECT_NEAR(r1.sample(1, 0), 0.5 + 0.6180339887498949 - 1, 2e-16);
}

// The fixed-point phase is frac(s + i α) within i·d·2^-127 for every 64-bit
// index; the double is its truncation to 53 bits. Checked against the
// 166-bit oracle, at small indices and near 2^40, 2^53 and 2^64 (where a
// double-precision i·α would have lost 40, 53 and all its bits).
TEST(Kronecker, MatchesTheHighPrecisionOracleAtLargeIndices) {
  const double offset = 0.3;
  for (unsigned d : {1u, 2u, 5u}) {
    const Kronecker sequence(d, offset);
    for (std::uint64_t i : {std::uint64_t{1}, std::uint64_t{12345}, (std::uint64_t{1} << 40) + 12345,
                            (std::uint64_t{1} << 40) - 1, (std::uint64_t{1} << 53) + 7, ~std::uint64_t{0} - 99}) {
      for (unsigned k = 0; k < d; ++k) {
        const Big exact = coordinate_oracle(d, k, i, offset);
        const Big top64 = boost::multiprecision::ldexp(exact, 64);
        const auto high = static_cast<std::uint64_t>(sequence.phase(i, k) >> 64);
        const Big difference = boost::multiprecision::abs(Big(high) - top64);
        EXPECT_LT(difference, 4) << "d " << d << " k " << k << " i " << i;
        const double x = sequence.sample(i, k);
        EXPECT_LT(std::fabs(x - static_cast<double>(exact)), 0x1.0p-53 + 0x1.0p-60) << "d " << d << " i " << i;
        EXPECT_LT(x, 1.0);
        EXPECT_LT(sequence.sample<float>(i, k), 1.0f);
      }
    }
  }
}

// Three-gap theorem (Sós 1958; Świerczkowski 1958): for any α and N, the
// points frac(i α), i < N, cut the circle into arcs of at most three
// lengths, and when there are three the largest is the sum of the others.
// It holds on the 2^128 circle of the phases exactly (they are i·A mod
// 2^128), so the gaps are compared as integers.
void expect_three_gaps(const Kronecker& sequence, unsigned dim, std::uint64_t n) {
  std::vector<u128> phases(n);
  for (std::uint64_t i = 0; i < n; ++i) phases[i] = sequence.phase(i, dim);
  std::sort(phases.begin(), phases.end());
  std::set<u128> gaps;
  for (std::uint64_t i = 0; i + 1 < n; ++i) gaps.insert(phases[i + 1] - phases[i]);
  gaps.insert(phases[0] - phases[n - 1]);  // the arc through 0, modulo 2^128
  ASSERT_LE(gaps.size(), 3u) << "dim " << dim << " n " << n;
  if (gaps.size() == 3) {
    const std::vector<u128> g(gaps.begin(), gaps.end());
    EXPECT_TRUE(g[2] == g[0] + g[1]) << "dim " << dim << " n " << n;
  }
}

TEST(Kronecker, ThreeGapTheoremForR1R2AndAUserAlpha) {
  const Kronecker r1(1), r2(2);
  const std::vector<double> user = {std::sqrt(2.0) - 1, std::sqrt(3.0) - 1, M_PI - 3};
  const Kronecker weyl(user);
  for (std::uint64_t n = 2; n <= 400; ++n) {
    expect_three_gaps(r1, 0, n);
    expect_three_gaps(r2, 0, n);
    expect_three_gaps(r2, 1, n);
    expect_three_gaps(weyl, n % 3, n);
  }
  for (std::uint64_t n : {987, 1000, 4181, 10000}) {
    expect_three_gaps(r1, 0, n);
    expect_three_gaps(r2, 1, n);
  }
  // For Fibonacci n, R_1's gaps take only two lengths (n = F_k).
  std::vector<u128> phases;
  for (std::uint64_t i = 0; i < 987; ++i) phases.push_back(r1.phase(i, 0));
  std::sort(phases.begin(), phases.end());
  std::set<u128> gaps = {phases[0] - phases.back()};
  for (std::size_t i = 0; i + 1 < phases.size(); ++i) gaps.insert(phases[i + 1] - phases[i]);
  EXPECT_EQ(gaps.size(), 2u);
}

TEST(Kronecker, UserAlphaIsUsedAsGiven) {
  const std::vector<double> alpha = {0.25, std::sqrt(2.0) - 1};
  const Kronecker sequence(alpha, 0.125);
  EXPECT_EQ(sequence.dimensions(), 2u);
  EXPECT_EQ(sequence.alpha(1), std::sqrt(2.0) - 1);
  EXPECT_EQ(sequence.sample(3, 0), 0.875);
  EXPECT_EQ(sequence.sample(4, 0), 0.125);  // 0.125 + 1, modulo 1
  // A dyadic α has an exact sequence: compare i α mod 1 in integers.
  const double a = 0x1.6a09e667f3bcdp-2;  // (√2 − 1) rounded: 53 bits below 2^-1
  const auto numerator = static_cast<std::uint64_t>(std::ldexp(a, 54));
  const Kronecker dyadic(std::vector<double>{a});
  for (std::uint64_t i : {std::uint64_t{3}, std::uint64_t{1} << 40, (std::uint64_t{1} << 62) + 5}) {
    const std::uint64_t exact54 = (numerator * i) & ((std::uint64_t{1} << 54) - 1);  // i α mod 1, times 2^54
    EXPECT_EQ(dyadic.sample(i, 0), std::ldexp(static_cast<double>(exact54 >> 1), -53)) << i;
  }
}

TEST(Kronecker, RejectsBadArguments) {
  EXPECT_THROW(Kronecker(0u), invalid_argument);
  EXPECT_THROW(Kronecker(Kronecker::max_dimensions + 1), invalid_argument);
  EXPECT_THROW(Kronecker(2u, 1.0), invalid_argument);
  EXPECT_THROW(Kronecker(2u, -0.1), invalid_argument);
  for (const std::vector<double>& bad :
       std::vector<std::vector<double>>{{}, {0.5, 0.0}, {1.0}, {-0.2}, {std::nan("")}, {0x1.0p-140}}) {
    try {
      Kronecker sequence(bad);
      FAIL() << "accepted " << bad.size() << " entries";
    } catch (const invalid_argument& e) {
      EXPECT_EQ(e.argument(), "alpha");
    }
  }
}

// R_2 against independent uniform points in the analysis measures: its L2
// star discrepancy² is far below the mean of random points', (2^-d − 3^-d)/n
// (Warnock's formula averaged; measured: 72 times below at n = 1024), and
// its star discrepancy far below that of each of 8 random sets.
TEST(Kronecker, DiscrepancyFarBelowRandom) {
  const std::size_t n = 1024;
  const Kronecker r2(2);
  std::vector<double> points(2 * n), random(2 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (unsigned k = 0; k < 2; ++k) points[2 * i + k] = r2.sample(i, k);
  const analysis::PointView view{points.data(), n, 2};
  const double l2 = analysis::l2_discrepancy_squared(analysis::L2Kind::star, view);
  const double random_mean_l2 = (0.25 - 1.0 / 9) / static_cast<double>(n);
  EXPECT_LT(l2, random_mean_l2 / 50) << l2;
  const double star = analysis::star_discrepancy_2d(view);
  EXPECT_LT(star, 3 * std::log(static_cast<double>(n)) / static_cast<double>(n)) << star;
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    for (std::size_t i = 0; i < 2 * n; ++i) random[i] = uniform01<double>(seed, i);
    EXPECT_LT(4 * star, analysis::star_discrepancy_2d(analysis::PointView{random.data(), n, 2})) << seed;
  }
}

// ---- The registry's kronecker ----

PointSet registry_points(std::uint64_t n, unsigned d, const std::string& randomize, std::uint64_t seed,
                         std::map<std::string, std::string> params = {}, std::uint64_t start = 0) {
  return testing::sampler_points("kronecker", n, d, randomize, seed, start, std::move(params));
}

TEST(KroneckerRegistry, IsTheHeadersSequenceFromStartWithCranleyPatterson) {
  const SamplerInfo& info = find_sampler("kronecker");
  EXPECT_EQ(info.randomizers, (std::vector<std::string>{"none", "cp"}));
  const Kronecker r3(3);
  const PointSet plain = registry_points(40, 3, "none", 7, {}, 1000);
  const PointSet rotated = registry_points(40, 3, "cp", 7, {}, 1000);
  for (std::size_t i = 0; i < 40; ++i)
    for (unsigned k = 0; k < 3; ++k) {
      ASSERT_EQ(plain(i, k), r3.sample(1000 + i, k));
      // A rotation modulo 1: the differences to the unrotated points agree.
      const double shift = rotated(i, k) - plain(i, k);
      const double first = rotated(0, k) - plain(0, k);
      EXPECT_NEAR(shift - std::floor(shift), first - std::floor(first), 1e-15);
    }
  const PointSet user = registry_points(4, 2, "none", 0, {{"alpha", "0.25,0.5"}, {"offset", "0.125"}});
  EXPECT_EQ(user(3, 0), 0.875);
  EXPECT_EQ(user(3, 1), 0.625);
}

TEST(KroneckerRegistry, RejectsBadParameters) {
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"alpha", "0.5"}, {"alpha", "0.5,1.5"}, {"alpha", "0.5,x"}, {"offset", "1"}, {"offset", "abc"}}) {
    try {
      registry_points(4, 2, "none", 0, {{key, value}});
      FAIL() << key << "=" << value;
    } catch (const invalid_argument& e) {
      EXPECT_EQ(e.argument().rfind(key, 0), 0u) << e.argument() << " for " << value;  // alpha or alpha[1]
    }
  }
}

// Unbiasedness of cp: over seeds, the mean of Q = (1/64) Σ f(x_k) with
// f = x0 · x1² · exp(x2), ∫f = (e − 1)/6, matches the integral: 400 seeds,
// a two-sided t-test at α = 1e-3 on the seeds' sample variance.
TEST(KroneckerRegistry, CranleyPattersonEstimatesAreUnbiased) {
  std::vector<double> estimates;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    const PointSet p = registry_points(64, 3, "cp", seed + 500);
    estimates.push_back(testing::product_test_mean(p.data.get(), p.n, p.d));
  }
  testing::expect_unbiased("kronecker:cp", estimates, testing::product_test_integral(), 1e-3);
}

}  // namespace
}  // namespace stratum
