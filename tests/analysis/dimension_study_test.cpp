/// Tests of the quadrature-versus-Monte-Carlo study (LECTURE.md §6).
/// Oracles: Gauss–Legendre's exactness on polynomials of degree < 2m per
/// axis, the midpoint sums' closed form for the sine product, the exact
/// Monte Carlo RMSE σ/√N (a χ² test of the measured mean squared error), and
/// the rule's theoretical order −2/d.
#include "stratum/analysis/dimension_study.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace sa = stratum::analysis;

namespace {

/// Product of per-axis polynomials of degree `degree` with coefficients
/// hashed from (seed, axis, power); returns f and its exact integral.
struct ProductPolynomial {
  unsigned d, degree;
  std::vector<double> coefficients;  // d × (degree + 1)
  ProductPolynomial(unsigned dim, unsigned deg, std::uint64_t seed) : d(dim), degree(deg) {
    for (unsigned j = 0; j < d; ++j)
      for (unsigned k = 0; k <= degree; ++k) coefficients.push_back(stratum::uniform01(seed, j, k) - 0.25);
  }
  double operator()(const double* x, unsigned) const {
    double product = 1;
    for (unsigned j = 0; j < d; ++j) {
      double value = 0;
      for (unsigned k = degree + 1; k-- > 0;) value = value * x[j] + coefficients[j * (degree + 1) + k];
      product *= value;
    }
    return product;
  }
  double exact() const {
    double product = 1;
    for (unsigned j = 0; j < d; ++j) {
      double value = 0;
      for (unsigned k = 0; k <= degree; ++k) value += coefficients[j * (degree + 1) + k] / (k + 1);
      product *= value;
    }
    return product;
  }
};

}  // namespace

TEST(DimensionStudy, RulesHaveUnitWeightAndNodesInside) {
  for (unsigned m : {1u, 2u, 7u, 64u, 256u}) {
    for (const char* name : {"midpoint", "gauss"}) {
      const auto rule = sa::product_rule_1d(name, m);
      ASSERT_EQ(rule.nodes.size(), m);
      EXPECT_NEAR(std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0), 1.0, 1e-13) << name << m;
      for (double x : rule.nodes) EXPECT_TRUE(x > 0 && x < 1) << name << m << " " << x;
    }
  }
}

// Gauss–Legendre with m points is exact for degree ≤ 2m − 1 in each variable
// (a tensor rule inherits it per axis) and not for degree 2m: the second
// assertion shows the first could fail.
TEST(DimensionStudy, GaussIsExactBelowDegree2mInEveryDimension) {
  for (unsigned d = 1; d <= 10; ++d) {
    for (unsigned m = 1; m <= 4; ++m) {
      if (std::pow(m, d) > 300000) continue;
      const auto rule = sa::gauss_legendre_rule(m);
      const ProductPolynomial exact_case(d, 2 * m - 1, 17 + d);
      const double q = sa::tensor_product_integral(std::cref(exact_case), d, rule, 2);
      EXPECT_NEAR(q, exact_case.exact(), 1e-12 * std::max(1.0, std::abs(exact_case.exact())))
          << "d=" << d << " m=" << m;
      // x_1^(2m): Gauss error is (m!)^4 / ((2m+1) ((2m)!)^3) · (2m)! ≠ 0 (on [0,1]).
      const auto monomial = [m](const double* x, unsigned) { return std::pow(x[0], 2.0 * m); };
      const double q2 = sa::tensor_product_integral(monomial, d, rule, 1);
      EXPECT_GT(std::abs(q2 - 1.0 / (2 * m + 1)), 1e-6) << "d=" << d << " m=" << m;
    }
  }
}

