#include "stratum/warps/spherical_triangle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

struct Case {
  const char* name;
  V3 p0, p1, p2, origin;
  double z_min;  // all directions of the triangle have z >= z_min (for χ² bins); NAN: not around +z
};

std::vector<Case> cases() {
  // No edge lies on a bin boundary of the χ² (a plane φ = const): there the
  // Simpson rule would count the edge's density from both sides.
  return {
      {"near the pole", {0.1, 0.05, 1}, {1, 0.2, 1}, {-0.1, 1, 1}, {0, 0, 0}, 0.6},
      {"clockwise, around the pole", {-1, -1, 1}, {0.2, 1.3, 1}, {1.5, -0.5, 1}, {0, 0, 0}, 0.5},
      {"wide (Ω > 2)", {-5, -5, 1}, {5, -5, 1}, {0, 6, 1}, {0, 0, 0}, 0.1},
      {"off-origin, tilted", {2, 1, -1}, {0.5, 3, 0}, {1, 0.5, 2}, {-0.3, 0.2, 0.4}, NAN},
      {"small (Ω ≈ 1e-4)", {0, 0, 10}, {0.1, 0, 10}, {0, 0.2, 10}, {0, 0, 0}, NAN},
  };
}

SphericalTriangle<double> make(const Case& c) { return {c.p0, c.p1, c.p2, c.origin}; }

/// The small case (Ω ≈ 1e-4), by its solid angle rather than its name: its
/// sub-areas lose digits and float cannot resolve its excess (Girard cancels).
bool tiny(const Case& c) { return make(c).solid_angle() < 1e-2; }

U2 u_at(std::uint64_t seed, std::uint64_t i, double margin = 0) {
  return {margin + (1 - 2 * margin) * uniform01(seed, i, 0), margin + (1 - 2 * margin) * uniform01(seed, i, 1)};
}

// Girard's excess (the warp's) against Van Oosterom–Strackee and L'Huilier.
TEST(WarpSphericalTriangle, SolidAngleMatchesIndependentFormulas) {
  for (const auto& c : cases()) {
    const double omega = make(c).solid_angle();
    const double vos = testing::van_oosterom_strackee(c.p0, c.p1, c.p2, c.origin);
    EXPECT_NEAR(omega, vos, 1e-11 * (1 + 1 / vos) * vos) << c.name;
    EXPECT_NEAR(omega, testing::lhuilier(c.p0, c.p1, c.p2, c.origin), 1e-8 * vos) << c.name;
  }
  // The octant's face x, y, z >= 0 seen from its corner: 4π/8.
  const SphericalTriangle<double> octant({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_NEAR(octant.solid_angle(), std::numbers::pi / 2, 1e-14);
}

// χ² with equal-solid-angle (cos θ, φ) bins on the cap z >= z_min holding the
// triangle (samples outside it would make χ² infinite), one test of the χ²
// family (tests/warps/chi2.hpp: Šidák at family α = 0.01) per case around +z.
// The cases without a cap (z_min = NAN) are tested by the other tests only.
std::vector<Case> capped_cases() {
  std::vector<Case> capped;
  for (const auto& c : cases())
    if (!std::isnan(c.z_min)) capped.push_back(c);
  return capped;
}

void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }  // ctest's names show the case

class WarpSphericalTriangleChi2 : public testing::Chi2Fixture<::testing::TestWithParam<Case>> {};

TEST_P(WarpSphericalTriangleChi2, UniformInSolidAngle) {
  const Case& c = GetParam();
  const auto map = make(c);
  testing::Chi2Options options;
  options.subdivisions = 24;  // the triangle's edges cut bins: a fine quadrature subgrid for the expected counts
  testing::expect_chi2(testing::chi2_test(testing::direction_sampler(map), testing::direction_pdf(map),
                                          testing::Domain::directions(c.z_min, 1, 24, 48), options),
                       c.name);
}

INSTANTIATE_TEST_SUITE_P(Capped, WarpSphericalTriangleChi2, ::testing::ValuesIn(capped_cases()),
                         [](const auto& info) { return testing::chi2_param_name(info.param.name); });

// The test has power: directions to points uniform in the plane triangle's
// area are not uniform in solid angle, and χ² rejects them.
TEST(WarpSphericalTriangle, Chi2RejectsUniformAreaSampling) {
  const Case c = cases()[2];
  const auto map = make(c);
  const testing::SampleFn by_area = [&](const double* u, double* out) {
    const double s = std::sqrt(u[0]), b0 = 1 - s, b1 = u[1] * s;  // uniform barycentrics
    const V3 p = testing::plus(testing::plus(vector3::scale(c.p0, b0), vector3::scale(c.p1, b1)),
                               vector3::scale(c.p2, 1 - b0 - b1));
    const V3 w = testing::unit(p);
    out[0] = w[0], out[1] = w[1], out[2] = w[2];
  };
  testing::Chi2Options options;
  options.subdivisions = 24;
  EXPECT_LT(
      testing::chi2_test(by_area, testing::direction_pdf(map), testing::Domain::directions(c.z_min, 1, 24, 48), options)
          .p_value,
      1e-12);
}

TEST(WarpSphericalTriangle, SamplesAreUnitDirectionsInside) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    for (std::uint64_t i = 0; i < 5000; ++i) {
      const V3 w = map.sample(u_at(3, i));
      ASSERT_NEAR(vector3::length(w), 1.0, 1e-12) << c.name;
      ASSERT_EQ(map.pdf(w), 1 / map.solid_angle()) << c.name << " " << i;
      ASSERT_EQ(map.pdf(vector3::scale(w, -1.0)), 0.0) << c.name;  // the opposite cone is outside
    }
  }
}

