/// Exact disks: Embree user geometry (src/render/disk_geometry.cpp) and the
/// disk area light (lights.cpp), against closed forms and against the
/// inscribed polygon they replace.
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <numbers>
#include <string>

#include "../warps/chi2.hpp"
#include "irradiance_estimate.hpp"
#include "render/disk_geometry.hpp"
#include "stratum/render/accelerator.hpp"
#include "stratum/render/bsdf.hpp"
#include "stratum/render/lights.hpp"
#include "stratum/render/render.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {
namespace {

constexpr double pi = std::numbers::pi;

/// A lamp disk of radius r centred at `center` with unit normal (0, −1, 0)
/// unless given; `extra` adds JSON keys (motion, segments).
Scene disk_scene(double r, Vec3 center, const std::string& extra = "", const std::string& normal = "[0, -1, 0]") {
  const auto num = [](double v) { return std::to_string(v); };
  return parse_scene(R"({"materials": {"lamp": {"reflectance": [0, 0, 0], "emission": [2, 2, 2]}},
    "shapes": [{"type": "disk", "center": [)" +
                         num(center.x) + ", " + num(center.y) + ", " + num(center.z) + R"(], "normal": )" + normal +
                         R"(, "radius": )" + num(r) + extra + R"(, "material": "lamp"}]})",
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
    EXPECT_LT(se, 2e-3 * exact);  // the test has the power to see the polygon's error
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

/// A tilted, moving disk seen off-axis at time 0.5, and the cap around the
/// axis towards it that holds the disk (the χ² bins).
struct MovingDiskView {
  Vec3 normal = normalize(Vec3{-0.3, -1, 0.2});
  Scene scene = disk_scene(0.8, {1, 2.5, 0.5}, R"(, "motion": [1, 0, 0])", "[-0.3, -1, 0.2]");
  Vec3 x{0.3, 0, -0.2}, n{0, 1, 0}, center{1.5, 2.5, 0.5};
  Vec3 axis = normalize(center - x);
  double z_min = cap_z_min();
  Frame frame{axis};

  double cap_z_min() const {
    double z = 1;
    const Frame rim(normal);
    for (int k = 0; k < 3600; ++k) {
      const double phi = 2 * pi * k / 3600;
      z = std::min(z, dot(normalize(center + 0.8 * (std::cos(phi) * rim.s + std::sin(phi) * rim.t) - x), axis));
    }
    return z - 0.01;
  }
};

// Every strategy draws the area density (solid-angle and projected-solid-angle
// fall back to the area sample): one test of the χ² family (tests/warps/chi2.hpp:
// Šidák at family α = 0.01) per strategy, each with its own seed.
struct DiskStrategy {
  const char* name;
  LightStrategy strategy;
  std::uint64_t seed;
};
void PrintTo(const DiskStrategy& c, std::ostream* out) { *out << c.name; }  // ctest's names show the case

class RenderExactDiskChi2 : public testing::Chi2Fixture<::testing::TestWithParam<DiskStrategy>> {};

TEST_P(RenderExactDiskChi2, LightDirectionsFollowTheAreaDensityInSolidAngle) {
  const MovingDiskView v;
  const auto pdf = [&](const double* p) {
    return disk_density(v.center, v.normal, 0.8, v.x, v.frame.to_world({p[0], p[1], p[2]}));
  };
  const auto sample = [&](const double* u, double* out) {
    const auto s = sample_light(v.scene, v.scene.lights[0], v.x, v.n, 0.5, {u[0], u[1]}, GetParam().strategy);
    if (!s) {
      out[0] = out[1] = 0, out[2] = -2;  // in no bin: counted as outside
      return;
    }
    out[0] = dot(s->wi, v.frame.s), out[1] = dot(s->wi, v.frame.t), out[2] = dot(s->wi, v.frame.n);
  };
  testing::Chi2Options options;
  options.samples = 200000;
  options.seed = GetParam().seed;
  options.subdivisions = 8;
  testing::expect_chi2(testing::chi2_test(sample, pdf, testing::Domain::directions(v.z_min, 1, 12, 24), options),
                       GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(Strategies, RenderExactDiskChi2,
                         ::testing::Values(DiskStrategy{"area", LightStrategy::area, 23},
                                           DiskStrategy{"solid-angle", LightStrategy::solid_angle, 24},
                                           DiskStrategy{"projected-solid-angle", LightStrategy::projected_solid_angle,
                                                        25}),
                         [](const auto& info) { return testing::chi2_param_name(info.param.name); });

// Each sample carries the area density, and light_pdf of the hit it leads to agrees (MIS).
TEST(RenderExactDisk, LightSamplesCarryTheirDensityAndLightPdfAgrees) {
  const MovingDiskView v;
  const auto& [normal, scene, x, n, center, axis, z_min, frame] = v;
  const Accelerator accelerator(scene);
  for (int i = 0; i < 500; ++i) {
    const auto s =
        sample_light(scene, scene.lights[0], x, n, 0.5, {uniform01(5, i, 0), uniform01(5, i, 1)}, LightStrategy::area);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->pdf, disk_density(center, normal, 0.8, x, s->wi), 1e-9 * s->pdf);
    const auto hit = accelerator.intersect({x, s->wi, 0.5});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, s->distance, 1e-5 * s->distance);
    for (LightStrategy strategy :
         {LightStrategy::area, LightStrategy::solid_angle, LightStrategy::projected_solid_angle})
      EXPECT_NEAR(light_pdf(scene, scene.lights[0], x, n, 0.5, s->wi, &*hit, strategy), s->pdf, 1e-5 * s->pdf);
  }
}

TEST(RenderExactDisk, EmbreeSeesTheRimToOnePartInABillion) {
  // Embree's rays are float, but the disk stays in double: a vertical ray
  // whose float origin lies at exactly ρ from the axis hits the disk of
  // radius ρ(1 + 1e-9) and misses the disk of radius ρ(1 − 1e-9).
  for (int k = 0; k < 8; ++k) {
    const double phi = 2 * pi * (k + 0.21) / 8;
    const Vec3 origin{double(float(1.3 * std::cos(phi))), 0, double(float(1.3 * std::sin(phi)))};
    const double rho = std::hypot(origin.x, origin.z);
    Scene wider = disk_scene(1, {0, 2, 0}), narrower = disk_scene(1, {0, 2, 0});
    wider.shapes[0].radius = rho * (1 + 1e-9);  // set in double: JSON text via to_string would round it
    narrower.shapes[0].radius = rho * (1 - 1e-9);
    const Accelerator a(wider), b(narrower);
    const Ray ray{origin, {0, 1, 0}, 0};
    const auto hit = a.intersect(ray);
    ASSERT_TRUE(hit) << k;
    EXPECT_EQ(hit->t, 2.0);  // the plane y = 2, exactly
    EXPECT_TRUE(a.occluded(ray));
    EXPECT_FALSE(b.intersect(ray)) << k;
    EXPECT_FALSE(b.occluded(ray)) << k;
  }
}

TEST(RenderExactDisk, RandomRaysAgreeWithTheClosedForm) {
  // A tilted disk moving over the shutter, shape 1 between a quad and a
  // sphere that no ray reaches first. Rays from below and above at random
  // times towards points within 1.3 r of the disk's centre at that time. The
  // oracle solves the ray in the disk's own frame: height along the normal
  // goes to zero at t* = −h₀/h', and the hit is inside when the in-plane
  // offset at t* is below r. Rays are built in float (what Embree sees).
  const Scene scene = parse_scene(R"({"materials": {"m": {}},
    "shapes": [{"type": "quad", "corner": [50, -1, -1], "edge_u": [0, 2, 0], "edge_v": [0, 0, 2], "material": "m"},
               {"type": "disk", "center": [0.4, 2, -0.3], "normal": [0.5, -1, 0.25], "radius": 0.9,
                "motion": [0.6, 0.2, -0.4], "material": "m"},
               {"type": "sphere", "center": [-50, 0, 0], "radius": 1, "material": "m"}]})",
                                  "random-rays");
  const Shape& disk = scene.shapes[1];
  const Frame local(disk.normal);
  const Accelerator accelerator(scene);
  // Rounded to float through a volatile store: with a plain double(float(v))
  // this file's GCC 12 -O3 build was seen to keep unrounded origins.
  const auto f = [](double v) {
    volatile float rounded = float(v);
    return double(rounded);
  };
  int hits = 0, misses = 0;
  for (int i = 0; i < 4000; ++i) {
    const auto u = [&](int d) { return uniform01(77, i, d); };
    const double time = f(u(0));
    const Vec3 c = disk.center + time * disk.motion;
    const double above = i % 2 == 0 ? 1 : -1;  // origins on both sides of the disk
    const Vec3 origin{f(c.x + 4 * u(1) - 2), f(c.y + above * (1 + 2 * u(2))), f(c.z + 4 * u(3) - 2)};
    const double rho = 1.3 * disk.radius * std::sqrt(u(4)), phi = 2 * pi * u(5);
    const Vec3 target = c + rho * (std::cos(phi) * local.s + std::sin(phi) * local.t);
    const Vec3 direction{f(target.x - origin.x), f(target.y - origin.y), f(target.z - origin.z)};
    // The oracle, in the disk's frame.
    const Vec3 o = origin - c;
    const double h0 = dot(o, local.n), slope = dot(direction, local.n);
    const double t_star = -h0 / slope;
    const double ps = dot(o, local.s) + t_star * dot(direction, local.s);
    const double pt = dot(o, local.t) + t_star * dot(direction, local.t);
    const double radial = std::sqrt(ps * ps + pt * pt) / disk.radius;
    if (std::abs(radial - 1) < 1e-5) continue;  // within float rounding of the rim
    const Ray ray{origin, direction, time};
    const auto hit = accelerator.intersect(ray);
    if (radial < 1) {
      ++hits;
      ASSERT_TRUE(hit) << i;
      EXPECT_EQ(hit->shape, 1u) << i;
      EXPECT_EQ(hit->primitive, 0u);
      EXPECT_NEAR(hit->t, t_star, 1e-6 * t_star) << i;
      EXPECT_EQ(hit->normal.x, disk.normal.x);
      EXPECT_EQ(hit->normal.y, disk.normal.y);
      EXPECT_EQ(hit->normal.z, disk.normal.z);
      EXPECT_TRUE(accelerator.occluded({origin, direction, time, t_star * (1 + 1e-4)})) << i;
      EXPECT_FALSE(accelerator.occluded({origin, direction, time, t_star * (1 - 1e-4)})) << i;
    } else {
      ++misses;
      EXPECT_TRUE(!hit || hit->shape != 1u) << i;
      EXPECT_FALSE(accelerator.occluded({origin, direction, time, 2 * t_star})) << i;
    }
  }
  EXPECT_GT(hits, 1500);
  EXPECT_GT(misses, 700);
}

TEST(RenderExactDisk, DirectIntegratorMatchesTheClosedFormIrradiance) {
  // A camera looks at the point of a diffuse floor (albedo ρ) on the axis of
  // a lamp disk (radius r, height h, radiance L). Its radiance is ρ/π times
  // the irradiance E = π L r²/(h² + r²). One pixel rendered through its
  // centre by the direct integrator, every strategy: the z-score of the
  // pixel against ρ L r²/(h² + r²) stays below the two-sided Šidák bound
  // for family α = 0.01 over the 5 strategies.
  const double r = 1.5, h = 2, le = 2, rho = 0.5, exact = rho * le * r * r / (h * h + r * r);
  const Scene scene = parse_scene(R"({
    "camera": {"position": [3, 1, 0.5], "look_at": [0, 0, 0], "fov": 10, "resolution": [1, 1]},
    "materials": {"floor": {"reflectance": [0.5, 0.5, 0.5]},
                  "lamp": {"reflectance": [0, 0, 0], "emission": [2, 2, 2]}},
    "shapes": [{"type": "quad", "corner": [-5, 0, 5], "edge_u": [10, 0, 0], "edge_v": [0, 0, -10], "material": "floor"},
               {"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 1.5, "material": "lamp"}]})",
                                  "direct-oracle");
  const char* strategies[] = {"area", "solid-angle", "projected-solid-angle", "bsdf", "mis"};
  const double alpha = testing::sidak_alpha(0.01, static_cast<int>(std::size(strategies)));
  const double z = boost::math::quantile(boost::math::complement(boost::math::normal(), alpha / 2));
  RenderSettings s;
  s.integrator = "direct";
  s.light_samples = 4;
  s.sampler.sampler = "random";
  s.sampler.spp = 32768;
  s.pixel_centers = true;
  for (const char* strategy : strategies) {
    s.light_strategy = strategy;
    ++s.sampler.seed;
    const Image image = render(scene, s);
    const double mean = image.rgb[0], se = std::sqrt(image.variance[0]);
    EXPECT_LT(se, 5e-3 * exact) << strategy;  // the power to see a 2% error (the 16-gon's is 2.6%)
    EXPECT_LT(std::abs(mean - exact), z * se) << strategy << ": " << mean << " vs " << exact << " ± " << se;
  }
}

TEST(RenderExactDisk, BadValuesAreRefusedByName) {
  const auto message = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto json_disk = [](const std::string& normal, const std::string& radius) {
    return parse_scene(R"({"materials": {"m": {}}, "shapes": [{"type": "disk", "center": [0, 0, 0], "normal": )" +
                           normal + R"(, "radius": )" + radius + R"(, "material": "m"}]})",
                       "bad");
  };
  EXPECT_NE(message([&] { json_disk("[0, 1, 0]", "0"); }).find("shapes[0].radius = 0"), std::string::npos);
  EXPECT_NE(message([&] { json_disk("[0, 1, 0]", "-2"); }).find("shapes[0].radius = -2"), std::string::npos);
  EXPECT_NE(message([&] { json_disk("[0, 0, 0]", "1"); }).find("shapes[0].normal"), std::string::npos);
  EXPECT_NE(message([&] { json_disk("[0, 1]", "1"); }).find("shapes[0].normal"), std::string::npos);
  EXPECT_NE(message([&] { json_disk("[0, 1, 0]", "1e999"); }).find("not finite"), std::string::npos);
  EXPECT_NE(message([&] { json_disk("[0, \"up\", 0]", "1"); }).find("shapes[0].normal[1]"), std::string::npos);
  // Huge and tiny normals are directions like any other (no overflow to inf or underflow to 0).
  EXPECT_NEAR(json_disk("[1e300, -1e300, 0]", "1").shapes[0].normal.x, std::sqrt(0.5), 1e-15);
  EXPECT_EQ(json_disk("[0, -1e-310, 0]", "1").shapes[0].normal.y, -1);
  // Through the C++ API, NaN and Inf reach validate_scene, which names the field.
  const auto validated = [&](const std::function<void(Shape&)>& spoil) {
    return message([&] {
      Scene scene = json_disk("[0, 1, 0]", "1");
      spoil(scene.shapes[0]);
      validate_scene(scene);
    });
  };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(validated([&](Shape& d) { d.radius = nan; }).find("shapes[0].radius = nan"), std::string::npos);
  EXPECT_NE(validated([&](Shape& d) { d.radius = inf; }).find("shapes[0].radius = inf"), std::string::npos);
  EXPECT_NE(validated([&](Shape& d) { d.normal.y = nan; }).find("shapes[0].normal"), std::string::npos);
  EXPECT_NE(validated([&](Shape& d) { d.normal = {0, 2, 0}; }).find("shapes[0].normal = 2"), std::string::npos);
  EXPECT_NE(validated([&](Shape& d) { d.center.z = inf; }).find("shapes[0].center"), std::string::npos);
  EXPECT_NE(validated([&](Shape& d) { d.motion.x = nan; }).find("shapes[0].motion"), std::string::npos);
  EXPECT_EQ(validated([](Shape&) {}), "no error");
}

TEST(RenderExactDisk, TheBackSideNeitherEmitsNorHasADensity) {
  // Seen from above, a lamp facing down gives no sample and no density.
  const Scene scene = disk_scene(1, {0, 2, 0});
  const Accelerator accelerator(scene);
  const Vec3 x{0.2, 4, 0.1}, n{0, -1, 0};
  for (LightStrategy strategy :
       {LightStrategy::area, LightStrategy::solid_angle, LightStrategy::projected_solid_angle}) {
    for (int i = 0; i < 100; ++i)
      EXPECT_FALSE(sample_light(scene, scene.lights[0], x, n, 0, {uniform01(8, i, 0), uniform01(8, i, 1)}, strategy));
    const Vec3 wi = normalize(Vec3{0.1, -1, 0.05});
    const auto hit = accelerator.intersect({x, wi, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(light_pdf(scene, scene.lights[0], x, n, 0, wi, &*hit, strategy), 0.0);
  }
}

}  // namespace
}  // namespace stratum::render
