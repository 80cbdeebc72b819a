/// Exact disks: Embree user geometry (src/render/disk_geometry.cpp) and the
/// disk area light (lights.cpp), against closed forms and against the
/// inscribed polygon they replace.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "../warps/chi2.hpp"
#include "irradiance_estimate.hpp"
#include "render/disk_geometry.hpp"
#include "stratum/render/accelerator.hpp"
#include "stratum/render/bsdf.hpp"
#include "stratum/render/lights.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {
namespace {

constexpr double pi = std::numbers::pi;

// The χ² test of this file: 1, at the Šidák level for family α = 0.01.
constexpr int chi2_tests_here = 1;

/// A lamp disk of radius r centred at `center` with unit normal (0, −1, 0)
/// unless given; `extra` adds JSON keys (motion, segments).
Scene disk_scene(double r, Vec3 center, const std::string& extra = "", const std::string& normal = "[0, -1, 0]") {
  const auto num = [](double v) { return std::to_string(v); };
  return parse_scene(R"({"materials": {"lamp": {"reflectance": [0, 0, 0], "emission": [2, 2, 2]}},
    "shapes": [{"type": "disk", "center": [)" + num(center.x) + ", " + num(center.y) + ", " + num(center.z) +
                         R"(], "normal": )" + normal + R"(, "radius": )" + num(r) + extra +
                         R"(, "material": "lamp"}]})",
                     "disk");
}

/// A ray straight up (+y) from the floor y = 0 at polar (ρ, φ) in the xz plane.
Ray upward(double rho, double phi, double time = 0) {
  return {{rho * std::cos(phi), 0, rho * std::sin(phi)}, {0, 1, 0}, time};
}

TEST(RenderExactDisk, IsReadAsOneExactShapeUnlessSegmentsAreGiven) {
  const Scene exact = disk_scene(1.5, {0, 2, 0}, "", "[0, -3, 0]");
  ASSERT_EQ(exact.shapes[0].type, ShapeType::disk);
  EXPECT_EQ(exact.shapes[0].normal.y, -1);  // normalized
  EXPECT_DOUBLE_EQ(shape_area(exact.shapes[0]), pi * 1.5 * 1.5);
  EXPECT_EQ(disk_scene(1.5, {0, 2, 0}, R"(, "segments": 12)").shapes[0].type, ShapeType::triangles);
  const auto message = [](const std::string& radius, const std::string& normal) {
    try {
      parse_scene(R"({"materials": {"m": {}}, "shapes": [{"type": "disk", "center": [0, 0, 0], "normal": )" + normal +
                      R"(, "radius": )" + radius + R"(, "material": "m"}]})",
                  "bad");
    } catch (const invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("0", "[0, 1, 0]").find("radius"), std::string::npos);
  EXPECT_NE(message("-1", "[0, 1, 0]").find("radius"), std::string::npos);
  EXPECT_NE(message("1", "[0, 0, 0]").find("normal"), std::string::npos);
}

TEST(RenderExactDisk, IntersectionIsExactAtTheRim) {
  const Scene scene = disk_scene(1.5, {0, 2, 0});
  const Shape& disk = scene.shapes[0];
  // In double: just inside and just outside the rim, in every direction.
  for (int k = 0; k < 16; ++k) {
    const double phi = 2 * pi * (k + 0.37) / 16;
    EXPECT_NEAR(intersect_disk(disk, upward(1.5 * (1 - 1e-12), phi).origin, {0, 1, 0}, 0), 2.0, 1e-15);
    EXPECT_LT(intersect_disk(disk, upward(1.5 * (1 + 1e-12), phi).origin, {0, 1, 0}, 0), 0);
  }
  EXPECT_LT(intersect_disk(disk, {0, 0, 0}, {1, 0, 0}, 0), 0);  // parallel to the plane
  // Through Embree (rays in float: a margin of 1e-6 of the radius).
  const Accelerator accelerator(scene);
  for (int k = 0; k < 16; ++k) {
    const double phi = 2 * pi * (k + 0.37) / 16;
    const auto hit = accelerator.intersect(upward(1.5 * (1 - 1e-6), phi));
    ASSERT_TRUE(hit) << k;
    EXPECT_NEAR(hit->t, 2.0, 1e-6);
    EXPECT_EQ(hit->shape, 0u);
    EXPECT_EQ(hit->normal.y, -1);  // the shape's orientation, not flipped towards the ray
    EXPECT_FALSE(accelerator.intersect(upward(1.5 * (1 + 1e-6), phi))) << k;
    EXPECT_TRUE(accelerator.occluded(upward(1.5 * (1 - 1e-6), phi)));
    EXPECT_FALSE(accelerator.occluded(upward(1.5 * (1 + 1e-6), phi)));
  }
  // From above, the hit has the same normal; a ray stopping short is not occluded.
  const auto down = accelerator.intersect({{0.3, 5, 0.2}, {0, -1, 0}, 0});
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->t, 3.0, 1e-6);
  EXPECT_EQ(down->normal.y, -1);
  EXPECT_FALSE(accelerator.occluded({{0.3, 0, 0.2}, {0, 1, 0}, 0, 1.9}));
}

TEST(RenderExactDisk, CoversWhatTheInscribedPolygonMisses) {
  // Between two vertices of the 64-gon its edge lies at r cos(π/64) ≈ 0.9988 r.
  const Scene exact = disk_scene(1.5, {0, 2, 0});
  const Scene polygon = disk_scene(1.5, {0, 2, 0}, R"(, "segments": 64)");
  const Accelerator a(exact), b(polygon);
  const Ray ray = upward(1.5 * 0.9995, pi / 64);
  EXPECT_TRUE(a.intersect(ray));
  EXPECT_FALSE(b.intersect(ray));
}

TEST(RenderExactDisk, MovesLinearlyOverTheShutter) {
  const Scene scene = disk_scene(1.5, {0, 2, 0}, R"(, "motion": [2, 0, 0])");
  const Accelerator accelerator(scene);
  // The centre moves from x = 0 (open) to x = 2 (close). A ray at x = 2.35
  // misses at open (2.35 > r = 1.5) and hits at 0.5 (1.35) and at close (0.35).
  const Ray at_half{{1 + 0.9 * 1.5, 0, 0}, {0, 1, 0}, 0.5};
  EXPECT_TRUE(accelerator.intersect(at_half));
  EXPECT_FALSE(accelerator.intersect({at_half.origin, at_half.direction, 0.0}));
  EXPECT_TRUE(accelerator.intersect({at_half.origin, at_half.direction, 1.0}));
  EXPECT_FALSE(accelerator.intersect({{-1.4, 0, 0}, {0, 1, 0}, 1.0}));  // left behind at close
  EXPECT_TRUE(accelerator.intersect({{-1.4, 0, 0}, {0, 1, 0}, 0.0}));
}

std::pair<double, double> irradiance(const Scene& scene, Vec3 x, Vec3 n, LightStrategy strategy, int samples) {
  return testing_support::irradiance(scene, x, n, strategy, samples, 31);
}

TEST(RenderExactDisk, IrradianceOnTheAxisMatchesTheClosedForm) {
  // A Lambertian disk of radiance L and radius r at height h over a point
  // facing it: E = π L r² / (h² + r²), with no polygon error now.
  const double r = 1.5, h = 2, le = 2, exact = pi * le * r * r / (h * h + r * r);
  const Scene disk = disk_scene(r, {0, h, 0});
  const Scene polygon = disk_scene(r, {0, h, 0}, R"(, "segments": 16)");
  for (LightStrategy strategy : {LightStrategy::area, LightStrategy::solid_angle}) {
    const auto [mean, se] = irradiance(disk, {0, 0, 0}, {0, 1, 0}, strategy, 200000);
    EXPECT_LT(se, 2e-3 * exact);                          // the test has the power to see the polygon's error
    EXPECT_LT(std::abs(mean - exact), 3.29 * se) << mean << " vs " << exact;  // two-sided α = 0.001
  }
  // The 16-gon lacks 2.6% of the area: its irradiance is visibly below E.
  const auto [fan, fan_se] = irradiance(polygon, {0, 0, 0}, {0, 1, 0}, LightStrategy::area, 200000);
  EXPECT_GT(exact - fan, 10 * fan_se);
}

/// Solid-angle density of the area-uniform disk sample, computed naively:
/// where the ray x + t w meets the disk, d² / (cos θ_y π r²), else 0.
double disk_density(Vec3 c, Vec3 normal, double r, Vec3 x, Vec3 w) {
  const double along = dot(w, normal);
  if (along >= 0) return 0;  // the emitting side faces x
  const double t = dot(c - x, normal) / along;
  const Vec3 y = x + t * w;
  if (t <= 0 || length(y - c) > r) return 0;
  return t * t / (-along * pi * r * r);
}

TEST(RenderExactDisk, LightDirectionsFollowTheAreaDensityInSolidAngle) {
  // A tilted, moving disk seen off-axis at time 0.5.
  const Vec3 normal = normalize(Vec3{-0.3, -1, 0.2});
  const Scene scene = disk_scene(0.8, {1, 2.5, 0.5}, R"(, "motion": [1, 0, 0])", "[-0.3, -1, 0.2]");
  const Vec3 x{0.3, 0, -0.2}, n{0, 1, 0}, center{1.5, 2.5, 0.5};
  const Vec3 axis = normalize(center - x);
  double z_min = 1;  // the cap around the axis that holds the disk
  const Frame rim(normal);
  for (int k = 0; k < 3600; ++k) {
    const double phi = 2 * pi * k / 3600;
    z_min = std::min(z_min, dot(normalize(center + 0.8 * (std::cos(phi) * rim.s + std::sin(phi) * rim.t) - x), axis));
  }
  z_min -= 0.01;
  const Frame frame(axis);
  const auto sample = [&](const double* u, double* out) {
    const auto s = sample_light(scene, scene.lights[0], x, n, 0.5, {u[0], u[1]}, LightStrategy::solid_angle);
    if (!s) {
      out[0] = out[1] = 0, out[2] = -2;  // in no bin: counted as outside
      return;
    }
    out[0] = dot(s->wi, frame.s), out[1] = dot(s->wi, frame.t), out[2] = dot(s->wi, frame.n);
  };
  const auto pdf = [&](const double* p) { return disk_density(center, normal, 0.8, x, frame.to_world({p[0], p[1], p[2]})); };
  testing::Chi2Options options;
  options.samples = 200000;
  options.seed = 23;
  options.subdivisions = 8;
  const auto result = testing::chi2_test(sample, pdf, testing::Domain::directions(z_min, 1, 12, 24), options);
  EXPECT_GT(result.p_value, testing::sidak_alpha(0.01, chi2_tests_here)) << result.table;
  // Each sample carries that density, and light_pdf of the hit it leads to agrees (MIS).
  const Accelerator accelerator(scene);
  for (int i = 0; i < 500; ++i) {
    const auto s = sample_light(scene, scene.lights[0], x, n, 0.5, {uniform01(5, i, 0), uniform01(5, i, 1)},
                                LightStrategy::area);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->pdf, disk_density(center, normal, 0.8, x, s->wi), 1e-9 * s->pdf);
    const auto hit = accelerator.intersect({x, s->wi, 0.5});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, s->distance, 1e-5 * s->distance);
    for (LightStrategy strategy : {LightStrategy::area, LightStrategy::solid_angle, LightStrategy::projected_solid_angle})
      EXPECT_NEAR(light_pdf(scene, scene.lights[0], x, n, 0.5, s->wi, &*hit, strategy), s->pdf, 1e-5 * s->pdf);
  }
}

}  // namespace
}  // namespace stratum::render
