/// Tests of the importance-sampling studies (LECTURE.md §3).
/// Oracles: Lambert's polygon irradiance against brute-force quadrature over
/// the light and against the textbook view factor of a parallel rectangle;
/// the sky's closed forms (E = πL, Var = π²L²/3 uniform, 0 cosine); measured
/// estimates and variances against exact values and predicted variances
/// (Student-t tests over the replicates, Šidák-corrected).
#include "stratum/analysis/importance_study.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numbers>

#include "stratum/util/error.hpp"

namespace sa = stratum::analysis;
constexpr double pi = std::numbers::pi;

namespace {

/// View factor from a differential area to a parallel a × b rectangle with
/// one corner above it at height h (Howell, "A catalog of radiation heat
/// transfer configuration factors", B-3): F = (1/2π)[A/√(1+A²) atan(B/√(1+A²))
/// + B/√(1+B²) atan(A/√(1+B²))], A = a/h, B = b/h. Irradiance = πL·F.
double corner_view_factor(double a, double b, double h) {
  const double A = a / h, B = b / h;
  return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
          B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
         (2 * pi);
}

}  // namespace

TEST(ImportanceStudy, LambertFormulaMatchesViewFactorForCenteredSquares) {
  for (double size : {0.01, 0.3, 1.0, 4.0, 50.0}) {
    for (double h : {0.1, 1.0, 3.0}) {
      const auto light = sa::centered_square_light(size, h, 2.0);
      const double expected = 2.0 * pi * 4 * corner_view_factor(size / 2, size / 2, h);
      EXPECT_NEAR(sa::rectangle_irradiance(light), expected, 1e-12 * expected) << size << " " << h;
    }
  }
  // A huge light fills the hemisphere: E → πL.
  EXPECT_NEAR(sa::rectangle_irradiance(sa::centered_square_light(1e6, 1)), pi, 1e-5);
}

TEST(ImportanceStudy, LambertFormulaMatchesBruteForceForTiltedAndOffsetLights) {
  const double c = std::cos(0.4), s = std::sin(0.4);
  const sa::RectangleLight lights[] = {
      {{0.3, -0.2, 0.5}, {0.7, 0, 0}, {0, 1.3, 0}, 1.0},            // offset, parallel
      {{-0.5, 0.2, 0.4}, {1.0, 0, 0}, {0, 0.6 * c, 0.6 * s}, 1.5},  // tilted about x
      {{1.0, 1.0, 0.2}, {0.5 * c, 0, 0.5 * s}, {0, 2.0, 0}, 0.7},   // far off-axis, tilted about y
  };
  for (const auto& light : lights) {
    const double brute = light.radiance * sa::rectangle_area_integral(light, 1, 1, 1, 64, 10);
    EXPECT_NEAR(sa::rectangle_irradiance(light), brute, 1e-10 * brute);
  }
}

TEST(ImportanceStudy, RejectsBadLightsAndRequests) {
  const auto message = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const stratum::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message([] {
              sa::rectangle_irradiance({{0, 0, -1}, {1, 0, 0}, {0, 1, 0}, 1});
            }).find("above the receiver"),
            std::string::npos);
  EXPECT_NE(message([] {
              sa::rectangle_irradiance({{0, 0, 1}, {1, 0, 0}, {1, 1, 0}, 1});
            }).find("perpendicular"),
            std::string::npos);
  EXPECT_NE(message([] {
              sa::rectangle_irradiance({{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 0});
            }).find("invalid radiance"),
            std::string::npos);
  sa::ImportanceStudyRequest r;
  r.runs = 1;
  EXPECT_NE(message([&] { sa::validate(r); }).find("invalid runs = 1"), std::string::npos);
  r = {};
  r.samples = 0;
  EXPECT_NE(message([&] { sa::validate(r); }).find("invalid samples = 0"), std::string::npos);
  r = {};
  r.sizes = {1, -2};
  EXPECT_NE(message([&] { sa::validate(r); }).find("invalid size = -2"), std::string::npos);
  r = {};
  r.sizes = {65};
  r.distances = {1};
  EXPECT_NE(message([&] { sa::validate(r); }).find("invalid size = 65: must lie in [distance/1000, 64 distance]"),
            std::string::npos);
  r.sizes = {64};
  EXPECT_EQ(message([&] { sa::validate(r); }), "");
  r = {};
  r.distances = {};
  EXPECT_NE(message([&] { sa::validate(r); }).find("invalid distances"), std::string::npos);
  EXPECT_EQ(message([] { sa::validate(sa::ImportanceStudyRequest{}); }), "");
}