// The midpoint sum of (π/2) sin(πx) is π / (2m sin(π/(2m))) exactly (sum of
// sines in arithmetic progression), so the d-dimensional sum is its d-th power.
TEST(DimensionStudy, MidpointSumOfSineProductMatchesClosedForm) {
  for (unsigned d = 1; d <= 6; ++d) {
    const auto integrand = sa::dimension_integrand("sine-product", d);
    for (unsigned m : {1u, 2u, 3u, 5u, 8u}) {
      if (std::pow(m, d) > 300000) continue;
      const double closed = std::pow(std::numbers::pi / (2 * m * std::sin(std::numbers::pi / (2 * m))), d);
      const double q = sa::tensor_product_integral(integrand.f, d, sa::midpoint_rule(m), 2);
      EXPECT_NEAR(q, closed, 1e-13 * closed) << "d=" << d << " m=" << m;
    }
  }
}

TEST(DimensionStudy, TensorSumDoesNotDependOnThreads) {
  const auto integrand = sa::dimension_integrand("sine-product", 5);
  const auto rule = sa::gauss_legendre_rule(9);
  EXPECT_EQ(sa::tensor_product_integral(integrand.f, 5, rule, 1), sa::tensor_product_integral(integrand.f, 5, rule, 2));
}

TEST(DimensionStudy, PointsPerAxisCoverTheRangeAboutOncePerDoubling) {
  sa::DimensionStudyRequest request;
  request.min_n = 16;
  request.max_n = 1 << 20;
  EXPECT_EQ(sa::points_per_axis(request, 10), (std::vector<unsigned>{2, 3, 4}));
  const auto one = sa::points_per_axis(request, 1);
  ASSERT_EQ(one.size(), 17u);
  EXPECT_EQ(one.front(), 16u);
  EXPECT_EQ(one.back(), 1u << 20);
}

// The study's own numbers: product-rule slopes near −2/d, the Monte Carlo
// mean squared error consistent with σ²/N, Sobol' below MC, MC winning at
// d = 10 and losing at d = 1.
TEST(DimensionStudy, RatesMatchTheory) {
  sa::DimensionStudyRequest request;
  request.min_dim = 1;
  request.max_dim = 10;
  request.min_n = 16;
  request.max_n = 1 << 15;
  request.runs = 32;
  request.seed = 7;
  request.threads = 2;
  const sa::DimensionStudy study = sa::run_dimension_study(request);
  ASSERT_EQ(study.series.size(), 10u);
  std::size_t points = 0;
  for (const auto& s : study.series) points += s.n.size();
  // χ² test of R·MSE/(σ²/N) ~ χ²_R (normal estimates; N ≥ 16 and the
  // integrand is bounded), two-sided, Šidák-corrected family α = 0.01.
  const double alpha = 1 - std::pow(1 - 0.01, 1.0 / static_cast<double>(points));
  const boost::math::chi_squared chi2(request.runs);
  const double low = boost::math::quantile(chi2, alpha / 2), high = boost::math::quantile(chi2, 1 - alpha / 2);
  for (const auto& s : study.series) {
    SCOPED_TRACE("d = " + std::to_string(s.d));
    ASSERT_GT(s.variance, 0);
    for (std::size_t i = 0; i < s.n.size(); ++i) {
      const double statistic = request.runs * s.mc_rmse[i] * s.mc_rmse[i] * static_cast<double>(s.n[i]) / s.variance;
      EXPECT_GT(statistic, low) << "N = " << s.n[i];
      EXPECT_LT(statistic, high) << "N = " << s.n[i];
    }
    // RMSE of 32 runs has relative spread ≈ 1/√64 ≈ 12.5%; over ≥ 4 values of
    // N spanning ≥ 2^5 the fitted slope's standard deviation is below 0.04:
    // 0.15 is > 3.5σ.
    if (s.n.size() >= 4) {
      EXPECT_NEAR(s.mc_slope, -0.5, 0.15);
    }
    if (s.n.size() >= 3 && s.d <= 6) {
      EXPECT_NEAR(s.product_slope, -2.0 / s.d, 0.05 + 0.02 * s.d);
    }
    EXPECT_EQ(s.product_predicted_slope, -2.0 / s.d);
    // Owen-scrambled Sobol' on a smooth integrand: far below MC at large N.
    EXPECT_LT(s.sobol_rmse.back(), 0.5 * s.mc_rmse.back());
  }
  const auto& d1 = study.series.front();
  EXPECT_LT(d1.product_error.back(), 1e-6 * d1.mc_rmse.back());
  const auto& d10 = study.series.back();
  EXPECT_GT(d10.product_error.back(), 3 * d10.mc_rmse.back());
}

