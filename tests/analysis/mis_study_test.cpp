// The MIS study (analysis/mis_study.hpp): predicted variances against an
// independent Simpson-rule integration of the same moments, the measured
// variances and estimates against the predictions and the closed form
// (Student-t over the runs, Šidák-corrected), Veach's bound on the balance
// heuristic, the power heuristic's advantage where one strategy is nearly
// exact (Veach 1997, §9.2.4), thread independence and the refusals.
#include "stratum/analysis/mis_study.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numbers>

#include "../patterns/unbiased.hpp"
#include "../registry/error_of.hpp"

namespace stratum::analysis {
namespace {

constexpr double pi = std::numbers::pi;

/// Per-sample variance of `method` by composite Simpson on [cos α, 1] with
/// 5·10^4 panels, written from the definitions (not the study's code).
double simpson_variance(const std::string& method, double e, double angle, double beta = 2) {
  const double c = std::cos(angle * pi / 180);
  const double p_light = 1 / (2 * pi * (1 - c));
  const auto lobe = [&](double t) { return (e + 1) / (2 * pi) * std::pow(t, e); };
  const auto w = [&](double self, double other) {
    if (method == "balance") return self / (self + other);
    if (method == "power") return std::pow(self, beta) / (std::pow(self, beta) + std::pow(other, beta));
    return 1.0;
  };
  // Moments of one strategy's w·f/p: ∫ (w f)²/p dω and ∫ w f dω, dω = 2π dt.
  const auto moments = [&](bool light) {
    const int panels = 50000;
    const double h = (1 - c) / panels;
    double second = 0, first = 0;
    for (int k = 0; k <= 2 * panels; ++k) {
      const double t = c + k * h / 2;
      const double weight = (k == 0 || k == 2 * panels) ? 1 : (k % 2 ? 4 : 2);
      const double p = light ? p_light : lobe(t);
      const double wf = (light ? w(p_light, lobe(t)) : w(lobe(t), p_light)) * lobe(t);
      if (wf != 0) second += weight * 2 * pi * wf * wf / p;  // t = cos 90° = 0: the lobe is 0 there
      first += weight * 2 * pi * wf;
    }
    second *= h / 6, first *= h / 6;
    return second - first * first;
  };
  if (method == "light") return moments(true);
  if (method == "bsdf") return moments(false);
  return 2 * (moments(true) + moments(false));
}

TEST(MisStudy, PredictedVariancesMatchAnIndependentQuadrature) {
  for (double e : {0.0, 1.0, 10.0, 100.0})
    for (double angle : {2.0, 10.0, 30.0, 60.0, 90.0})
      for (const std::string method : {"light", "bsdf", "balance", "power"}) {
        const double ours = mis_predicted_variance(method, e, angle), theirs = simpson_variance(method, e, angle);
        EXPECT_NEAR(ours, theirs, 1e-9 * std::max(1.0, std::fabs(theirs)) + 1e-7 * std::fabs(theirs))
            << method << " e " << e << " angle " << angle;
      }
  // β = 3 reaches the power heuristic.
  EXPECT_NEAR(mis_predicted_variance("power", 10, 10, 3), simpson_variance("power", 10, 10, 3), 1e-9);
  EXPECT_NE(mis_predicted_variance("power", 10, 10, 3), mis_predicted_variance("power", 10, 10, 2));
}

TEST(MisStudy, MeasuredAgreesWithPredictedAndExact) {
  MisStudyRequest request;
  request.exponents = {1, 10};
  request.angles = {10, 30, 60};
  request.runs = 32;
  request.samples = 1024;
  request.seed = 3;
  const MisStudy study = run_mis_study(request);
  ASSERT_EQ(study.cases.size(), 6u);
  // 6 cases × 4 methods × (estimate, variance): Šidák at family α = 0.001.
  const double alpha = stratum::testing::sidak(0.001, 48);
  const boost::math::students_t t(request.runs - 1);
  const double critical = boost::math::quantile(boost::math::complement(t, alpha / 2));
  for (const MisCase& c : study.cases) {
    EXPECT_DOUBLE_EQ(c.exact, 1 - std::pow(std::cos(c.angle * pi / 180), c.exponent + 1));
    ASSERT_EQ(c.methods.size(), 4u);
    for (const MisMethodResult& m : c.methods) {
      EXPECT_LE(std::fabs(m.estimate - c.exact), critical * m.estimate_stderr)
          << m.method << " e " << c.exponent << " angle " << c.angle;
      EXPECT_LE(std::fabs(m.variance - m.predicted_variance), critical * m.variance_stderr)
          << m.method << " e " << c.exponent << " angle " << c.angle << ": " << m.variance << " vs "
          << m.predicted_variance;
    }
  }
}

TEST(MisStudy, VeachsBoundHoldsAndThePowerHeuristicWinsWhereOneStrategyIsNearlyExact) {
  const MisStudy study =
      run_mis_study({.exponents = {0, 1, 10, 100, 1000}, .angles = {1, 2, 10, 30, 60, 90}, .runs = 2, .samples = 4});
  for (const MisCase& c : study.cases) {
    EXPECT_LE(c.methods[2].predicted_variance, c.balance_bound * (1 + 1e-9)) << c.exponent << " " << c.angle;
    EXPECT_EQ(c.methods[2].method, "balance");
  }
  // A small light over a broad lobe: light sampling is nearly exact, the
  // balance heuristic carries the I² term (≫ the best), the power heuristic
  // stays within a small factor of the best.
  const MisCase& small_light = study.cases[1 * 6 + 1];  // e = 1, α = 2°
  ASSERT_EQ(small_light.exponent, 1);
  ASSERT_EQ(small_light.angle, 2);
  EXPECT_EQ(small_light.best_single, "light");
  EXPECT_GT(small_light.balance_over_best, 1000);
  EXPECT_LT(small_light.power_over_best, 3);
  // Where the two strategies are comparable (e = 10, α = 30°), the balance
  // heuristic is within a few percent of the better one.
  const MisCase& crossover = study.cases[2 * 6 + 3];
  ASSERT_EQ(crossover.exponent, 10);
  ASSERT_EQ(crossover.angle, 30);
  EXPECT_LT(crossover.balance_over_best, 1.1);
}

TEST(MisStudy, ResultsDoNotDependOnThreads) {
  MisStudyRequest request{.exponents = {10}, .angles = {10, 60}, .runs = 8, .samples = 256, .seed = 9};
  const MisStudy one = run_mis_study(request);
  request.threads = 2;
  const MisStudy two = run_mis_study(request);
  for (std::size_t k = 0; k < one.cases.size(); ++k)
    for (std::size_t m = 0; m < 4; ++m) {
      EXPECT_EQ(one.cases[k].methods[m].estimate, two.cases[k].methods[m].estimate);
      EXPECT_EQ(one.cases[k].methods[m].variance, two.cases[k].methods[m].variance);
    }
}

TEST(MisStudy, Refusals) {
  using stratum::testing::error_of;
  EXPECT_EQ(error_of([] { run_mis_study({.angles = {0}}); }),
            "invalid angle = 0: light half-angles must be in (0, 90] degrees");
  EXPECT_EQ(error_of([] { run_mis_study({.exponents = {-1}}); }),
            "invalid exponent = -1: Phong exponents must be in [0, 100000]");
  EXPECT_EQ(error_of([] { run_mis_study({.samples = 7}); }),
            "invalid samples = 7: must be even, in [4, 2^32] (the MIS methods take half from each strategy)");
  EXPECT_EQ(error_of([] { run_mis_study({.runs = 1}); }), "invalid runs = 1: must be in [2, 100000]");
  EXPECT_EQ(error_of([] { run_mis_study({.beta = 0}); }), "invalid beta = 0: must be in (0, 16]");
  EXPECT_EQ(error_of([] { mis_predicted_variance("mixture", 1, 10); }),
            "invalid method = mixture: must be one of light, bsdf, balance, power");
}

}  // namespace
}  // namespace stratum::analysis
