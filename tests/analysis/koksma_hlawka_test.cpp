// Tests of the Koksma–Hlawka test functions and check (koksma_hlawka.hpp).
// Oracles: Gauss–Legendre quadrature (Boost.Math) for the integrals; for the
// Hardy–Krause variation, its definition evaluated on a fine grid (the sums
// of |quasi-differences| over a partition converge to the variation from
// below for continuous f), independent of the product formula; the exact
// star discrepancy for the inequality itself.
#include "stratum/analysis/koksma_hlawka.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

double quadrature_2d(double (*f)(double, double)) {
  using boost::math::quadrature::gauss;
  return gauss<double, 30>::integrate(
      [&](double x) { return gauss<double, 30>::integrate([&](double y) { return f(x, y); }, 0.0, 1.0); }, 0.0, 1.0);
}

/// V_HK anchored at 1 on an m×m grid: the Vitali sum plus the 1D variation
/// sums along the faces y = 1 and x = 1 (Owen 2005, eq. (9)–(12)).
double grid_variation(double (*f)(double, double), int m) {
  std::vector<double> values((m + 1) * (m + 1));
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) values[j * (m + 1) + i] = f(static_cast<double>(i) / m, static_cast<double>(j) / m);
  const auto at = [&](int i, int j) { return values[j * (m + 1) + i]; };
  double vitali = 0, face_x = 0, face_y = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) vitali += std::fabs(at(i + 1, j + 1) - at(i, j + 1) - at(i + 1, j) + at(i, j));
  for (int i = 0; i < m; ++i) face_x += std::fabs(at(i + 1, m) - at(i, m));
  for (int j = 0; j < m; ++j) face_y += std::fabs(at(m, j + 1) - at(m, j));
  return vitali + face_x + face_y;
}

TEST(KoksmaHlawka, IntegralsMatchQuadrature) {
  for (const auto& function : variation_test_functions())
    EXPECT_NEAR(function.integral, quadrature_2d(function.f), 1e-13) << function.name;
}

TEST(KoksmaHlawka, VariationsMatchTheDefinitionOnAFineGrid) {
  for (const auto& function : variation_test_functions()) {
    const double grid = grid_variation(function.f, 1500);
    // A lower bound that converges like O(1/m) for smooth f; 1e-3 relative
    // is far below any error in a wrong closed form (e.g. a missing face term).
    // Lower bound up to the rounding of a 2.25·10⁶-term sum (≈ 10⁻¹⁰ relative).
    EXPECT_LE(grid, function.variation * (1 + 1e-9)) << function.name;
    EXPECT_NEAR(grid, function.variation, 1e-3 * function.variation) << function.name;
  }
}

TEST(KoksmaHlawka, ProductFormulaByHand) {
  // x·y: Vitali 1, faces 1 and 1.
  EXPECT_DOUBLE_EQ(product_variation(1, 1, 1, 1), 3);
  // g = 1 − x (V 1, g(1) = 0), h = y: Vitali 1, face y = 1: V(g)·1 = 1, face x = 1: 0.
  EXPECT_DOUBLE_EQ(product_variation(1, 0, 1, 1), 2);
  EXPECT_DOUBLE_EQ(product_variation(2, -3, 0, 5), 10);  // constant h: only the face y = 1 varies
}

TEST(KoksmaHlawka, InequalityHoldsWithTheExactStarDiscrepancy) {
  for (const auto& [sampler, randomize] :
       {std::pair<std::string, std::string>{"random", ""}, {"jittered", ""}, {"hammersley", "none"}, {"sobol", "owen"}})
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SamplerRequest request;
      request.n = 64;
      request.d = 2;
      request.seed = seed;
      request.randomize = randomize;
      const PointSet points = generate_points(sampler, request);
      const PointView view{points.data.get(), points.n, 2};
      const double star = star_discrepancy_2d(view);
      const auto checks = koksma_hlawka_checks(view, star);
      ASSERT_EQ(checks.size(), variation_test_functions().size());
      for (std::size_t k = 0; k < checks.size(); ++k) {
        const auto& function = variation_test_functions()[k];
        double sum = 0;
        for (std::size_t i = 0; i < 64; ++i) sum += function.f(points(i, 0), points(i, 1));
        EXPECT_NEAR(checks[k].estimate, sum / 64, 1e-13);
        EXPECT_NEAR(checks[k].error, std::fabs(sum / 64 - function.integral), 1e-13);
        EXPECT_DOUBLE_EQ(checks[k].bound, function.variation * star);
        EXPECT_TRUE(checks[k].holds) << sampler << " " << seed << " " << function.name;
      }
      // With a discrepancy too small the same errors break the bound.
      for (const auto& check : koksma_hlawka_checks(view, 0.0)) EXPECT_EQ(check.holds, check.error <= 1e-12);
    }
}

TEST(KoksmaHlawka, TwoPointsAtTheOriginByHand) {
  // Both points at the origin: f = x·y gives estimate 0, error 1/4; D* = 1
  // (the closed box at (0, 0) holds both points, volume 0), bound V·D* = 3.
  const double origin[4] = {0, 0, 0, 0};
  const auto checks = koksma_hlawka_checks({origin, 2, 2}, star_discrepancy_2d({origin, 2, 2}));
  EXPECT_EQ(checks[0].function, "xy");
  EXPECT_DOUBLE_EQ(checks[0].error, 0.25);
  EXPECT_DOUBLE_EQ(checks[0].bound, 3.0);
  EXPECT_TRUE(checks[0].holds);
}

TEST(KoksmaHlawka, RejectsBadInput) {
  const double xyz[3] = {0.1, 0.2, 0.3};
  EXPECT_THROW(koksma_hlawka_checks({xyz, 1, 3}, 0.1), invalid_argument);
  const double outside[4] = {0.1, 1.5, 0.2, 0.3};
  EXPECT_THROW(koksma_hlawka_checks({outside, 2, 2}, 0.1), invalid_argument);
  const double fine[4] = {0.1, 0.5, 0.2, 0.3};
  EXPECT_THROW(koksma_hlawka_checks({fine, 2, 2}, -0.1), invalid_argument);
  EXPECT_THROW(koksma_hlawka_checks({fine, 2, 2}, std::nan("")), invalid_argument);
}

}  // namespace
}  // namespace stratum::analysis