TEST(DimensionStudy, ResultDoesNotDependOnThreads) {
  sa::DimensionStudyRequest request;
  request.min_dim = 2;
  request.max_dim = 4;
  request.max_n = 4096;
  request.runs = 4;
  request.rule = "gauss";
  request.threads = 1;
  const auto a = sa::run_dimension_study(request);
  request.threads = 2;
  const auto b = sa::run_dimension_study(request);
  for (std::size_t s = 0; s < a.series.size(); ++s) {
    EXPECT_EQ(a.series[s].product_error, b.series[s].product_error);
    EXPECT_EQ(a.series[s].mc_rmse, b.series[s].mc_rmse);
    EXPECT_EQ(a.series[s].sobol_rmse, b.series[s].sobol_rmse);
  }
}

TEST(DimensionStudy, RejectsBadRequests) {
  const auto error_of = [](sa::DimensionStudyRequest request) -> std::string {
    try {
      sa::validate(request);
    } catch (const stratum::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  sa::DimensionStudyRequest good;
  EXPECT_EQ(error_of(good), "");
  auto r = good;
  r.runs = 1;
  EXPECT_NE(error_of(r).find("invalid runs = 1"), std::string::npos);
  r = good;
  r.min_dim = 0;
  EXPECT_NE(error_of(r).find("invalid min_dim = 0"), std::string::npos);
  r = good;
  r.max_dim = 0;
  EXPECT_NE(error_of(r).find("invalid max_dim = 0"), std::string::npos);
  r = good;
  r.min_n = 100, r.max_n = 10;
  EXPECT_NE(error_of(r).find("invalid max_n = 10"), std::string::npos);
  r = good;
  r.rule = "simpson";
  EXPECT_NE(error_of(r).find("invalid rule = simpson"), std::string::npos);
  r = good;
  r.integrand = "nosuch";
  EXPECT_NE(error_of(r).find("invalid integrand = nosuch"), std::string::npos);
  r = good;
  r.max_n = 500;  // d = 9 needs 2^9 = 512 (d = 8 has 2^8 = 256)
  EXPECT_NE(error_of(r).find("d = 9 has none"), std::string::npos);
}

// A smooth registry integrand: Gauss–Legendre with 64 points per axis
// integrates the Genz Gaussian (a = 5) to rounding, so the registry's closed
// form and the tensor rule must agree; both product and MC errors are finite.
TEST(DimensionStudy, AcceptsSmoothRegistryIntegrands) {
  const auto names = sa::dimension_integrand_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "genz-gaussian"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "genz-discontinuous"), names.end());
  sa::DimensionStudyRequest request;
  request.integrand = "genz-gaussian";
  request.rule = "gauss";
  request.min_dim = 2;
  request.max_dim = 2;
  request.max_n = 4096;
  request.runs = 4;
  const auto study = sa::run_dimension_study(request);
  for (const auto& s : study.series) {
    EXPECT_LT(s.product_error.back(), 1e-12 * s.exact) << "d = " << s.d;
    EXPECT_GT(s.product_error.front(), 1e-6 * s.exact) << "d = " << s.d;  // 4 points per axis are not enough
    EXPECT_TRUE(std::isnan(s.variance));                                  // unknown
    for (double e : s.mc_rmse) EXPECT_TRUE(std::isfinite(e) && e > 0);
  }
}