TEST(WarpSphericalTriangle, PdfIntegratesToOne) {
  for (const auto& c : cases()) {
    if (std::isnan(c.z_min)) continue;
    const auto map = make(c);
    const double integral =
        testing::integrate_over_sphere([&](V3 w) { return map.pdf(w); }, c.z_min < 0.3 ? 0.0 : c.z_min, 600, 1200);
    // Midpoint rule on an indicator: only cells cut by an edge err, with
    // errors of both signs; at this grid they sum to ~1e-4 (1e-3 allowed).
    EXPECT_NEAR(integral, 1.0, 1e-3) << c.name;
  }
}

TEST(WarpSphericalTriangle, InverseRoundTrip) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    const double tolerance = tiny(c) ? 1e-6 : 1e-9;  // the small triangle's sub-areas lose digits
    for (std::uint64_t i = 0; i < 20000; ++i) {
      const U2 u = u_at(5, i);
      const V3 w = map.sample(u);
      const U2 back = map.invert(w);
      ASSERT_NEAR(back[0], u[0], tolerance) << c.name << " " << i;
      ASSERT_NEAR(back[1], u[1], tolerance) << c.name << " " << i;
      const V3 again = map.sample(back);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(again[k], w[k], 1e-9) << c.name << " " << i;
    }
    // Vertices: B is u1 = 0, A is (0, 1), C is (1, 1).
    const U2 at_a = map.invert(map.a()), at_c = map.invert(map.c());
    EXPECT_NEAR(at_a[0], 0, 1e-9);
    EXPECT_NEAR(at_a[1], 1, 1e-9);
    EXPECT_NEAR(at_c[0], 1, 1e-9);
    EXPECT_EQ(map.invert(map.b())[1], 0.0);
  }
}

// Area preservation: the map's solid-angle Jacobian equals Ω everywhere, so
// equal strata of [0,1)² become equal solid angles.
TEST(WarpSphericalTriangle, JacobianIsTheSolidAngle) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    const std::function<V3(U2)> sample = [&](U2 u) { return map.sample(u); };
    for (std::uint64_t i = 0; i < 500; ++i) {
      const double jacobian = testing::solid_angle_jacobian(sample, u_at(9, i, 0.01));
      ASSERT_NEAR(jacobian / map.solid_angle(), 1.0, 1e-4) << c.name << " " << i;
    }
  }
}

// u0 alone: the sub-triangle A B Ĉ(u0) (Ĉ = sample(u0, 1)) subtends u0·Ω, by
// the independent Van Oosterom–Strackee formula.
TEST(WarpSphericalTriangle, FirstCoordinateSweepsSubTrianglesOfProportionalArea) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    for (double u0 : {0.1, 0.25, 0.5, 0.8, 0.95}) {
      const V3 c_hat = map.sample({u0, 1.0});
      EXPECT_NEAR(testing::van_oosterom_strackee(map.a(), map.b(), c_hat), u0 * map.solid_angle(),
                  1e-9 * map.solid_angle())
          << c.name << " u0 = " << u0;
    }
  }
}

// A jittered 16 × 16 grid: each image lies in a different one of the 256
// equal-solid-angle strata (the preimages of the grid cells, located by the inverse).
TEST(WarpSphericalTriangle, StratifiedInputStaysStratified) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    const int n = 16;
    const auto hits = testing::stratum_hits(
        testing::direction_sampler(map), n, n, 11,
        [&](const double* p) {
          const U2 u = map.invert(V3{p[0], p[1], p[2]});
          return static_cast<long>(std::floor(u[1] * n) * n + std::floor(u[0] * n));
        },
        n * n);
    for (int cell = 0; cell < n * n; ++cell) ASSERT_EQ(hits[cell], 1) << c.name << " cell " << cell;
  }
}

