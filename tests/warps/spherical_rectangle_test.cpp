#include "stratum/warps/spherical_rectangle.hpp"

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
  V3 corner, edge_u, edge_v, origin;
  double z_min;  // all directions to the rectangle have z >= z_min (χ² bins); NAN: not around +z
};

std::vector<Case> cases() {
  // No edge lies on a χ² bin boundary (a plane φ = const through the z axis).
  return {
      {"rotated, around the pole", {-0.4, -0.3, 1}, {0.9, 0.3, 0}, {-0.2, 0.6, 0.15}, {0, 0, 0}, 0.55},
      {"wide (S > 2)", {-4, -3, 1}, {8, 0, 0}, {0, 7, 0}, {0, 0, 0}, 0.1},
      {"seen from above, plane flipped", {1, 1, 3}, {0, 2, 0.5}, {2, 0, 0}, {0.5, 0.5, 4}, NAN},
      {"small (S ≈ 2e-4)", {0.3, 0.2, 10}, {0.2, 0, 0}, {0, 0.1, 0}, {0, 0, 0}, NAN},
  };
}

SphericalRectangle<double> make(const Case& c) { return {c.corner, c.edge_u, c.edge_v, c.origin}; }

/// The small case (S ≈ 2e-4), by its solid angle rather than its name: it
/// loses digits, and float cannot resolve its angle sum.
bool tiny(const Case& c) { return make(c).solid_angle() < 1e-2; }

V3 at(const Case& c, double s, double t) {
  return testing::plus(c.corner, testing::plus(vector3::scale(c.edge_u, s), vector3::scale(c.edge_v, t)));
}
/// Solid angle of the part s ∈ [0, s1] of the rectangle as two triangles (Van Oosterom–Strackee).
double two_triangles(const Case& c, double s1 = 1) {
  return testing::van_oosterom_strackee(at(c, 0, 0), at(c, s1, 0), at(c, s1, 1), c.origin) +
         testing::van_oosterom_strackee(at(c, 0, 0), at(c, s1, 1), at(c, 0, 1), c.origin);
}
/// The rectangle coordinate s of the point the ray from the origin along w hits.
double hit_s(const Case& c, const V3& w) {
  using namespace vector3;
  const V3 n = cross(c.edge_u, c.edge_v);
  const double t = dot(testing::minus(c.corner, c.origin), n) / dot(w, n);
  const V3 hit = testing::plus(c.origin, scale(w, t));
  return dot(testing::minus(hit, c.corner), c.edge_u) / dot(c.edge_u, c.edge_u);
}

U2 u_at(std::uint64_t seed, std::uint64_t i, double margin = 0) {
  return {margin + (1 - 2 * margin) * uniform01(seed, i, 0), margin + (1 - 2 * margin) * uniform01(seed, i, 1)};
}

TEST(WarpSphericalRectangle, SolidAngleMatchesIndependentFormulas) {
  for (const auto& c : cases()) {
    const double s = make(c).solid_angle(), reference = two_triangles(c);
    EXPECT_NEAR(s, reference, 1e-7 * reference) << c.name;
  }
  // A 3 × 1.5 rectangle seen from 2 above one corner: atan(ab / (d √(a² + b² + d²))).
  const SphericalRectangle<double> corner_view({0, 0, 2}, {3, 0, 0}, {0, 1.5, 0});
  EXPECT_NEAR(corner_view.solid_angle(), std::atan(3 * 1.5 / (2 * std::sqrt(4 + 9 + 2.25))), 1e-12);
}

// χ² with equal-solid-angle (cos θ, φ) bins on the cap z >= z_min holding the
// rectangle (samples outside it would make χ² infinite), one test of the χ²
// family (tests/warps/chi2.hpp: Šidák at family α = 0.01) per case around +z.
// The cases without a cap (z_min = NAN) are tested by the other tests only.
std::vector<Case> capped_cases() {
  std::vector<Case> capped;
  for (const auto& c : cases())
    if (!std::isnan(c.z_min)) capped.push_back(c);
  return capped;
}

