#include "stratum/warps/projected_solid_angle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "chi2.hpp"
#include "spherical_support.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/warp_registry.hpp"

namespace stratum {
namespace {

using testing::U2;
using testing::V3;

/// One projected warp under test, with its polygon's corners (for Lambert's formula).
struct Case {
  const char* name;
  std::function<V3(U2)> sample;
  std::function<double(V3)> pdf;
  std::function<U2(V3)> invert;
  std::vector<V3> polygon;  // vertices in order, as seen from the origin
  V3 normal;
  double z_min;                          // all directions have z >= z_min
  std::function<V3(U2)> uniform_sample;  // the spherical warp alone
  double solid_angle;
};

const ProjectedSphericalTriangle<double> triangle(SphericalTriangle<double>({0.1, 0.05, 1}, {1, 0.2, 1}, {-0.1, 1, 1}),
                                                  {0.6, 0, 0.8});
const ProjectedSphericalRectangle<double> rectangle(SphericalRectangle<double>({-4, -3, 1}, {8, 0, 0}, {0, 7, 0}),
                                                    {0, 0, 1});
const ProjectedSphericalRectangle<double> tilted(SphericalRectangle<double>({-0.4, -0.3, 1}, {0.9, 0.3, 0},
                                                                            {-0.2, 0.6, 0.15}),
                                                 {0.3, -0.4, 0.8});

template <class Map>
Case make_case(const char* name, const Map& map, std::vector<V3> polygon, V3 normal, double z_min) {
  return {name,
          [&map](U2 u) { return map.sample(u); },
          [&map](V3 w) { return map.pdf(w); },
          [&map](V3 w) { return map.invert(w); },
          std::move(polygon),
          normal,
          z_min,
          [&map](U2 u) { return map.spherical().sample(u); },
          map.spherical().solid_angle()};
}

std::vector<Case> cases() {
  return {
      make_case("triangle", triangle, {{0.1, 0.05, 1}, {1, 0.2, 1}, {-0.1, 1, 1}}, {0.6, 0, 0.8}, 0.6),
      make_case("wide rectangle", rectangle, {{-4, -3, 1}, {4, -3, 1}, {4, 4, 1}, {-4, 4, 1}}, {0, 0, 1}, 0.1),
      make_case("tilted rectangle", tilted, {{-0.4, -0.3, 1}, {0.5, 0, 1}, {0.3, 0.6, 1.15}, {-0.6, 0.3, 1.15}},
                {0.3, -0.4, 0.8}, 0.55),
  };
}

/// ∫ |n·ω| dω over a polygon above the plane of n, by Lambert's (1760) formula:
/// ½ |Σ_i angle(v_i, v_{i+1}) n·unit(v_i × v_{i+1})|.
double lambert_projected_solid_angle(const std::vector<V3>& polygon, const V3& normal) {
  using namespace vector3;
  const V3 n = testing::unit(normal);
  double sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const V3 a = testing::unit(polygon[i]), b = testing::unit(polygon[(i + 1) % polygon.size()]);
    sum += angle_between(a, b) * dot(n, testing::unit(cross(a, b)));
  }
  return std::abs(sum) / 2;
}

U2 u_at(std::uint64_t seed, std::uint64_t i, double margin = 0) {
  return {margin + (1 - 2 * margin) * uniform01(seed, i, 0), margin + (1 - 2 * margin) * uniform01(seed, i, 1)};
}

// χ² against the (non-uniform) pdf on equal-solid-angle bins of the cap, one
// test of the χ² family per case (tests/warps/chi2.hpp: Šidák at family α = 0.01).
void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }  // ctest's names show the case

class WarpProjectedSolidAngleChi2 : public testing::Chi2Fixture<::testing::TestWithParam<Case>> {};

