// Solid-angle sampling of sphere and triangle lights (src/render/lights.cpp):
// χ² tests of the directions the renderer's light sampler draws from a
// shading point against the density they should have, closed-form
// irradiance, the pdf MIS uses, and agreement of the rendered images with
// area sampling (per-pixel z-tests, Šidák-corrected).
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "../warps/chi2.hpp"
#include "irradiance_estimate.hpp"
#include "stratum/render/bsdf.hpp"
#include "stratum/render/lights.hpp"
#include "stratum/render/render.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {
namespace {

constexpr double pi = std::numbers::pi;

// The three tests of RenderLightSamplingChi2 are members of the χ² family
// (tests/warps/chi2.hpp: Šidák at family α = 0.01), one χ² check each.
class RenderLightSamplingChi2 : public testing::Chi2Fixture<> {};

/// The solid angle of the triangle (a, b, c) seen from x, by Van Oosterom and
/// Strackee (1983): tan(Ω/2) = |a·(b×c)| / (1 + a·b + b·c + c·a) for unit
/// a, b, c (an oracle independent of the sampler's Girard formula).
double solid_angle(Vec3 a, Vec3 b, Vec3 c, Vec3 x) {
  a = normalize(a - x), b = normalize(b - x), c = normalize(c - x);
  return 2 * std::atan2(std::abs(dot(a, cross(b, c))), 1 + dot(a, b) + dot(b, c) + dot(c, a));
}

/// Does the ray x + t·w (t > 0) cross the triangle (a, b, c)? (Möller, Trumbore 1997.)
bool crosses(Vec3 x, Vec3 w, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 e1 = b - a, e2 = c - a, p = cross(w, e2);
  const double det = dot(e1, p);
  if (std::abs(det) < 1e-300) return false;
  const Vec3 s = x - a;
  const double u = dot(s, p) / det;
  const Vec3 q = cross(s, e1);
  const double v = dot(w, q) / det, t = dot(e2, q) / det;
  return u >= 0 && v >= 0 && u + v <= 1 && t > 0;
}

/// Runs a χ² test of the directions sample_light(…, solid_angle) draws for
/// `light` from x (normal n), in the frame whose z axis is `axis`, binned on
/// the cap z ≥ z_min, against `density` (per steradian, of a world direction).
testing::Chi2Result light_chi2(const Scene& scene, const Light& light, Vec3 x, Vec3 n, double time, Vec3 axis,
                               double z_min, const std::function<double(Vec3)>& density, int subdivisions) {
  const Frame frame(normalize(axis));
  const auto sample = [&](const double* u, double* out) {
    const auto s = sample_light(scene, light, x, n, time, {u[0], u[1]}, LightStrategy::solid_angle);
    if (!s) {
      out[0] = out[1] = 0, out[2] = -2;  // in no bin: counted as outside
      return;
    }
    out[0] = dot(s->wi, frame.s), out[1] = dot(s->wi, frame.t), out[2] = dot(s->wi, frame.n);
  };
  const auto pdf = [&](const double* p) { return density(frame.to_world({p[0], p[1], p[2]})); };
  testing::Chi2Options options;
  options.samples = 200000;
  options.seed = 21;
  options.subdivisions = subdivisions;
  return testing::chi2_test(sample, pdf, testing::Domain::directions(z_min, 1, 12, 24), options);
}

Scene one_light(const std::string& shape) {
  return parse_scene(R"({"materials": {"lamp": {"reflectance": [0, 0, 0], "emission": [3, 2, 1]}},
                         "shapes": [)" +
                         shape + R"(]})",
                     "light");
}

TEST_F(RenderLightSamplingChi2, SphereConeDirectionsAreUniformOverTheCone) {
  // A moving sphere seen at time 0.5: centre (0.5, 3, 1) + 0.5·(2, 0, 0).
  const Scene scene = one_light(R"({"type": "sphere", "center": [0.5, 3, 1], "radius": 0.8, "motion": [2, 0, 0],
                                    "material": "lamp"})");
  const Vec3 x{0.2, 0, 0.3}, n{0, 1, 0}, center{1.5, 3, 1};
  const double d = length(center - x), cos_max = std::sqrt(1 - 0.64 / (d * d));
  const double uniform = 1 / (2 * pi * (1 - cos_max));  // closed form, computed naively
  const auto result = light_chi2(
      scene, scene.lights[0], x, n, 0.5, center - x, cos_max,
      [&](Vec3 w) { return dot(w, normalize(center - x)) >= cos_max ? uniform : 0.0; }, 8);
  testing::expect_chi2(result);
  // Every sample's distance puts its point on the sphere, where it has that density.
  for (int i = 0; i < 1000; ++i) {
    const auto s = sample_light(scene, scene.lights[0], x, n, 0.5, {uniform01(3, i, 0), uniform01(3, i, 1)},
                                LightStrategy::solid_angle);
    ASSERT_TRUE(s);
    EXPECT_NEAR(length(x + s->distance * s->wi - center), 0.8, 1e-9);
    EXPECT_NEAR(s->pdf, uniform, 1e-9 * uniform);
    EXPECT_EQ(s->radiance.x, 3);
  }
}

