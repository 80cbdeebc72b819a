#include "stratum/analysis/geometry.hpp"

#include <gtest/gtest.h>

#include "../registry/error_of.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "stratum/analysis/measures.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

PointSet points_of(const std::string& sampler, std::size_t n, unsigned d, std::uint64_t seed = 1) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  return generate_points(sampler, request);
}

PointView view(const PointSet& points) { return {points.data.get(), points.n, points.d}; }

using testing::error_of;

// The grid search against all pairs, Euclidean and toroidal, d = 1..9 (9:
// the all-pairs fallback), for random, blue-noise and clustered sets.
TEST(Geometry, MinimumDistanceMatchesAllPairs) {
  for (unsigned d : {1u, 2u, 3u, 5u, 9u})
    for (const std::string sampler : {"random", "poisson-disk", "best-candidate"}) {
      if (sampler != "random" && d > 3) continue;
      for (std::uint64_t seed = 0; seed < 3; ++seed) {
        PointSet points = points_of(sampler, 400, d, seed);
        if (seed == 2)  // squeeze half the points into a small corner box
          for (std::size_t i = 0; i < points.n / 2; ++i)
            for (std::size_t j = 0; j < d; ++j) points.data[i * d + j] *= 0.01;
        for (bool toroidal : {false, true}) {
          const MinimumDistance fast = minimum_distance(view(points), toroidal);
          const MinimumDistance slow = minimum_distance_reference(view(points), toroidal);
          ASSERT_DOUBLE_EQ(fast.distance, slow.distance) << sampler << " d " << d << " seed " << seed;
          // The reported pair is at that distance.
          double d2 = 0;
          for (std::size_t j = 0; j < d; ++j) {
            double delta = std::abs(points(fast.first, j) - points(fast.second, j));
            if (toroidal) delta = std::min(delta, 1 - delta);
            d2 += delta * delta;
          }
          EXPECT_DOUBLE_EQ(std::sqrt(d2), fast.distance);
          EXPECT_LT(fast.first, fast.second);
        }
      }
    }
}

TEST(Geometry, MinimumDistanceClosedForms) {
  // Across the seam: toroidal 0.02, Euclidean 0.49.
  const std::vector<double> seam = {0.01, 0.5, 0.99, 0.5, 0.5, 0.5};
  EXPECT_NEAR(minimum_distance({seam.data(), 3, 2}, true).distance, 0.02, 1e-15);
  EXPECT_NEAR(minimum_distance({seam.data(), 3, 2}, false).distance, 0.49, 1e-15);
  // m×m grid of centres: 1/m both ways; ρ = (1/m)/sqrt(2/(√3 m²)) = sqrt(√3/2).
  const PointSet grid = points_of("grid", 49, 2);
  EXPECT_NEAR(minimum_distance(view(grid), false).distance, 1.0 / 7, 1e-15);
  EXPECT_NEAR(poisson_radius(view(grid), true), std::sqrt(std::sqrt(3.0) / 2), 1e-14);
  // Duplicates: 0.
  const std::vector<double> twice = {0.3, 0.4, 0.7, 0.1, 0.3, 0.4};
  const MinimumDistance zero = minimum_distance({twice.data(), 3, 2}, false);
  EXPECT_EQ(zero.distance, 0.0);
  EXPECT_EQ(zero.first, 0u);
  EXPECT_EQ(zero.second, 2u);
}

// Densest packings: 1D spacing 1/N; 2D hexagonal sqrt(2/(√3 N)) (Lagae &
// Dutré 2008); 3D fcc, cell volume a³/√2 per point; 8D E8, density π⁴/384.
TEST(Geometry, DensestPackingDistance) {
  EXPECT_NEAR(densest_packing_distance(10, 1), 0.1, 1e-15);
  EXPECT_NEAR(densest_packing_distance(1000, 2), std::sqrt(2 / (std::sqrt(3.0) * 1000)), 1e-15);
  EXPECT_NEAR(densest_packing_distance(500, 3), std::cbrt(std::sqrt(2.0) / 500), 1e-15);
  // E8 at N = 1 per unit volume: minimal vectors of length √2 with one point per unit volume.
  EXPECT_NEAR(densest_packing_distance(1, 8), std::sqrt(2.0), 1e-13);
  EXPECT_NE(error_of([] { densest_packing_distance(10, 9); }).find("invalid d = 9"), std::string::npos);
}

// Two points at toroidal distance s: g(r) = 2 k_σ(r − s) / (N(N−1) 2πr).
// What a uniform random set puts under the kernel at radius r, per ordered
// pair, by Simpson's rule on the distance t (an oracle for the closed form in
// geometry.cpp): ∫ k_σ(r − t) S_{d−1} t^{d−1} dt over t ≥ 0, |r − t| < 4σ.
double kernel_shell_by_quadrature(double r, double sigma, std::size_t d) {
  const double sphere = d == 1 ? 2.0 : d == 2 ? 2 * std::numbers::pi : 4 * std::numbers::pi;
  const double low = std::max(0.0, r - 4 * sigma), high = r + 4 * sigma;
  const int steps = 20000;
  const double h = (high - low) / steps;
  double sum = 0;
  for (int i = 0; i <= steps; ++i) {
    const double t = low + h * i, u = (r - t) / sigma;
    const double f = std::exp(-0.5 * u * u) / (std::sqrt(2 * std::numbers::pi) * sigma) * sphere *
                     std::pow(t, static_cast<double>(d) - 1.0);
    sum += f * (i == 0 || i == steps ? 1 : i % 2 ? 4 : 2);
  }
  return sum * h / 3;
}