TEST_P(WarpProjectedSolidAngleChi2, MatchesPdf) {
  const Case& c = GetParam();
  const testing::SampleFn sample = [&](const double* u, double* out) {
    const V3 w = c.sample({u[0], u[1]});
    out[0] = w[0], out[1] = w[1], out[2] = w[2];
  };
  const testing::PdfFn pdf = [&](const double* p) { return c.pdf({p[0], p[1], p[2]}); };
  testing::Chi2Options options;
  options.subdivisions = 24;  // the polygon's edges cut bins: a fine quadrature subgrid
  testing::expect_chi2(testing::chi2_test(sample, pdf, testing::Domain::directions(c.z_min, 1, 24, 48), options),
                       c.name);
}

INSTANTIATE_TEST_SUITE_P(Polygons, WarpProjectedSolidAngleChi2, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return testing::chi2_param_name(info.param.name); });

// The density of the composite map is 1 / |Jacobian| (numerical, independent
// of the pdf's formula through the inverse).
TEST(WarpProjectedSolidAngle, PdfIsTheInverseJacobian) {
  for (const auto& c : cases()) {
    for (std::uint64_t i = 0; i < 500; ++i) {
      const U2 u = u_at(17, i, 0.01);
      const double jacobian = testing::solid_angle_jacobian(c.sample, u);
      ASSERT_NEAR(c.pdf(c.sample(u)) * jacobian, 1.0, 1e-4) << c.name << " " << i;
    }
  }
}

TEST(WarpProjectedSolidAngle, PdfIntegratesToOne) {
  for (const auto& c : cases()) {
    const double integral = testing::integrate_over_sphere(c.pdf, c.z_min < 0.3 ? 0.0 : c.z_min, 600, 1200);
    EXPECT_NEAR(integral, 1.0, 1e-3) << c.name;  // midpoint rule; edge cells err ~1e-4 in all
  }
}

TEST(WarpProjectedSolidAngle, InverseRoundTrip) {
  for (const auto& c : cases()) {
    for (std::uint64_t i = 0; i < 20000; ++i) {
      const U2 u = u_at(5, i);
      const V3 w = c.sample(u);
      const U2 back = c.invert(w);
      ASSERT_NEAR(back[0], u[0], 1e-9) << c.name << " " << i;
      ASSERT_NEAR(back[1], u[1], 1e-9) << c.name << " " << i;
      ASSERT_GT(c.pdf(w), 0.0) << c.name << " " << i;
    }
  }
}

// Lecture §3: irradiance E = ∫ cos θ dω. The estimator cos θ / p has the
// exact mean (Lambert's formula) and, where the cosine varies between the
// corners, far less variance than with the uniform solid-angle warp. The wide
// rectangle shows the approximation's limit: its corners all see cos θ ≈ 0.19
// while the middle sees 1, so the bilinear density is nearly uniform and the
// variance is no lower.
TEST(WarpProjectedSolidAngle, IrradianceEstimatorIsUnbiasedWithLowerVariance) {
  for (const auto& c : cases()) {
    const V3 n = testing::unit(c.normal);
    const auto cosine = [&](const V3& w) { return std::abs(vector3::dot(n, w)); };
    const int samples = 20000;
    double sum = 0, sum2 = 0, uniform_sum = 0, uniform_sum2 = 0;
    for (int i = 0; i < samples; ++i) {
      const U2 u = u_at(23, i);
      const V3 w = c.sample(u);
      const double y = cosine(w) / c.pdf(w);
      sum += y, sum2 += y * y;
      const double z = cosine(c.uniform_sample(u)) * c.solid_angle;
      uniform_sum += z, uniform_sum2 += z * z;
    }
    const double mean = sum / samples, variance = sum2 / samples - mean * mean;
    const double uniform_mean = uniform_sum / samples;
    const double uniform_variance = uniform_sum2 / samples - uniform_mean * uniform_mean;
    const double exact = lambert_projected_solid_angle(c.polygon, c.normal);
    // 4.5 standard errors: two-sided level 7e-6 per check.
    EXPECT_NEAR(mean, exact, 4.5 * std::sqrt(variance / samples)) << c.name;
    EXPECT_NEAR(uniform_mean, exact, 4.5 * std::sqrt(uniform_variance / samples)) << c.name;
    if (std::string(c.name) == "wide rectangle") continue;
    EXPECT_LT(variance, 0.25 * uniform_variance) << c.name;
  }
}