void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }  // ctest's names show the case

class WarpSphericalRectangleChi2 : public testing::Chi2Fixture<::testing::TestWithParam<Case>> {};

TEST_P(WarpSphericalRectangleChi2, UniformInSolidAngle) {
  const Case& c = GetParam();
  const auto map = make(c);
  testing::Chi2Options options;
  options.subdivisions = 24;  // the rectangle's edges cut bins: a fine quadrature subgrid for the expected counts
  testing::expect_chi2(testing::chi2_test(testing::direction_sampler(map), testing::direction_pdf(map),
                                          testing::Domain::directions(c.z_min, 1, 24, 48), options),
                       c.name);
}

INSTANTIATE_TEST_SUITE_P(Capped, WarpSphericalRectangleChi2, ::testing::ValuesIn(capped_cases()),
                         [](const auto& info) { return testing::chi2_param_name(info.param.name); });

// The test has power: directions to points uniform in the rectangle's area are rejected.
TEST(WarpSphericalRectangle, Chi2RejectsUniformAreaSampling) {
  const Case c = cases()[1];
  const auto map = make(c);
  const testing::SampleFn by_area = [&](const double* u, double* out) {
    const V3 w = testing::unit(testing::minus(at(c, u[0], u[1]), c.origin));
    out[0] = w[0], out[1] = w[1], out[2] = w[2];
  };
  testing::Chi2Options options;
  options.subdivisions = 24;
  EXPECT_LT(
      testing::chi2_test(by_area, testing::direction_pdf(map), testing::Domain::directions(c.z_min, 1, 24, 48), options)
          .p_value,
      1e-12);
}

TEST(WarpSphericalRectangle, SamplesAreUnitDirectionsInside) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    for (std::uint64_t i = 0; i < 5000; ++i) {
      const V3 w = map.sample(u_at(3, i));
      ASSERT_NEAR(vector3::length(w), 1.0, 1e-12) << c.name;
      ASSERT_EQ(map.pdf(w), 1 / map.solid_angle()) << c.name << " " << i;
      const double s = hit_s(c, w);
      ASSERT_TRUE(s >= -1e-12 && s <= 1 + 1e-12) << c.name << " s = " << s;
      ASSERT_EQ(map.pdf(vector3::scale(w, -1.0)), 0.0) << c.name;
    }
  }
}

TEST(WarpSphericalRectangle, PdfIntegratesToOne) {
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

TEST(WarpSphericalRectangle, InverseRoundTrip) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    const double tolerance = tiny(c) ? 1e-5 : 1e-9;  // the small one loses digits
    for (std::uint64_t i = 0; i < 20000; ++i) {
      const U2 u = u_at(5, i);
      const V3 w = map.sample(u);
      const U2 back = map.invert(w);
      ASSERT_NEAR(back[0], u[0], tolerance) << c.name << " " << i;
      ASSERT_NEAR(back[1], u[1], tolerance) << c.name << " " << i;
      const V3 again = map.sample(back);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(again[k], w[k], 1e-9) << c.name << " " << i;
    }
    // Corners: u = (0,0) is the corner, (1,1) the opposite one.
    const auto corners = map.corner_directions();
    const U2 first = map.invert(corners[0]), last = map.invert(corners[3]);
    EXPECT_NEAR(first[0], 0, 1e-9);
    EXPECT_NEAR(first[1], 0, 1e-9);
    EXPECT_NEAR(last[0], 1, 1e-9);
    EXPECT_NEAR(last[1], 1, 1e-9);
    EXPECT_NEAR(hit_s(c, corners[1]), 1.0, 1e-12);
  }
}

TEST(WarpSphericalRectangle, JacobianIsTheSolidAngle) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    const std::function<V3(U2)> sample = [&](U2 u) { return map.sample(u); };
    for (std::uint64_t i = 0; i < 500; ++i) {
      const double jacobian = testing::solid_angle_jacobian(sample, u_at(9, i, 0.01));
      ASSERT_NEAR(jacobian / map.solid_angle(), 1.0, 1e-4) << c.name << " " << i;
    }
  }
}