TEST_F(RenderLightSamplingChi2, TriangleMeshDirectionsFollowAreaPickThenUniformSolidAngle) {
  // Two triangles of areas 0.5 and 2 (picked with probability 0.2 and 0.8),
  // both facing down towards x: density Σ_k (A_k / A)·[w crosses k] / Ω_k.
  const Scene scene = one_light(R"({"type": "triangles", "material": "lamp",
      "vertices": [[-1, 2, 0], [0, 2, 0], [-1, 2, 1], [0.2, 2.5, -1], [2.2, 2.5, -1], [0.2, 2.5, 1]],
      "indices": [[0, 1, 2], [3, 4, 5]]})");
  const Vec3 x{0, 0, 0}, n{0, 1, 0};
  const Vec3 v[6] = {{-1, 2, 0}, {0, 2, 0}, {-1, 2, 1}, {0.2, 2.5, -1}, {2.2, 2.5, -1}, {0.2, 2.5, 1}};
  const double omega0 = solid_angle(v[0], v[1], v[2], x), omega1 = solid_angle(v[3], v[4], v[5], x);
  const auto density = [&](Vec3 w) {
    return (crosses(x, w, v[0], v[1], v[2]) ? 0.2 / omega0 : 0.0) +
           (crosses(x, w, v[3], v[4], v[5]) ? 0.8 / omega1 : 0.0);
  };
  const Vec3 axis{0.3, 2.2, 0.1};
  double z_min = 1;
  for (Vec3 p : v) z_min = std::min(z_min, dot(normalize(p - x), normalize(axis)));
  const auto result = light_chi2(scene, scene.lights[0], x, n, 0, axis, z_min - 0.01, density, 32);
  testing::expect_chi2(result);
}

TEST_F(RenderLightSamplingChi2, RectangleDirectionsAreUniformOverItsSolidAngle) {
  const Scene scene = one_light(R"({"type": "quad", "corner": [-0.5, 2, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 1.5],
                                    "material": "lamp"})");
  const Vec3 x{0.1, 0, 0.2}, n{0, 1, 0};
  const Vec3 a{-0.5, 2, -1}, b{1.5, 2, -1}, c{1.5, 2, 0.5}, e{-0.5, 2, 0.5};
  const double omega = solid_angle(a, b, c, x) + solid_angle(a, c, e, x);
  const auto density = [&](Vec3 w) { return crosses(x, w, a, b, c) || crosses(x, w, a, c, e) ? 1 / omega : 0.0; };
  const Vec3 axis{0.4, 2, -0.05};
  double z_min = 1;
  for (Vec3 p : {a, b, c, e}) z_min = std::min(z_min, dot(normalize(p - x), normalize(axis)));
  const auto result = light_chi2(scene, scene.lights[0], x, n, 0, axis, z_min - 0.01, density, 32);
  testing::expect_chi2(result);
}

std::pair<double, double> irradiance(const Scene& scene, Vec3 x, Vec3 n, LightStrategy strategy, int samples) {
  return testing_support::irradiance(scene, x, n, strategy, samples, 5);
}

