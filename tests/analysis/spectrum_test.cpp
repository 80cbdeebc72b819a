#include "stratum/analysis/spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

PointSet random_points(std::size_t n, unsigned d, std::uint64_t seed) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  return generate_points("random", request);
}

PointView view(const PointSet& points) { return {points.data.get(), points.n, points.d}; }

/// m×m grid of cell centres (i + 1/2)/m.
std::vector<double> grid_points(std::size_t m) {
  std::vector<double> xy;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      xy.push_back((static_cast<double>(i) + 0.5) / static_cast<double>(m));
      xy.push_back((static_cast<double>(j) + 0.5) / static_cast<double>(m));
    }
  return xy;
}

std::string error_of(const std::vector<PointView>& realizations, int max_frequency) {
  try {
    mean_periodogram(realizations, max_frequency, 1);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

// The recurrence with re-anchoring against one std::exp per term
// (std::complex), in 1D and 2D, one and several realizations, and with K
// much larger than the re-anchoring interval: agreement to 1e-9 of
// max(P, 1) (P is O(1) for these sets; its absolute error is a few N·ε).
TEST(Spectrum, FastRecurrenceMatchesBruteForce) {
  struct Case {
    std::size_t n;
    unsigned d;
    int k;
    std::size_t realizations;
  };
  for (const Case c :
       {Case{50, 2, 12, 1}, Case{37, 2, 9, 3}, Case{20, 2, 70, 1}, Case{64, 1, 300, 2}, Case{5, 1, 3, 1}}) {
    std::vector<PointSet> sets;
    std::vector<PointView> views;
    for (std::size_t r = 0; r < c.realizations; ++r) sets.push_back(random_points(c.n, c.d, 100 + r));
    for (const auto& s : sets) views.push_back(view(s));
    const Periodogram fast = mean_periodogram(views, c.k, 2);
    const Periodogram slow = mean_periodogram_reference(views, c.k);
    ASSERT_EQ(fast.power.size(), slow.power.size());
    ASSERT_EQ(fast.power.size(), c.d == 1 ? std::size_t(2 * c.k + 1) : std::size_t((2 * c.k + 1) * (2 * c.k + 1)));
    for (std::size_t i = 0; i < fast.power.size(); ++i)
      ASSERT_NEAR(fast.power[i], slow.power[i], 1e-9 * std::max(1.0, slow.power[i])) << "n " << c.n << " index " << i;
    // P(0) = |N|²/N = N exactly up to rounding.
    EXPECT_NEAR(fast.at(0, 0), static_cast<double>(c.n), 1e-12 * static_cast<double>(c.n));
  }
}

TEST(Spectrum, SameBitsForAnyThreadCount) {
  const PointSet points = random_points(300, 2, 7);
  const Periodogram one = mean_periodogram({view(points)}, 40, 1);
  for (unsigned threads : {2u, 3u, 0u}) {
    const Periodogram many = mean_periodogram({view(points)}, 40, threads);
    ASSERT_EQ(one.power, many.power) << threads << " threads";
  }
}

// A uniform random set has E[P(k)] = 1 for every integer k ≠ 0 and, for
// k ≠ ±l, Cov(P(k), P(l)) = 0 (the fourth moment sum has no cross terms), with
// Var P(k) = 1 − 1/N. The mean over the h = ((2K+1)²−1)/2 distinct frequencies
// of R independent realizations has sd sqrt((1 − 1/N)/(hR)); by the CLT the
// test |mean − 1| ≤ 4.89 sd has significance α = 1e-6.
TEST(Spectrum, UniformRandomSetAveragesOneAwayFromZero) {
  const std::size_t n = 64, realizations = 20;
  const int k = 16;
  std::vector<PointSet> sets;
  std::vector<PointView> views;
  for (std::size_t r = 0; r < realizations; ++r) sets.push_back(random_points(n, 2, 1000 + r));
  for (const auto& s : sets) views.push_back(view(s));
  const Periodogram mean = mean_periodogram(views, k, 2);
  double sum = 0;
  std::size_t count = 0;
  for (int ky = 0; ky <= k; ++ky)
    for (int kx = (ky == 0 ? 1 : -k); kx <= k; ++kx) {
      sum += mean.at(kx, ky);
      ++count;
    }
  ASSERT_EQ(count, std::size_t(((2 * k + 1) * (2 * k + 1) - 1) / 2));
  const double sd = std::sqrt((1.0 - 1.0 / n) / static_cast<double>(count * realizations));
  EXPECT_NEAR(sum / static_cast<double>(count), 1.0, 4.89 * sd);
  EXPECT_DOUBLE_EQ(mean.at(0, 0), static_cast<double>(n));

  // Anisotropy: ring values are ~ Gamma(R, 1/R), so s²/P̄² ≈ (1 − 1/N)/R:
  // −10·log10(20·64/63) = −13.08 dB. Averaged over the rings 6..16 (≈ 550
  // distinct values, Gamma kurtosis 6/R) the linear ratio has relative sd
  // ≈ sqrt((2 + 6/R)/550) ≈ 0.063, i.e. 0.27 dB; 1.5 dB is over 5 sd.
  const RadialPower radial = radial_average(mean);
  double ratio = 0;
  int rings = 0;
  for (std::size_t r = 5; r < radial.power.size(); ++r) {
    ratio += std::pow(10.0, radial.anisotropy_db[r] / 10.0);
    ++rings;
  }
  EXPECT_NEAR(10.0 * std::log10(ratio / rings), -10.0 * std::log10(realizations * n / (n - 1.0)), 1.5);
}

// m×m grid of cell centres: the 1D sums Σ_i exp(−2πi k (i+½)/m) are
// m·(−1)^{k/m} when m divides k and 0 otherwise, so P(k) = N = m² exactly at
// multiples of √N = m in both coordinates and 0 elsewhere. Its zero region
// ends at ring m, so ν_eff = (m − 1)/2 normalized by m.
TEST(Spectrum, RegularGridHasPeaksOnlyAtMultiplesOfSqrtN) {
  const std::size_t m = 8;
  const int k = 20;
  const std::vector<double> xy = grid_points(m);
  const Periodogram p = mean_periodogram({PointView{xy.data(), m * m, 2}}, k, 1);
  const double n = static_cast<double>(m * m);
  for (int ky = -k; ky <= k; ++ky)
    for (int kx = -k; kx <= k; ++kx) {
      const bool peak = kx % static_cast<int>(m) == 0 && ky % static_cast<int>(m) == 0;
      ASSERT_NEAR(p.at(kx, ky), peak ? n : 0.0, 1e-9 * n) << kx << "," << ky;
    }
  const RadialPower radial = radial_average(p);
  ASSERT_EQ(radial.power.size(), std::size_t(k));
  EXPECT_DOUBLE_EQ(radial.frequency[m - 1], 1.0);  // ring m at 1 in units of √N
  EXPECT_NEAR(radial.power[m - 2], 0.0, 1e-9);
  EXPECT_GT(radial.power[m - 1], 1.0);  // the four peaks of ring m
  const BlueNoiseFigures figures = blue_noise_figures(radial);
  EXPECT_DOUBLE_EQ(figures.effective_nyquist, (m - 1.0) / (2.0 * m));
  EXPECT_FALSE(figures.nyquist_is_lower_bound);

  // 1D: N equally spaced points have P(k) = N at multiples of N, else 0.
  std::vector<double> x;
  for (int i = 0; i < 10; ++i) x.push_back((i + 0.5) / 10);
  const Periodogram q = mean_periodogram({PointView{x.data(), 10, 1}}, 25, 1);
  for (int kx = -25; kx <= 25; ++kx) ASSERT_NEAR(q.at(kx), kx % 10 == 0 ? 10.0 : 0.0, 1e-9) << kx;
}

// A random set has no zero region (ν_eff = 0) and its radial power reaches 1
// at once; a jittered set's power near 0 is small (P(k) ≈ 1 − sinc² of the
// cell), so its zero region is wider.
TEST(Spectrum, BlueNoiseFiguresOrderPatterns) {
  const std::size_t n = 256;
  std::vector<PointSet> random_sets, jittered_sets;
  std::vector<PointView> random_views, jittered_views;
  for (std::uint64_t r = 0; r < 8; ++r) {
    random_sets.push_back(random_points(n, 2, 50 + r));
    SamplerRequest request;
    request.n = n;
    request.d = 2;
    request.seed = 50 + r;
    jittered_sets.push_back(generate_points("jittered", request));
  }
  for (const auto& s : random_sets) random_views.push_back(view(s));
  for (const auto& s : jittered_sets) jittered_views.push_back(view(s));
  const BlueNoiseFigures random = blue_noise_figures(radial_average(mean_periodogram(random_views, 48, 2)));
  const BlueNoiseFigures jittered = blue_noise_figures(radial_average(mean_periodogram(jittered_views, 48, 2)));
  EXPECT_EQ(random.effective_nyquist, 0.0);
  EXPECT_GT(jittered.effective_nyquist, 0.05);
  EXPECT_LT(jittered.effective_nyquist, 0.5);  // below a regular grid's
  EXPECT_TRUE(std::isfinite(random.oscillation));
}

TEST(Spectrum, BadInputIsNamed) {
  const PointSet points = random_points(10, 2, 1);
  const PointSet points3 = random_points(10, 3, 1);
  const PointSet fewer = random_points(9, 2, 1);
  EXPECT_NE(error_of({view(points)}, 0).find("invalid max_frequency = 0"), std::string::npos);
  EXPECT_NE(error_of({view(points)}, -3).find("invalid max_frequency = -3"), std::string::npos);
  EXPECT_NE(error_of({view(points)}, 5000).find("at most 2^25"), std::string::npos);
  EXPECT_NE(error_of({view(points3)}, 4).find("invalid d = 3"), std::string::npos);
  EXPECT_NE(error_of({view(points), view(fewer)}, 4).find("invalid n of realization 1 = 9"), std::string::npos);
  EXPECT_NE(error_of({}, 4).find("invalid realizations"), std::string::npos);
  std::vector<double> bad = {0.1, 0.2, std::numeric_limits<double>::quiet_NaN(), 0.5};
  EXPECT_NE(error_of({PointView{bad.data(), 2, 2}}, 4).find("point[1][0]"), std::string::npos);
  std::vector<double> outside = {0.1, 0.2, 0.3, 1.5};
  EXPECT_NE(error_of({PointView{outside.data(), 2, 2}}, 4).find("point[1][1]"), std::string::npos);
}

}  // namespace
}  // namespace stratum::analysis
