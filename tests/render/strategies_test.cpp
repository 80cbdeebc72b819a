// Light strategies and MIS in the integrators (src/render/integrators.cpp,
// lights.cpp): every --light-strategy converges to the same image, and the
// densities MIS uses are those the techniques sample with (so the weights of
// the two techniques sum to 1 at every direction).
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <string>

#include "stratum/estimators/mis.hpp"
#include "stratum/render/bsdf.hpp"
#include "stratum/render/lights.hpp"
#include "stratum/render/render.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {
namespace {

/// A glossy floor under a quad light, a disk light and a triangle light,
/// with a diffuse blocker and a dim sky: every emitter type and both BSDFs.
/// Every emitter is at least 0.6 above any surface: area sampling's 1/d²
/// then stays bounded, so that 256 samples give means close to normal (with
/// lights touching a surface its heavy tail makes the z-test meaningless).
Scene lit_scene() {
  return parse_scene(R"({
    "camera": {"position": [0, 6, -6], "look_at": [0, 0, 0], "fov": 50, "resolution": [8, 8]},
    "materials": {
      "floor": {"type": "glossy", "reflectance": [0.7, 0.6, 0.5], "exponent": 3},
      "wall": {"reflectance": [0.5, 0.5, 0.5]},
      "lamp": {"reflectance": [0, 0, 0], "emission": [4, 4, 4]},
      "warm": {"reflectance": [0, 0, 0], "emission": [6, 3, 1]}
    },
    "shapes": [
      {"type": "quad", "corner": [-5, 0, 5], "edge_u": [10, 0, 0], "edge_v": [0, 0, -10], "material": "floor"},
      {"type": "quad", "corner": [-1, 1.2, 1], "edge_u": [1.5, 0, 0], "edge_v": [0, 0, -1.5], "material": "wall"},
      {"type": "quad", "corner": [-1.5, 3, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2], "material": "lamp"},
      {"type": "disk", "center": [2, 2.4, 1], "normal": [-0.4, -1, 0], "radius": 0.9, "material": "warm"},
      {"type": "triangles", "vertices": [[-3.5, 2.5, 1], [-1.5, 2.5, 3], [-3.5, 1.8, 3]], "indices": [[0, 2, 1]], "material": "lamp"}
    ],
    "lights": [{"type": "environment", "radiance": [0.1, 0.1, 0.1]}]
  })",
                     "lit");
}

RenderSettings settings(const std::string& integrator, const std::string& strategy, std::uint64_t seed) {
  RenderSettings s;
  s.integrator = integrator;
  s.light_strategy = strategy;
  s.light_samples = 4;
  s.max_depth = 3;
  s.sampler.sampler = "random";
  s.sampler.spp = 256;
  s.sampler.seed = seed;
  return s;
}

/// Largest |a − b| / sqrt(var a + var b) over pixels and channels, and how many were tested.
std::pair<double, std::size_t> largest_z(const Image& a, const Image& b) {
  double largest = 0;
  std::size_t tests = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double variance = a.variance[i] + b.variance[i];
    if (variance > 0) {
      const double z = std::abs(a.rgb[i] - b.rgb[i]) / std::sqrt(variance);
      largest = std::max(largest, z);
      ++tests;
    } else {
      EXPECT_NEAR(a.rgb[i], b.rgb[i], 1e-12) << i;  // both exact (the sky seen directly)
    }
  }
  return {largest, tests};
}

TEST(RenderStrategies, EveryLightStrategyConvergesToTheSameImage) {
  // Each strategy against area sampling (independent seeds), per-pixel and
  // per-channel z-tests, Šidák-corrected at family α = 0.01 over at most
  // 7 × 8 × 8 × 3 tests (+1 below). Path tracing with BSDF sampling alone
  // finds the small lights by rare hits at every bounce: with 256 samples its
  // per-pixel means are far from normal and their sample variances unreliable
  // (measured: z up to 8 with 256 spp, below 2.5 with 2048), so it is tested
  // on the image mean (the sum over 192 pixel channels, close to normal).
  const Scene scene = lit_scene();
  const std::size_t tests = 7 * 8 * 8 * 3 + 1;
  const double alpha = 1 - std::pow(1 - 0.01, 1.0 / double(tests));
  const double z_max = boost::math::quantile(boost::math::complement(boost::math::normal(), alpha / 2));
  for (const char* integrator : {"direct", "path"}) {
    const Image reference = render(scene, settings(integrator, "area", 1));
    std::uint64_t seed = 2;
    for (const char* strategy : {"solid-angle", "projected-solid-angle", "bsdf", "mis"}) {
      const Image image = render(scene, settings(integrator, strategy, seed++));
      if (std::string(integrator) == "path" && std::string(strategy) == "bsdf") {
        double difference = 0, variance = 0;
        for (std::size_t i = 0; i < image.rgb.size(); ++i)
          difference += image.rgb[i] - reference.rgb[i], variance += image.variance[i] + reference.variance[i];
        EXPECT_LT(std::abs(difference) / std::sqrt(variance), z_max) << integrator << " " << strategy;
        continue;
      }
      const auto [z, tested] = largest_z(reference, image);
      EXPECT_GT(tested, 120u) << integrator << " " << strategy;
      EXPECT_LT(z, z_max) << integrator << " " << strategy;
    }
  }
}