// A centred light much smaller than its distance: Y_area = LA cos⁴θ/h² and
// Y_solid-angle = LΩ cos θ, so the relative spread is 4× larger by area and
// the variance ratio tends to 16 (both see nearly the same ψ² spread).
TEST(ImportanceStudy, PredictedVarianceRatioOfSmallLightTendsTo16) {
  sa::ImportanceStudyRequest request;
  request.runs = 2;
  request.samples = 2;
  request.sizes = {0.002, 0.1, 1};
  request.distances = {1};
  const auto study = sa::run_importance_study(request);
  EXPECT_NEAR(study.light.at(0).predicted_variance_ratio, 16, 1e-3);
  EXPECT_NEAR(study.light.at(1).predicted_variance_ratio, 16, 1e-3);
  // At size = distance the light is no longer small: the ratio has grown.
  EXPECT_GT(study.light.at(2).predicted_variance_ratio, 16.1);
}

TEST(ImportanceStudy, MeasurementsAgreeWithTheory) {
  sa::ImportanceStudyRequest request;
  request.runs = 24;
  request.samples = 4096;
  request.radiance = 1.5;
  request.sizes = {0.25, 1, 4};
  request.distances = {0.5, 2};
  request.seed = 11;
  request.threads = 2;
  const auto study = sa::run_importance_study(request);
  ASSERT_EQ(study.hemisphere.size(), 2u);
  ASSERT_EQ(study.light.size(), 6u);

  const double L = request.radiance;
  const auto& sky = study.hemisphere[0];
  EXPECT_EQ(sky.scene, "sky");
  EXPECT_NEAR(sky.exact, pi * L, 1e-15);
  // Zero variance: cosine sampling makes every sample exactly πL up to rounding.
  EXPECT_LT(sky.b.variance, 1e-26 * L * L);
  EXPECT_NEAR(sky.b.estimate, pi * L, 1e-13);
  EXPECT_GT(sky.variance_ratio, 1e20);
  EXPECT_GT(sky.efficiency_ratio, 1e15);

  // Student-t tests (runs − 1 degrees of freedom) of every estimate against the
  // exact irradiance and every non-zero variance against its prediction:
  // 4 tests per comparison, family α = 0.01, Šidák-corrected.
  const std::size_t tests = 4 * (study.hemisphere.size() + study.light.size());
  const double alpha = 1 - std::pow(1 - 0.01, 1.0 / static_cast<double>(tests));
  const double t = boost::math::quantile(boost::math::students_t(request.runs - 1), 1 - alpha / 2);
  const auto check = [&](const sa::ImportanceComparison& c) {
    SCOPED_TRACE(c.study + " " + c.scene + " size " + std::to_string(c.size) + " distance " +
                 std::to_string(c.distance));
    for (const sa::MethodResult* m : {&c.a, &c.b}) {
      SCOPED_TRACE(m->method);
      if (m->predicted_variance == 0) continue;
      EXPECT_LT(std::abs(m->estimate - c.exact), t * m->estimate_stderr);
      EXPECT_LT(std::abs(m->variance - m->predicted_variance), t * m->variance_stderr);
      EXPECT_GT(m->seconds_per_sample, 0);
      EXPECT_NEAR(m->efficiency, 1 / (m->variance * m->seconds_per_sample), 1e-9 * m->efficiency);
    }
  };
  for (const auto& c : study.hemisphere) check(c);
  for (const auto& c : study.light) check(c);

  // Cosine beats uniform under the light too (p closer to ∝ cos θ · 1_light),
  // and solid-angle beats area sampling in every configuration, increasingly
  // as the light grows against its distance.
  const auto& lit = study.hemisphere[1];
  EXPECT_GT(lit.predicted_variance_ratio, 1.2);
  EXPECT_GT(lit.variance_ratio - t * lit.variance_ratio_stderr, 1);
  for (const auto& c : study.light) {
    EXPECT_GT(c.predicted_variance_ratio, 1.5) << c.size << " " << c.distance;
    EXPECT_GT(c.variance_ratio - t * c.variance_ratio_stderr, 1) << c.size << " " << c.distance;
    EXPECT_NEAR(c.efficiency_ratio, c.variance_ratio * c.time_ratio, 1e-9 * c.efficiency_ratio);
  }
  // size 4 at distance 0.5 is the hardest case for area sampling.
  EXPECT_GT(study.light[4].predicted_variance_ratio, study.light[0].predicted_variance_ratio);
}

TEST(ImportanceStudy, ResultDoesNotDependOnThreads) {
  sa::ImportanceStudyRequest request;
  request.runs = 4;
  request.samples = 512;
  request.sizes = {1};
  request.distances = {1, 2};
  request.threads = 1;
  const auto a = sa::run_importance_study(request);
  request.threads = 2;
  const auto b = sa::run_importance_study(request);
  ASSERT_EQ(a.light.size(), b.light.size());
  for (std::size_t i = 0; i < a.light.size(); ++i) {
    EXPECT_EQ(a.light[i].a.estimate, b.light[i].a.estimate);
    EXPECT_EQ(a.light[i].b.variance, b.light[i].b.variance);
    EXPECT_EQ(a.light[i].variance_ratio, b.light[i].variance_ratio);
  }
  EXPECT_EQ(a.hemisphere[1].a.variance, b.hemisphere[1].a.variance);
}