TEST(WarpProjectedSolidAngle, CornerWeightsAreTheCosinesAtTheCorners) {
  // Rectangle at z = 1 with normal +z: the weights are the corners' z over their distance.
  const auto& w = rectangle.bilinear();
  const std::vector<V3> corners = {{-4, -3, 1}, {4, -3, 1}, {-4, 4, 1}, {4, 4, 1}};  // u = (0,0), (1,0), (0,1), (1,1)
  const double total = [&] {
    double t = 0;
    for (const auto& p : corners) t += testing::unit(p)[2];
    return t;
  }();
  for (int i = 0; i < 4; ++i) {
    const U2 corner_u = {double(i % 2), double(i / 2)};
    // The bilinear density at a corner is 4 w_i / Σw.
    EXPECT_NEAR(w.pdf(corner_u), 4 * testing::unit(corners[i])[2] / total, 1e-12) << i;
  }
  // Grazing corners are floored at 0.01 (pbrt-v4), so the density stays positive.
  const ProjectedSphericalTriangle<double> grazing(SphericalTriangle<double>({1, 0, 0}, {0, 1, 0}, {0, 0, 1}),
                                                   {1, 0, 0});
  EXPECT_GT(grazing.pdf(testing::unit({0.001, 0.5, 0.5})), 0.0);
}

TEST(WarpProjectedSolidAngle, FloatAgreesWithDouble) {
  const ProjectedSphericalRectangle<float> rectangle_float(SphericalRectangle<float>({-4, -3, 1}, {8, 0, 0}, {0, 7, 0}),
                                                           {0, 0, 1});
  for (std::uint64_t i = 0; i < 2000; ++i) {
    const U2 u = u_at(29, i);
    const V3 w = rectangle.sample(u);
    const Vector3<float> wf = rectangle_float.sample({float(u[0]), float(u[1])});
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(wf[k], w[k], 2e-4) << i;
    ASSERT_NEAR(rectangle_float.pdf(wf), rectangle.pdf(w), 1e-3 * rectangle.pdf(w)) << i;
  }
}

std::string error_of(const char* name, const WarpParams& params) {
  try {
    make_warp(name, params);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WarpProjectedSolidAngle, BadInputAndRegistry) {
  for (const char* name : {"spherical-triangle-projected", "spherical-rectangle-projected"}) {
    const std::string zero = error_of(name, {{"normal", {0, 0, 0}}});
    EXPECT_NE(zero.find("invalid normal = (0, 0, 0): must be a non-zero vector"), std::string::npos) << zero;
    EXPECT_NE(error_of(name, {{"normal", {0, 1}}}).find("invalid normal = (2 values): must be 3 finite reals"),
              std::string::npos);
    EXPECT_FALSE(find_warp(name).area_preserving);
    EXPECT_EQ(error_of(name, {}), "");
  }
  EXPECT_NE(
      error_of("spherical-triangle-projected", {{"vertices", {0, 0, 1, 1, 1, 1, 2, 2, 1}}}).find("invalid vertices"),
      std::string::npos);
  EXPECT_NE(error_of("spherical-rectangle-projected", {{"origin", {0, 0, 1}}}).find("invalid origin"),
            std::string::npos);
  // The registry entry is the core map with the default normal (0, 0, 1).
  const auto warp = make_warp("spherical-rectangle-projected",
                              {{"corner", {-4, -3, 1}}, {"edge_u", {8, 0, 0}}, {"edge_v", {0, 7, 0}}});
  const double u[2] = {0.3, 0.8};
  const auto p = warp_sample(*warp, u, 1);
  const V3 w = rectangle.sample({0.3, 0.8});
  for (int k = 0; k < 3; ++k) EXPECT_EQ(p[k], w[k]);
  EXPECT_EQ(warp_pdf(*warp, p.data(), 1)[0], rectangle.pdf(w));
}

}  // namespace
}  // namespace stratum