TEST(Geometry, PairCorrelationOfTwoPoints) {
  const double sigma = 0.01;
  const std::vector<double> radii = {0.004, 0.02, 0.12, 0.14, 0.15, 0.16, 0.2};
  for (std::size_t d : {1u, 2u, 3u}) {
    // Two points at toroidal distance 0.15 along the first axis.
    std::vector<double> pair(2 * d, 0.2);
    pair[0] = 0.1, pair[d] = 0.95;
    const PairCorrelation g = pair_correlation({pair.data(), 2, d}, radii, sigma, 1);
    for (std::size_t k = 0; k < radii.size(); ++k) {
      const double u = (radii[k] - 0.15) / sigma;
      const double kernel = std::abs(u) < 4 ? std::exp(-0.5 * u * u) / (std::sqrt(2 * std::numbers::pi) * sigma) : 0.0;
      const double expected = 2 * kernel / (2.0 * kernel_shell_by_quadrature(radii[k], sigma, d));
      EXPECT_NEAR(g.g[k], expected, 1e-9 * std::max(1.0, expected)) << "d " << d << " r " << radii[k];
    }
  }
}

// A uniform random set: E g(r) = 1 exactly at every radius (binomial process
// on the torus, N(N−1) normalization, the denominator what such a set puts
// under the kernel), also at radii of a fraction of σ, where the sphere-area
// normalization of Öztireli & Gross read 2.15 at r = σ/4. Each estimate's sd is
// ≈ 0.016 (12 seeds of the same setting, brute force with scipy's cKDTree);
// 0.1 is 6 sd (α ≈ 2e-9 each, 4 radii). Larger radii: 2000 points, sd ≲ 0.03,
// 0.15 is 5 sd (α ≈ 6e-7 each, 5 radii).
TEST(Geometry, PairCorrelationOfRandomSetIsOne) {
  const PointSet white = points_of("random", 4000, 2, 5);
  const double sigma = 0.005;
  const std::vector<double> small = {sigma / 4, sigma / 2, sigma, 2 * sigma};
  const PairCorrelation near_zero = pair_correlation(view(white), small, sigma, 2);
  for (std::size_t k = 0; k < small.size(); ++k) EXPECT_NEAR(near_zero.g[k], 1.0, 0.1) << small[k];
  const PointSet random = points_of("random", 2000, 2, 11);
  const std::vector<double> radii = {0.02, 0.04, 0.06, 0.08, 0.1};
  const PairCorrelation g = pair_correlation(view(random), radii, 0.002, 2);
  for (std::size_t k = 0; k < radii.size(); ++k) EXPECT_NEAR(g.g[k], 1.0, 0.15) << radii[k];
  // Same numbers for any thread count.
  EXPECT_EQ(pair_correlation(view(random), radii, 0.002, 1).g, g.g);
  // Poisson disk: no pair closer than its radius, so g ≈ 0 well below it.
  const PointSet disk = points_of("poisson-disk", 1000, 2, 3);
  const double dmin = minimum_distance(view(disk), true).distance;
  const PairCorrelation h = pair_correlation(view(disk), {0.5 * dmin}, 0.05 * dmin, 1);
  EXPECT_LT(h.g[0], 1e-6);
}

TEST(Geometry, MeasuresAndBadInput) {
  const PointSet grid = points_of("grid", 64, 2);
  EXPECT_NEAR(compute_measure("min-distance", view(grid), {}).value, 0.125, 1e-15);
  const MeasureResult rho = compute_measure("poisson-radius", view(grid), {});
  EXPECT_NEAR(rho.value, std::sqrt(std::sqrt(3.0) / 2), 1e-14);
  EXPECT_NEAR(rho.extras.at("packing_distance"), std::sqrt(2 / (std::sqrt(3.0) * 64)), 1e-15);
  EXPECT_NE(error_of([&] {
              compute_measure("min-distance", view(grid), {{{"toroidal", "maybe"}}, 1});
            }).find("invalid toroidal = maybe"),
            std::string::npos);
  const PointSet nine = points_of("random", 20, 9);
  EXPECT_NE(error_of([&] { compute_measure("poisson-radius", view(nine), {}); }).find("invalid d = 9"),
            std::string::npos);
  const PointSet random = points_of("random", 100, 2);
  EXPECT_NE(error_of([&] { pair_correlation(view(random), {0.1}, 0, 1); }).find("invalid sigma = 0"),
            std::string::npos);
  EXPECT_NE(error_of([&] { pair_correlation(view(random), {0.45}, 0.02, 1); }).find("invalid radius = 0.45"),
            std::string::npos);
  EXPECT_NE(error_of([&] { pair_correlation(view(random), {-0.1}, 0.02, 1); }).find("invalid radius = -0.1"),
            std::string::npos);
  const std::vector<double> one = {0.5, 0.5};
  EXPECT_NE(error_of([&] { minimum_distance({one.data(), 1, 2}, false); }).find("invalid n = 1"), std::string::npos);
}

}  // namespace
}  // namespace stratum::analysis