TEST(RenderLightSampling, IrradianceMatchesClosedFormsForBothStrategies) {
  // Sphere of radiance L, radius r, centre at distance d along the normal:
  // E = π L (r/d)² (the sphere is a Lambertian disk of the cone's cap).
  // Triangle: Lambert's polygon formula E = L/2 Σ_edges Θ_i (n · n_i), Θ_i the
  // angle an edge subtends, n_i the unit normal of the plane through x and
  // the edge (Arvo 1995, "Applications of irradiance tensors"). Two-sided
  // α = 0.001 per check (4 checks: z = 3.29 bounds at Bonferroni ≈ 0.004).
  const Scene sphere = one_light(R"({"type": "sphere", "center": [0, 3, 0], "radius": 1.2, "material": "lamp"})");
  const Vec3 x{0, 0, 0}, n{0, 1, 0};
  const double e_sphere = pi * 3 * (1.2 / 3) * (1.2 / 3);
  const Scene triangle = one_light(R"({"type": "triangles", "material": "lamp",
      "vertices": [[-1, 1, -0.5], [1.5, 1.5, -0.5], [0, 2, 1.5]], "indices": [[0, 1, 2]]})");
  const Vec3 v[3] = {{-1, 1, -0.5}, {0, 2, 1.5}, {1.5, 1.5, -0.5}};
  double e_triangle = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = normalize(v[i] - x), q = normalize(v[(i + 1) % 3] - x);
    e_triangle += std::acos(dot(p, q)) * dot(n, normalize(cross(p, q)));
  }
  e_triangle = 3 * std::abs(e_triangle) / 2;
  for (LightStrategy strategy : {LightStrategy::area, LightStrategy::solid_angle}) {
    const auto [ms, ss] = irradiance(sphere, x, n, strategy, 100000);
    EXPECT_LT(std::abs(ms - e_sphere), 3.29 * ss + 1e-12) << int(strategy) << ": " << ms << " vs " << e_sphere;
    const auto [mt, st] = irradiance(triangle, x, n, strategy, 100000);
    EXPECT_LT(std::abs(mt - e_triangle), 3.29 * st + 1e-12) << int(strategy) << ": " << mt << " vs " << e_triangle;
  }
  // Solid-angle sampling of a near sphere has the smaller variance (no 1/d² nor cos θ_y in the estimator).
  EXPECT_LT(irradiance(sphere, x, n, LightStrategy::solid_angle, 100000).second,
            irradiance(sphere, x, n, LightStrategy::area, 100000).second);
}

TEST(RenderLightSampling, TinyTrianglesFallBackToAreaSampling) {
  // A triangle of area 5e-9 at distance ~10 (area/d² < 1e-10): solid-angle
  // sampling would be refused, so it samples by area, still unbiased: E ≈ L A
  // cos θ cos θ_y / d² (relative error ~(size/d)² = 1e-10; every sample is
  // within ~1e-5 of it, as the integrand is nearly constant).
  const Scene scene = one_light(R"({"type": "triangles", "material": "lamp",
      "vertices": [[0, 10, 0], [0.0001, 10, 0], [0, 10, 0.0001]], "indices": [[0, 1, 2]]})");
  const Vec3 x{3, 0, 0}, n{0, 1, 0};
  const Vec3 to = Vec3{0, 10, 0} - x;
  const double d2 = dot(to, to), cos_x = to.y / std::sqrt(d2);
  const double expected = 3 * 0.5e-8 * cos_x * cos_x / d2;  // cos θ_y = cos θ_x: the triangle faces down
  const auto [mean, se] = irradiance(scene, x, n, LightStrategy::solid_angle, 1000);
  EXPECT_NEAR(mean, expected, 1e-4 * expected);
  EXPECT_LT(se, 1e-4 * expected);
}

TEST(RenderLightSampling, PdfOfAHitEqualsTheSampledPdf) {
  // What MIS recomputes from a BSDF ray's hit equals the density the sample
  // carried: a moving sphere (solid angle), a 16-gon fan (a triangle mesh) and
  // a moving exact disk (area-sampled under every strategy), the last two
  // under every strategy, each seen at random shutter times. (Not the sphere
  // by area: its hit normal comes from a float hit point, which near the
  // silhouette, where cos θ_y → 0, moves its area density by up to ~1e-5.)
  const Scene scene = parse_scene(R"({"materials": {"lamp": {"reflectance": [0, 0, 0], "emission": [1, 1, 1]}},
      "shapes": [{"type": "sphere", "center": [1, 3, 0], "radius": 0.7, "motion": [0, 0, 1], "material": "lamp"},
                 {"type": "disk", "center": [-2, 2.5, 0], "normal": [0.3, -1, 0], "radius": 0.8, "segments": 16,
                  "material": "lamp"},
                 {"type": "disk", "center": [0.5, 2.8, -1.5], "normal": [-0.2, -1, 0.4], "radius": 0.6,
                  "motion": [0.8, 0, 0.5], "material": "lamp"}]})",
                                  "pdf");
  ASSERT_EQ(scene.lights.size(), 3u);
  ASSERT_EQ(scene.shapes[2].type, ShapeType::disk);
  const Accelerator accelerator(scene);
  const Vec3 x{0, 0, 0}, n{0, 1, 0};
  for (LightStrategy strategy : {LightStrategy::area, LightStrategy::solid_angle, LightStrategy::projected_solid_angle})
    for (const Light& light : scene.lights) {
      if (scene.shapes[light.shape].type == ShapeType::sphere && strategy != LightStrategy::solid_angle) continue;
      int checked = 0;
      for (int i = 0; i < 300; ++i) {
        const double time = uniform01(9, i, 2);
        const auto s = sample_light(scene, light, x, n, time, {uniform01(9, i, 0), uniform01(9, i, 1)}, strategy);
        if (!s) continue;
        const auto hit = accelerator.intersect({x, s->wi, time});
        ASSERT_TRUE(hit);
        ASSERT_EQ(hit->shape, light.shape);
        EXPECT_NEAR(light_pdf(scene, light, x, n, time, s->wi, &*hit, strategy), s->pdf, 1e-6 * s->pdf)
            << int(strategy) << " shape " << light.shape;
        ++checked;
      }
      // Every light faces x: a sample is refused only in a rounding corner case.
      EXPECT_GE(checked, 290) << int(strategy) << " shape " << light.shape;
    }
}