TEST(RenderStrategies, MisReducesVarianceOnAGlossyFloor) {
  // Veach 1997, ch. 9: MIS is never much worse than the better of its two
  // techniques, and here better than BSDF sampling alone (deterministic: fixed seeds).
  const Scene scene = lit_scene();
  double v_bsdf = 0, v_mis = 0;
  const Image bsdf = render(scene, settings("direct", "bsdf", 4)), mis = render(scene, settings("direct", "mis", 5));
  for (std::size_t i = 0; i < bsdf.rgb.size(); ++i) v_bsdf += bsdf.variance[i], v_mis += mis.variance[i];
  EXPECT_LT(v_mis, v_bsdf);
}

TEST(RenderStrategies, MisWeightsOfTheTwoTechniquesSumToOne) {
  // For light samples that reach their light, the light technique's weight
  // (from the density it sampled with) plus the BSDF technique's weight (from
  // the densities recomputed as if a BSDF ray had found the same point) is 1.
  const Scene scene = lit_scene();
  const Accelerator accelerator(scene);
  const Vec3 x{0.5, 0, -0.5}, n{0, 1, 0};
  const Bsdf bsdf(scene.materials[0], n, normalize(Vec3{0, 6, -6} - x));
  const double lights = double(scene.lights.size()), m = 4, b = 4;
  int checked = 0;
  for (LightStrategy strategy : {LightStrategy::area, LightStrategy::solid_angle, LightStrategy::projected_solid_angle})
    for (const Light& light : scene.lights)
      for (int i = 0; i < 200; ++i) {
        const auto s = sample_light(scene, light, x, n, 0.0, {uniform01(8, i, 0), uniform01(8, i, 1)}, strategy);
        if (!s) continue;
        const auto hit = accelerator.intersect({x, s->wi, 0.0});
        const bool reaches = light.type == LightType::environment ? !hit : hit && hit->shape == light.shape;
        if (!reaches) continue;
        const double pdf_light = light_pdf(scene, light, x, n, 0.0, s->wi, hit ? &*hit : nullptr, strategy);
        EXPECT_NEAR(pdf_light, s->pdf, 1e-6 * s->pdf);
        const double w_light = estimators::power_heuristic(m, s->pdf / lights, b, bsdf.pdf(s->wi));
        const double w_bsdf = estimators::power_heuristic(b, bsdf.pdf(s->wi), m, pdf_light / lights);
        EXPECT_NEAR(w_light + w_bsdf, 1.0, 1e-6);
        ++checked;
      }
  EXPECT_GT(checked, 1000);
}

TEST(RenderStrategies, ProjectedSolidAngleReducesVarianceUnderAnObliqueLight) {
  // A light to the side of the receiver: the cosine varies across it, which
  // the bilinear warp follows (warps/projected_solid_angle.hpp).
  Scene scene = parse_scene(R"({
    "camera": {"position": [0, 3, -3], "look_at": [0, 0, 0], "fov": 30, "resolution": [8, 8]},
    "materials": {"floor": {"reflectance": [0.8, 0.8, 0.8]}, "lamp": {"reflectance": [0, 0, 0], "emission": [5, 5, 5]}},
    "shapes": [
      {"type": "quad", "corner": [-5, 0, 5], "edge_u": [10, 0, 0], "edge_v": [0, 0, -10], "material": "floor"},
      {"type": "quad", "corner": [-2, 0.1, -2], "edge_u": [0, 3, 0], "edge_v": [0, 0, 4], "material": "lamp"}
    ]})",
                            "oblique");
  RenderSettings s = settings("direct", "solid-angle", 6);
  s.sampler.spp = 64;
  const Image solid = render(scene, s);
  s.light_strategy = "projected-solid-angle";
  s.sampler.seed = 7;
  const Image projected = render(scene, s);
  double vs = 0, vp = 0;
  for (std::size_t i = 0; i < solid.rgb.size(); ++i) vs += solid.variance[i], vp += projected.variance[i];
  EXPECT_LT(vp, vs);
}

}  // namespace
}  // namespace stratum::render