// u0 alone: the part of the rectangle left of the sample's abscissa subtends
// u0·S, by two Van Oosterom–Strackee triangles.
TEST(WarpSphericalRectangle, FirstCoordinateSweepsSubRectanglesOfProportionalArea) {
  for (const auto& c : cases()) {
    const auto map = make(c);
    for (double u0 : {0.1, 0.25, 0.5, 0.8, 0.95}) {
      const double s = hit_s(c, map.sample({u0, 0.37}));
      EXPECT_NEAR(two_triangles(c, s), u0 * map.solid_angle(), 1e-8 * map.solid_angle()) << c.name << " " << u0;
    }
  }
}

TEST(WarpSphericalRectangle, StratifiedInputStaysStratified) {
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

TEST(WarpSphericalRectangle, FloatAgreesWithDouble) {
  const auto all = cases();
  ASSERT_EQ(std::count_if(all.begin(), all.end(), tiny), 1);  // the float check skips only it
  for (const auto& c : cases()) {
    if (tiny(c)) continue;  // float cannot resolve the small one's angle sum
    const auto map = make(c);
    const auto f = [](const V3& v) { return Vector3<float>{float(v[0]), float(v[1]), float(v[2])}; };
    const SphericalRectangle<float> map_float(f(c.corner), f(c.edge_u), f(c.edge_v), f(c.origin));
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
    make_warp("spherical-rectangle", params);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WarpSphericalRectangle, BadInput) {
  const std::string zero_u = error_of({{"edge_u", {0, 0, 0}}});
  EXPECT_NE(zero_u.find("invalid edge_u = (0, 0, 0): must be non-zero"), std::string::npos) << zero_u;
  const std::string zero_v = error_of({{"edge_v", {0, 0, 0}}});
  EXPECT_NE(zero_v.find("invalid edge_v = (0, 0, 0)"), std::string::npos) << zero_v;
  const std::string parallel = error_of({{"edge_u", {1, 0, 0}}, {"edge_v", {-2, 0, 0}}});
  EXPECT_NE(parallel.find("invalid edge_v = (-2, 0, 0): must not be parallel to edge_u = (1, 0, 0)"), std::string::npos)
      << parallel;
  const std::string skew = error_of({{"edge_u", {1, 0, 0}}, {"edge_v", {1, 1, 0}}});
  EXPECT_NE(skew.find("must be perpendicular to edge_u"), std::string::npos) << skew;
  const std::string on_plane = error_of({{"origin", {3, -2, 1}}});
  EXPECT_NE(on_plane.find("invalid origin = (3, -2, 1): must not lie on the rectangle's plane"), std::string::npos)
      << on_plane;
  const std::string inside_plane = error_of({{"origin", {0, 0, 1}}});
  EXPECT_NE(inside_plane.find("invalid origin = (0, 0, 1)"), std::string::npos) << inside_plane;
  const std::string short_corner = error_of({{"corner", {1, 2}}});
  EXPECT_NE(short_corner.find("invalid corner = (2 values): must be 3 finite reals"), std::string::npos)
      << short_corner;
  EXPECT_NE(error_of({{"corner", {1, INFINITY, 0}}}).find("invalid corner[1] = inf: must be a finite real"),
            std::string::npos);
  EXPECT_EQ(error_of({}), "");
}

TEST(WarpSphericalRectangle, RegistryEntryMatchesTheCore) {
  const Case c = cases()[2];
  const auto warp = make_warp("spherical-rectangle", {{"corner", {c.corner[0], c.corner[1], c.corner[2]}},
                                                      {"edge_u", {c.edge_u[0], c.edge_u[1], c.edge_u[2]}},
                                                      {"edge_v", {c.edge_v[0], c.edge_v[1], c.edge_v[2]}},
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
    EXPECT_NEAR(back[2 * i + 1], u[2 * i + 1], 1e-9);
  }
  EXPECT_TRUE(find_warp("spherical-rectangle").area_preserving);
}

}  // namespace
}  // namespace stratum