TEST(WarpSphericalTriangle, FloatAgreesWithDouble) {
  const auto all = cases();
  ASSERT_EQ(std::count_if(all.begin(), all.end(), tiny), 1);  // the float check skips only it
  for (const auto& c : cases()) {
    if (tiny(c)) continue;  // float cannot resolve a 1e-4 sr triangle's excess (Girard cancels)
    const auto map = make(c);
    const auto f = [](const V3& v) { return Vector3<float>{float(v[0]), float(v[1]), float(v[2])}; };
    const SphericalTriangle<float> map_float(f(c.p0), f(c.p1), f(c.p2), f(c.origin));
    EXPECT_NEAR(map_float.solid_angle(), map.solid_angle(), 1e-5 * map.solid_angle()) << c.name;
    for (std::uint64_t i = 0; i < 2000; ++i) {
      const U2 u = u_at(13, i);
      const V3 w = map.sample(u);
      const Vector3<float> wf = map_float.sample({float(u[0]), float(u[1])});
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(wf[k], w[k], 2e-4) << c.name << " " << i;
      const auto uf = map_float.invert(wf);
      ASSERT_NEAR(uf[0], u[0], 2e-3) << c.name << " " << i;
      ASSERT_NEAR(uf[1], u[1], 2e-3) << c.name << " " << i;
    }
  }
}

std::string error_of(const WarpParams& params) {
  try {
    make_warp("spherical-triangle", params);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WarpSphericalTriangle, BadInput) {
  // Collinear vertices, a plane through the origin, a vertex at the origin.
  const std::string collinear = error_of({{"vertices", {0, 0, 1, 1, 1, 1, 2, 2, 1}}});
  EXPECT_NE(collinear.find("invalid vertices = (0, 0, 1), (1, 1, 1), (2, 2, 1)"), std::string::npos) << collinear;
  EXPECT_NE(collinear.find("positive solid angle"), std::string::npos) << collinear;
  const std::string edge_on = error_of({{"vertices", {1, 0, 0, 0, 1, 0, 1, 1, 0}}});
  EXPECT_NE(edge_on.find("invalid vertices"), std::string::npos) << edge_on;
  EXPECT_NE(edge_on.find("plane not through the origin"), std::string::npos) << edge_on;
  const std::string shifted = error_of({{"vertices", {0, 0, 1, 1, 0, 1, 0, 1, 1}}, {"origin", {5, 5, 1}}});
  EXPECT_NE(shifted.find("invalid vertices"), std::string::npos) << shifted;
  const std::string at_origin = error_of({{"vertices", {0, 0, 0, 1, 0, 1, 0, 1, 1}}});
  EXPECT_NE(at_origin.find("invalid vertices = (0, 0, 0): each vertex must differ from the origin"), std::string::npos)
      << at_origin;
  const std::string short_list = error_of({{"vertices", {0, 0, 1, 1, 0, 1}}});
  EXPECT_NE(short_list.find("invalid vertices = (6 values): must be 9 finite reals"), std::string::npos) << short_list;
  const std::string bad_origin = error_of({{"origin", {0, 0}}});
  EXPECT_NE(bad_origin.find("invalid origin = (2 values): must be 3 finite reals"), std::string::npos) << bad_origin;
  EXPECT_NE(
      error_of({{"vertices", {0, 0, 1, 1, 0, 1, 0, NAN, 1}}}).find("invalid vertices[7] = nan: must be a finite real"),
      std::string::npos);
  EXPECT_EQ(error_of({}), "");  // the defaults are a valid triangle
}

TEST(WarpSphericalTriangle, RegistryEntryMatchesTheCore) {
  const Case c = cases()[3];
  const auto warp =
      make_warp("spherical-triangle",
                {{"vertices", {c.p0[0], c.p0[1], c.p0[2], c.p1[0], c.p1[1], c.p1[2], c.p2[0], c.p2[1], c.p2[2]}},
                 {"origin", {c.origin[0], c.origin[1], c.origin[2]}}});
  const auto map = make(c);
  const double u[4] = {0.25, 0.75, 0.9, 0.1};
  const auto points = warp_sample(*warp, u, 2);
  const auto pdfs = warp_pdf(*warp, points.data(), 2);
  const auto back = warp_invert(*warp, points.data(), 2);
  for (int i = 0; i < 2; ++i) {
    const V3 w = map.sample({u[2 * i], u[2 * i + 1]});
    for (int k = 0; k < 3; ++k) EXPECT_EQ(points[3 * i + k], w[k]);
    EXPECT_EQ(pdfs[i], 1 / map.solid_angle());
    EXPECT_NEAR(back[2 * i], u[2 * i], 1e-9);
  }
  EXPECT_TRUE(find_warp("spherical-triangle").area_preserving);
}

}  // namespace
}  // namespace stratum
