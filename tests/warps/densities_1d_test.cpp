#include "stratum/warps/densities_1d.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "chi2.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

struct Density1d {
  std::string name;
  std::function<double(double)> sample, pdf, invert;
  double lo, hi;  // χ² bins cover [lo, hi]; the rest of the mass is the "outside" cell
};

template <class D>
Density1d wrap(std::string name, D d, double lo, double hi) {
  return {std::move(name),
          [d](double u) { return d.sample(u); },
          [d](double x) { return d.pdf(x); },
          [d](double x) { return d.invert(x); },
          lo,
          hi};
}

std::vector<Density1d> densities() {
  return {wrap("linear 1 3", LinearDensity<double>(1, 3), 0, 1),
          wrap("linear 0 1", LinearDensity<double>(0, 1), 0, 1),
          wrap("linear 2 2", LinearDensity<double>(2, 2), 0, 1),
          wrap("tent 0.7", TentDensity<double>(0.7), -0.7, 0.7),
          wrap("exponential 2", ExponentialDensity<double>(2), 0, 3),
          wrap("normal 1 0.5", NormalDensity<double>(1, 0.5), -1, 3)};
}

// χ² over 40 intervals plus the tail cell, one test of the χ² family per
// density (tests/warps/chi2.hpp: Šidák at family α = 0.01).
void PrintTo(const Density1d& t, std::ostream* out) { *out << t.name; }  // ctest's names show the case

class WarpDensities1dChi2 : public testing::Chi2Fixture<::testing::TestWithParam<Density1d>> {};

TEST_P(WarpDensities1dChi2, MatchesPdf) {
  const Density1d& t = GetParam();
  testing::Chi2Options options;
  options.input_dim = 1;
  testing::expect_chi2(testing::chi2_test([&](const double* u, double* x) { x[0] = t.sample(u[0]); },
                                          [&](const double* x) { return t.pdf(x[0]); },
                                          testing::Domain::interval(t.lo, t.hi, 40), options),
                       t.name);
}

INSTANTIATE_TEST_SUITE_P(Densities, WarpDensities1dChi2, ::testing::ValuesIn(densities()),
                         [](const auto& info) { return testing::chi2_param_name(info.param.name); });

class WarpBilinearDensityChi2 : public testing::Chi2Fixture<> {};

TEST_F(WarpBilinearDensityChi2, MatchesPdf) {
  const BilinearDensity<double> bilinear(std::array<double, 4>{1, 2, 0.5, 4});
  testing::expect_chi2(testing::chi2_test(
      [&](const double* u, double* out) {
        const auto p = bilinear.sample({u[0], u[1]});
        out[0] = p[0], out[1] = p[1];
      },
      [&](const double* p) {
        return bilinear.pdf({p[0], p[1]});
      },
      testing::Domain::box(0, 1, 0, 1, 16, 16)));
}

TEST(WarpDensities1d, InverseRoundTrip) {
  for (const auto& t : densities())
    for (int k = 0; k < 20000; ++k) {
      const double u = uniform01(4, k);
      const double x = t.sample(u);
      ASSERT_GT(t.pdf(x), 0.0) << t.name << " " << u;
      ASSERT_NEAR(t.invert(x), u, 1e-12) << t.name << " " << k;
      ASSERT_NEAR(t.sample(t.invert(x)), x, 1e-12 * (1 + std::abs(x))) << t.name << " " << k;
    }
  const BilinearDensity<double> bilinear(std::array<double, 4>{1, 2, 0.5, 4});
  for (int k = 0; k < 20000; ++k) {
    const std::array<double, 2> u = {uniform01(6, k, 0), uniform01(6, k, 1)};
    const auto back = bilinear.invert(bilinear.sample(u));
    ASSERT_NEAR(back[0], u[0], 1e-12) << k;
    ASSERT_NEAR(back[1], u[1], 1e-12) << k;
  }
}

// Closed forms and Boost.Math as the oracle for the normal quantile.
TEST(WarpDensities1d, ClosedForms) {
  EXPECT_DOUBLE_EQ(sample_linear(0.25, 0.0, 1.0), 0.5);  // density 2x: x = √u
  EXPECT_DOUBLE_EQ(sample_linear(0.75, 1.0, 0.0), 0.5);  // density 2(1 − x): x = 1 − √(1 − u)
  EXPECT_DOUBLE_EQ(sample_linear(0.3, 2.0, 2.0), 0.3);   // uniform
  EXPECT_DOUBLE_EQ(linear_pdf(0.5, 1.0, 3.0), 1.0);
  const TentDensity<double> tent(2);
  EXPECT_EQ(tent.sample(0.5), 0.0);
  EXPECT_DOUBLE_EQ(tent.pdf(0), 0.5);
  EXPECT_DOUBLE_EQ(tent.sample(0.125), -1.0);  // CDF at −1 is (1/2)(1/2)² = 1/8
  const ExponentialDensity<double> exponential(3);
  EXPECT_DOUBLE_EQ(exponential.sample(1 - std::exp(-1.5)), 0.5);
  EXPECT_DOUBLE_EQ(exponential.pdf(0), 3.0);
  const NormalDensity<double> normal(1, 2);
  const boost::math::normal_distribution<double> oracle(1, 2);
  for (double u : {1e-18, 1e-12, 0.01, 0.3, 0.5, 0.77, 0.999, 1 - 1e-12}) {
    const double x = normal.sample(u);
    EXPECT_NEAR(x, boost::math::quantile(oracle, u), 1e-13 * (1 + std::abs(x))) << u;
    EXPECT_NEAR(normal.pdf(x), boost::math::pdf(oracle, x), 1e-15) << u;
  }
  EXPECT_TRUE(std::isfinite(normal.sample(0.0)));  // u = 0 is raised to 2^-64
  EXPECT_LT(normal.sample(0.0), 1 - 2 * 9);
  const BilinearDensity<double> bilinear(std::array<double, 4>{1, 2, 3, 4});
  EXPECT_DOUBLE_EQ(bilinear.pdf({0, 0}), 0.4);
  EXPECT_DOUBLE_EQ(bilinear.pdf({0.5, 0.5}), 1.0);
  EXPECT_EQ(bilinear.pdf({1.5, 0.5}), 0.0);
}

