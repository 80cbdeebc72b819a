// Shapes from scene files (src/render/obj.cpp, scene_json.cpp): OBJ meshes
// and their errors, disk lights against the closed-form irradiance of a
// disk, and motion blur against the closed-form coverage of a moving edge.
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

#include "stratum/render/lights.hpp"
#include "stratum/render/obj.hpp"
#include "stratum/render/render.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {
namespace {

constexpr double pi = std::numbers::pi;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(RenderObj, ReadsVerticesAndFaces) {
  const ObjMesh mesh = parse_obj(
      "# a unit square and a triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
      "o square\nf 1/1/1 2/1/1 3//1 4\nv 2 0 0  # fifth\nf -1 2 3\n",
      "mem.obj");
  ASSERT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.vertices[4].x, 2);
  ASSERT_EQ(mesh.triangles.size(), 3u);  // the quad as a fan of two, then one
  EXPECT_EQ(mesh.triangles[0], (std::array<unsigned, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (std::array<unsigned, 3>{0, 2, 3}));
  EXPECT_EQ(mesh.triangles[2], (std::array<unsigned, 3>{4, 1, 2}));
}

TEST(RenderObj, ErrorsNameTheFileAndLine) {
  EXPECT_NE(message_of([] { parse_obj("v 0 0 0\nv 1 0 0\nf 1 2 7\n", "a.obj"); }).find("a.obj, line 3"),
            std::string::npos);
  EXPECT_NE(message_of([] { parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 0 2\n", "a.obj"); }).find("line 4"),
            std::string::npos);
  EXPECT_NE(message_of([] { parse_obj("v 0 zero 0\n", "a.obj"); }).find("line 1"), std::string::npos);
  EXPECT_NE(message_of([] { parse_obj("v 0 0 0\nbezier 1\n", "a.obj"); }).find("bezier"), std::string::npos);
  EXPECT_NE(message_of([] { parse_obj("v 0 0 0\nf 1 1\n", "a.obj"); }).find("at least 3"), std::string::npos);
  EXPECT_NE(message_of([] { parse_obj("v 0 0 0\n", "a.obj"); }).find("no faces"), std::string::npos);
  EXPECT_NE(message_of([] { read_obj("/nonexistent/x.obj"); }).find("/nonexistent/x.obj"), std::string::npos);
}

TEST(RenderObj, SceneMeshesAreRelativeToTheSceneFile) {
  const auto dir = std::filesystem::temp_directory_path() / ("stratum-obj-" + std::to_string(hash64(17, ::getpid())));
  std::filesystem::create_directories(dir / "meshes");
  std::ofstream(dir / "meshes" / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string scene_text =
      R"({"materials": {"m": {}}, "shapes": [{"type": "mesh", "file": "meshes/tri.obj", "material": "m"}]})";
  std::ofstream(dir / "scene.json") << scene_text;
  std::ofstream(dir / "missing.json")
      << R"({"materials": {"m": {}}, "shapes": [{"type": "mesh", "file": "no.obj", "material": "m"}]})";
  const Scene scene = load_scene((dir / "scene.json").string());
  ASSERT_EQ(scene.shapes.size(), 1u);
  EXPECT_EQ(scene.shapes[0].type, ShapeType::triangles);
  EXPECT_EQ(scene.shapes[0].indices.size(), 1u);
  EXPECT_NEAR(shape_area(scene.shapes[0]), 0.5, 1e-15);
  EXPECT_NE(message_of([&] { load_scene((dir / "missing.json").string()); }).find("no.obj"), std::string::npos);
  std::filesystem::remove_all(dir);
}

Scene disk_scene(double radius, double height, int segments) {
  return parse_scene(R"({"materials": {"lamp": {"reflectance": [0, 0, 0], "emission": [2, 2, 2]}},
    "shapes": [{"type": "disk", "center": [0, )" +
                         std::to_string(height) + R"(, 0], "normal": [0, -1, 0], "radius": )" + std::to_string(radius) +
                         R"(, "segments": )" + std::to_string(segments) + R"(, "material": "lamp"}]})",
                     "disk");
}

TEST(RenderDisk, IsAnInscribedPolygonFacingItsNormal) {
  const Scene scene = disk_scene(1.5, 2, 12);
  const Shape& disk = scene.shapes[0];
  ASSERT_EQ(disk.indices.size(), 12u);
  EXPECT_NEAR(shape_area(disk), 0.5 * 12 * 1.5 * 1.5 * std::sin(2 * pi / 12), 1e-12);
  for (const auto& t : disk.indices) {
    const Vec3 n =
        normalize(cross(disk.vertices[t[1]] - disk.vertices[t[0]], disk.vertices[t[2]] - disk.vertices[t[0]]));
    EXPECT_NEAR(n.y, -1, 1e-12);
  }
  EXPECT_THROW(
      parse_scene(
          R"({"materials": {"m": {}}, "shapes": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 0], "radius": 1, "material": "m"}]})",
          "d"),
      invalid_argument);
}

TEST(RenderDisk, IrradianceOnTheAxisMatchesTheClosedForm) {
  // A Lambertian disk of radiance L and radius r at height h over a point
  // facing it: E = π L r² / (h² + r²). The 1024-gon inscribed in the disk
  // lacks a relative 1 − sin(2π/N)/(2π/N) ≈ 6e-6 of the area (bound used below).
  const double r = 1.5, h = 2, le = 2;
  const Scene scene = disk_scene(r, h, 1024);
  const double exact = pi * le * r * r / (h * h + r * r);
  const Vec3 x{0, 0, 0}, n{0, 1, 0};
  const int samples = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < samples; ++i) {
    const auto s =
        sample_light(scene, scene.lights[0], x, n, 0, {uniform01(4, i, 0), uniform01(4, i, 1)}, LightStrategy::area);
    const double v = s ? s->radiance.x * std::max(0.0, dot(n, s->wi)) / s->pdf : 0.0;
    sum += v, sum2 += v * v;
  }
  const double mean = sum / samples, se = std::sqrt((sum2 / samples - mean * mean) / (samples - 1));
  EXPECT_LT(std::abs(mean - exact), 3.29 * se + 1e-5 * exact) << mean << " vs " << exact;  // two-sided α = 0.001
}

TEST(RenderMotionBlur, MovingEdgeMatchesTheClosedFormCoverage) {
  // An emitting strip of width w (radiance 1) in the plane z = 0 moves by D
  // along x while the shutter is open, over a black background. A pinhole
  // camera looking down the z axis maps the plane linearly onto the film, so
  // a pixel's value is the mean over its footprint [X0, X1] of the fraction
  // of the shutter during which the strip covers X:
  //   c(X) = |[(X − x0 − w)/D, (X − x0)/D] ∩ [0, 1]|,
  // integrated here by the midpoint rule (c is piecewise linear).
  const double z = 10, x0 = -1.5, w = 1, d = 2;
  const int width = 32;
  const double half_width = 4, tan_half = half_width / (z * width / 2.0);
  Scene scene = parse_scene(R"({
    "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0], "fov": )" +
                                std::to_string(2 * std::atan(tan_half) * 180 / pi) +
                                R"(, "resolution": [32, 2]},
    "materials": {"strip": {"reflectance": [0, 0, 0], "emission": [1, 1, 1]}},
    "shapes": [{"type": "quad", "corner": [-1.5, -1, 0], "edge_u": [0, 2, 0], "edge_v": [1, 0, 0], "motion": [2, 0, 0], "material": "strip"}]
  })",
                            "strip");
  RenderSettings s;
  s.sampler.sampler = "random";
  s.sampler.spp = 256;
  s.sampler.seed = 12;
  const Image image = render(scene, s);
  const auto coverage = [&](double x) {
    const double lo = std::max(0.0, (x - x0 - w) / d), hi = std::min(1.0, (x - x0) / d);
    return std::max(0.0, hi - lo);
  };
  // Šidák over the 32 × 2 pixels (red channel) at family α = 0.01.
  const double alpha = 1 - std::pow(0.99, 1.0 / 64);
  const double z_max = boost::math::quantile(boost::math::complement(boost::math::normal(), alpha / 2));
  int partial = 0;
  for (int row = 0; row < 2; ++row)
    for (int i = 0; i < width; ++i) {
      // Film x grows to the image's right = world −x (camera_model.cpp).
      const double xa = -half_width * (2.0 * i / width - 1), xb = -half_width * (2.0 * (i + 1) / width - 1);
      double expected = 0;
      const int steps = 4000;
      for (int k = 0; k < steps; ++k) expected += coverage(xb + (xa - xb) * (k + 0.5) / steps) / steps;
      const std::size_t p = 3 * (std::size_t(row) * width + i);
      const double se = std::sqrt(image.variance[p]);
      if (se > 0) {
        ++partial;
        EXPECT_LT(std::abs(image.rgb[p] - expected), z_max * se)
            << "pixel " << i << ": " << image.rgb[p] << " vs " << expected;
      } else {
        EXPECT_NEAR(image.rgb[p], expected, 1e-9) << "pixel " << i;  // always or never covered
      }
    }
  EXPECT_GT(partial, 20);  // the blurred ramps span many pixels
}

}  // namespace
}  // namespace stratum::render
