// The renderer end to end (src/render/render.cpp, integrators.cpp):
// closed-form furnaces, thread-count determinism, and agreement of light
// strategies by per-pixel z-tests.
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>

#include "stratum/render/render.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {
namespace {

/// A diffuse sphere of albedo rho under a constant sky of radiance 1, seen
/// from a pinhole. A convex surface never sees itself, so the reflected
/// radiance is exactly rho·1 (the white furnace, Pharr et al. §13.4), and
/// with cosine-weighted sampling of the sky each sample is exact.
Scene furnace(double rho) {
  Scene scene;
  scene.camera.position = {0, 0, -4};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.fov_degrees = 40;
  scene.camera.width = scene.camera.height = 16;
  scene.materials = {{"grey", MaterialType::diffuse, {rho, rho, rho}, {}}};
  Shape ball;
  ball.type = ShapeType::sphere;
  ball.radius = 1;
  scene.shapes.push_back(ball);
  scene.lights.push_back(Light{LightType::environment, 0, {}, {}, {1, 1, 1}});
  validate_scene(scene);
  return scene;
}

RenderSettings settings(std::string integrator, std::uint32_t spp) {
  RenderSettings s;
  s.integrator = std::move(integrator);
  s.sampler.sampler = "random";
  s.sampler.spp = spp;
  s.sampler.seed = 3;
  return s;
}

TEST(Render, FurnaceIsExactForEveryIntegrator) {
  const Scene scene = furnace(0.6);
  for (const char* integrator : {"direct", "irradiance", "path"}) {
    RenderSettings s = settings(integrator, 4);
    s.light_samples = 2;
    const Image image = render(scene, s);
    // The centre pixels see only the sphere, the corners only the sky.
    for (int y = 7; y <= 8; ++y)
      for (int x = 7; x <= 8; ++x)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.rgb[3 * (y * 16 + x) + c], 0.6, 1e-9) << integrator;
    EXPECT_NEAR(image.rgb[0], 1.0, 1e-12) << integrator;
    EXPECT_NEAR(image.rgb[3 * 255], 1.0, 1e-12) << integrator;
  }
}

/// A quad light over a floor with a blocker between them: soft shadows.
Scene soft_shadow_scene() {
  Scene scene;
  scene.camera.position = {0, 6, -6};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.fov_degrees = 50;
  scene.camera.width = scene.camera.height = 12;
  scene.materials = {{"floor", MaterialType::diffuse, {0.8, 0.8, 0.8}, {}},
                     {"lamp", MaterialType::diffuse, {0, 0, 0}, {5, 5, 5}}};
  Shape floor;
  floor.type = ShapeType::quad;
  floor.corner = {-5, 0, 5};
  floor.edge_u = {10, 0, 0};
  floor.edge_v = {0, 0, -10};
  scene.shapes.push_back(floor);
  Shape blocker = floor;
  blocker.corner = {-1, 1.5, 1};
  blocker.edge_u = {2, 0, 0};
  blocker.edge_v = {0, 0, -2};
  scene.shapes.push_back(blocker);
  Shape lamp;
  lamp.type = ShapeType::quad;
  lamp.material = 1;
  lamp.corner = {-1, 3, -1};
  lamp.edge_u = {2, 0, 0};  // edge_u × edge_v = −y: emits downwards
  lamp.edge_v = {0, 0, 2};
  scene.shapes.push_back(lamp);
  validate_scene(scene);
  return scene;
}

TEST(Render, SameImageWithOneOrTwoThreads) {
  const Scene scene = soft_shadow_scene();
  RenderSettings s = settings("path", 8);
  s.sampler.sampler = "sobol";
  s.light_samples = 2;
  const Image one = render(scene, s);
  s.threads = 2;
  const Image two = render(scene, s);
  EXPECT_EQ(one.rgb, two.rgb);
}

/// A BVH built once serves several renders (compare's configurations) and
/// gives the images render(scene, …) gives: its scene, its seeds.
TEST(Render, PrebuiltBvhGivesTheSameImages) {
  Scene small = cornell_box();
  small.camera.width = small.camera.height = 12;
  const Accelerator accelerator(small);
  EXPECT_EQ(&accelerator.scene(), &small);
  for (const char* integrator : {"direct", "path"}) {
    RenderSettings s = settings(integrator, 4);
    s.passes = 2;
    const Image built = render(small, s);
    const Image shared = render(accelerator, s);
    EXPECT_EQ(shared.rgb, built.rgb) << integrator;
    EXPECT_EQ(shared.variance, built.variance) << integrator;
    EXPECT_EQ(shared.samples, built.samples) << integrator;
    s.sampler.seed = 4;  // another seed on the same BVH: another image
    EXPECT_NE(render(accelerator, s).rgb, built.rgb) << integrator;
  }
  RenderSettings bad = settings("direct", 0);
  EXPECT_THROW(render(accelerator, bad), invalid_argument);
}

TEST(Render, AreaAndSolidAngleSamplingAgree) {
  // Per-pixel z-tests of the difference of two independent estimates;
  // Šidák-corrected two-sided α = 0.01 over every pixel and channel tested.
  const Scene scene = soft_shadow_scene();
  RenderSettings area = settings("direct", 64);
  area.light_samples = 4;
  RenderSettings solid = area;
  solid.light_strategy = "solid-angle";
  solid.sampler.seed = 11;
  const Image a = render(scene, area), b = render(scene, solid);
  std::size_t tests = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) tests += a.variance[i] + b.variance[i] > 0;
  ASSERT_GT(tests, 100u);
  const double alpha = 1 - std::pow(1 - 0.01, 1.0 / double(tests));
  const double z_max = boost::math::quantile(boost::math::complement(boost::math::normal(), alpha / 2));
  double largest = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double variance = a.variance[i] + b.variance[i];
    if (variance > 0) largest = std::max(largest, std::abs(a.rgb[i] - b.rgb[i]) / std::sqrt(variance));
    else EXPECT_EQ(a.rgb[i], b.rgb[i]) << i;  // both exact (unlit or background)
  }
  EXPECT_LT(largest, z_max);
  // Solid-angle sampling has the lower variance over the lit floor (LECTURE.md §3).
  double va = 0, vb = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) va += a.variance[i], vb += b.variance[i];
  EXPECT_LT(vb, va);
}

TEST(Render, BadSettingsAreNamed) {
  const Scene scene = furnace(0.5);
  RenderSettings s = settings("bidirectional", 4);
  EXPECT_THROW(render(scene, s), invalid_argument);
  s = settings("direct", 4);
  s.light_strategy = "cone";
  EXPECT_THROW(render(scene, s), invalid_argument);
  s = settings("direct", 0);
  EXPECT_THROW(render(scene, s), invalid_argument);
  // Jittered shadow-ray arrays need a square count: refused before rendering, naming --light-samples.
  s = settings("direct", 4);
  s.sampler.sampler = "jittered";
  s.light_samples = 3;
  try {
    render(scene, s);
    ADD_FAILURE() << "no error";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("light-samples = 3"), std::string::npos) << e.what();
  }
  s.light_samples = 4;
  EXPECT_NO_THROW(render(scene, s));
}

}  // namespace
}  // namespace stratum::render