// ∫ pdf = 1: 3-point Gauss–Legendre over the support on 10000 panels (tent
// and linear are piecewise linear with kinks on panel edges: exact to rounding; the tails beyond 40/rate and 12 σ
// are below 1e-15).
TEST(WarpDensities1d, PdfIntegratesToOne) {
  for (auto t : densities()) {
    if (t.name.starts_with("exponential")) t.hi = 20;
    if (t.name.starts_with("normal")) t.lo = 1 - 6, t.hi = 1 + 6;
    const double total = testing::bin_mass([&](const double* x) { return t.pdf(x[0]); },
                                           testing::Domain::interval(t.lo, t.hi, 1), 0, 0, 10000);
    EXPECT_NEAR(total, 1.0, 1e-12) << t.name;
  }
  const BilinearDensity<double> bilinear(std::array<double, 4>{1, 2, 0.5, 4});
  const double total = testing::bin_mass(
      [&](const double* p) {
        return bilinear.pdf({p[0], p[1]});
      },
      testing::Domain::box(0, 1, 0, 1, 1, 1), 0, 0, 4);
  EXPECT_NEAR(total, 1.0, 1e-14);  // Gauss–Legendre is exact for bilinear
}

TEST(WarpDensities1d, FloatAgreesWithDouble) {
  const TentDensity<float> tf(0.7f);
  const NormalDensity<float> nf(1, 0.5f);
  const ExponentialDensity<float> ef(2);
  const LinearDensity<float> lf(1, 3);
  const BilinearDensity<float> bf(std::array<float, 4>{1, 2, 0.5f, 4});
  const auto d = densities();
  for (int k = 1; k < 5000; ++k) {
    const float u = uniform01<float>(8, k);
    ASSERT_NEAR(lf.sample(u), d[0].sample(u), 2e-6) << u;
    ASSERT_NEAR(tf.sample(u), d[3].sample(u), 2e-6) << u;
    ASSERT_NEAR(ef.sample(u), d[4].sample(u), 2e-6 * (1 + d[4].sample(u)) / (1 - u)) << u;
    ASSERT_NEAR(nf.sample(u), d[5].sample(u), 1e-5 / std::min(u, 1 - u)) << u;
    const auto pf = bf.sample({u, 1 - u});
    const auto pd = BilinearDensity<double>(std::array<double, 4>{1, 2, 0.5, 4}).sample({u, 1.0 - u});
    ASSERT_NEAR(pf[0], pd[0], 4e-6);
    ASSERT_NEAR(pf[1], pd[1], 4e-6);
  }
}

TEST(WarpDensities1d, BadParameters) {
  const auto error_of = [](const std::function<void()>& make) -> std::string {
    try {
      make();
    } catch (const invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of([] { TentDensity<double>(0); }).find("invalid radius = 0"), std::string::npos);
  EXPECT_NE(error_of([] { TentDensity<double>(-1); }).find("invalid radius = -1"), std::string::npos);
  EXPECT_NE(error_of([] { ExponentialDensity<double>(0); }).find("invalid rate = 0"), std::string::npos);
  EXPECT_NE(error_of([] { NormalDensity<double>(0, 0); }).find("invalid sigma = 0"), std::string::npos);
  EXPECT_NE(error_of([] { NormalDensity<double>(0, -2); }).find("invalid sigma = -2"), std::string::npos);
  EXPECT_NE(error_of([] { LinearDensity<double>(-1, 2); }).find("invalid a = -1"), std::string::npos);
  EXPECT_NE(error_of([] { LinearDensity<double>(0, 0); }).find("not both be zero"), std::string::npos);
  EXPECT_NE(error_of([] {
              BilinearDensity<double>(std::array<double, 4>{0, 0, 0, 0});
            }).find("invalid weights"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              BilinearDensity<double>(std::array<double, 4>{1, -1, 0, 0});
            }).find("invalid weights"),
            std::string::npos);
  EXPECT_EQ(error_of([] { BilinearDensity<double>(std::array<double, 4>{0, 0, 0, 1}); }), "");
}

}  // namespace
}  // namespace stratum