/// A floor lit by a sphere light and a triangle light, with a blocker.
Scene sphere_and_triangle_scene() {
  return parse_scene(R"({
    "camera": {"position": [0, 6, -6], "look_at": [0, 0, 0], "fov": 50, "resolution": [8, 8]},
    "materials": {
      "floor": {"reflectance": [0.7, 0.6, 0.5]},
      "wall": {"reflectance": [0.5, 0.5, 0.5]},
      "lamp": {"reflectance": [0, 0, 0], "emission": [4, 4, 4]},
      "warm": {"reflectance": [0, 0, 0], "emission": [6, 3, 1]}
    },
    "shapes": [
      {"type": "quad", "corner": [-5, 0, 5], "edge_u": [10, 0, 0], "edge_v": [0, 0, -10], "material": "floor"},
      {"type": "quad", "corner": [-1, 1.2, 1], "edge_u": [1.5, 0, 0], "edge_v": [0, 0, -1.5], "material": "wall"},
      {"type": "sphere", "center": [1.5, 2.6, 0.5], "radius": 0.7, "motion": [0, 0, -0.5], "material": "warm"},
      {"type": "triangles", "vertices": [[-3.5, 2.5, 1], [-1.5, 2.5, 3], [-3.5, 1.8, 3]], "indices": [[0, 2, 1]],
       "material": "lamp"}
    ]})",
                     "sphere-triangle");
}

TEST(RenderLightSampling, SolidAngleAndMisImagesConvergeToTheAreaImage) {
  // Independent seeds; per-pixel, per-channel z-tests of the difference,
  // Šidák-corrected at family α = 0.01 over at most 2 × 8 × 8 × 3 tests.
  const Scene scene = sphere_and_triangle_scene();
  RenderSettings s;
  s.integrator = "direct";
  s.light_samples = 4;
  s.sampler.sampler = "random";
  s.sampler.spp = 256;
  s.sampler.seed = 31;
  const Image area = render(scene, s);
  const double alpha = 1 - std::pow(1 - 0.01, 1.0 / (2 * 8 * 8 * 3));
  const double z_max = boost::math::quantile(boost::math::complement(boost::math::normal(), alpha / 2));
  double v_area = 0, v_solid = 0;
  for (const char* strategy : {"solid-angle", "mis"}) {
    s.light_strategy = strategy;
    ++s.sampler.seed;
    const Image image = render(scene, s);
    std::size_t tested = 0;
    for (std::size_t i = 0; i < area.rgb.size(); ++i) {
      const double variance = area.variance[i] + image.variance[i];
      if (variance > 0) {
        EXPECT_LT(std::abs(area.rgb[i] - image.rgb[i]) / std::sqrt(variance), z_max) << strategy << " " << i;
        ++tested;
      } else {
        EXPECT_NEAR(area.rgb[i], image.rgb[i], 1e-12) << strategy << " " << i;
      }
      if (std::string(strategy) == "solid-angle") v_area += area.variance[i], v_solid += image.variance[i];
    }
    EXPECT_GT(tested, 150u) << strategy;
  }
  EXPECT_LT(v_solid, v_area);  // LECTURE.md §3: solid angle removes 1/d² and cos θ_y from the estimator
}

}  // namespace
}  // namespace stratum::render
