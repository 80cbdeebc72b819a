// The scene model: the built-in Cornell box and JSON scene files
// (src/render/cornell_box.cpp, scene_json.cpp, scene_validate.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "stratum/render/scene.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {
namespace {

std::string error_of(const std::string& json) {
  try {
    parse_scene(json, "test.json");
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

double triangle_area(const Shape& shape) {
  double area = 0;
  for (const auto& t : shape.indices)
    area +=
        0.5 * length(cross(shape.vertices[t[1]] - shape.vertices[t[0]], shape.vertices[t[2]] - shape.vertices[t[0]]));
  return area;
}

TEST(CornellBox, PublishedGeometryAndOneAreaLight) {
  const Scene scene = cornell_box();
  ASSERT_EQ(scene.lights.size(), 1u);
  const Shape& lamp = scene.shapes[scene.lights[0].shape];
  EXPECT_EQ(lamp.type, ShapeType::quad);
  // The light is 130 × 105 mm and faces down.
  const Vec3 normal = cross(lamp.edge_u, lamp.edge_v);
  EXPECT_DOUBLE_EQ(length(normal), 130.0 * 105.0);
  EXPECT_LT(normal.y, 0);
  // Floor: the published quadrilateral, area by the shoelace formula in (x, z).
  const Shape& floor = scene.shapes[0];
  const double xs[] = {552.8, 0, 0, 549.6}, zs[] = {0, 0, 559.2, 559.2};
  double shoelace = 0;
  for (int i = 0; i < 4; ++i) shoelace += xs[i] * zs[(i + 1) % 4] - xs[(i + 1) % 4] * zs[i];
  EXPECT_NEAR(triangle_area(floor), std::abs(shoelace) / 2, 1e-9);
  // 5 walls, 2 blocks of 5 faces, the lamp, the moving sphere.
  EXPECT_EQ(scene.shapes.size(), 5u + 10u + 1u + 1u);
  const Shape& ball = scene.shapes.back();
  EXPECT_EQ(ball.type, ShapeType::sphere);
  EXPECT_GT(length(ball.motion), 0);
  EXPECT_GT(scene.camera.aperture_radius, 0);
  // The 35 mm lens on 25 mm film.
  EXPECT_NEAR(std::tan(scene.camera.fov_degrees * M_PI / 360), 12.5 / 35, 1e-6);
}

constexpr const char* minimal = R"({
  "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0], "fov": 40, "resolution": [32, 24]},
  "materials": {"grey": {"reflectance": [0.5, 0.5, 0.5]}, "lamp": {"emission": [4, 4, 4], "reflectance": [0, 0, 0]}},
  "shapes": [
    {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "grey", "motion": [0.5, 0, 0]},
    {"type": "quad", "corner": [-1, 3, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2], "material": "lamp"},
    {"type": "triangles", "vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 0, 1]], "indices": [[0, 1, 2], [0, 1, 3]], "material": "grey"}
  ],
  "lights": [{"type": "environment", "radiance": [0.1, 0.1, 0.1]}]
})";

TEST(SceneJson, ReadsEveryPart) {
  std::vector<std::string> warnings;
  const Scene scene = parse_scene(minimal, "minimal.json", &warnings);
  EXPECT_EQ(scene.camera.width, 32);
  EXPECT_EQ(scene.camera.height, 24);
  EXPECT_DOUBLE_EQ(scene.camera.focus_distance, 5);  // defaults to the look-at distance
  ASSERT_EQ(scene.shapes.size(), 3u);
  EXPECT_DOUBLE_EQ(scene.shapes[0].motion.x, 0.5);
  // The collinear triangle is dropped with a warning; the other stays.
  EXPECT_EQ(scene.shapes[2].indices.size(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("zero area"), std::string::npos);
  // The environment plus the emitting quad.
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].type, LightType::environment);
  EXPECT_EQ(scene.lights[1].type, LightType::area);
  EXPECT_EQ(scene.lights[1].shape, 1u);
}

TEST(SceneJson, SyntaxErrorsGiveLineAndColumn) {
  const std::string message = error_of("{\n  \"materials\": {},\n  \"shapes\": [,]\n}");
  EXPECT_NE(message.find("line 3, column 14"), std::string::npos) << message;
}

TEST(SceneJson, BadValuesAreNamed) {
  EXPECT_NE(error_of(R"({"materials": {}, "shapes": [], "colour": 1})").find("colour"), std::string::npos);
  EXPECT_NE(
      error_of(
          R"({"materials": {"m": {}}, "shapes": [{"type": "sphere", "center": [0,0,0], "radius": -1, "material": "m"}]})")
          .find("shapes[0].radius"),
      std::string::npos);
  EXPECT_NE(
      error_of(R"({"materials": {"m": {}}, "shapes": [{"type": "cone", "material": "m"}]})").find("shapes[0].type"),
      std::string::npos);
  EXPECT_NE(
      error_of(
          R"({"materials": {"m": {}}, "shapes": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "x"}]})")
          .find("shapes[0].material"),
      std::string::npos);
  EXPECT_NE(error_of(R"({"materials": {"m": {"reflectance": [2, 0, 0]}}, "shapes": []})").find("reflectance"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"camera": {"fov": 200}, "materials": {}, "shapes": []})").find("camera.fov"),
            std::string::npos);
  EXPECT_NE(
      error_of(R"({"camera": {"resolution": [100000, 10]}, "materials": {}, "shapes": []})").find("camera.resolution"),
      std::string::npos);
  EXPECT_NE(
      error_of(
          R"({"materials": {"m": {}}, "shapes": [{"type": "quad", "corner": [0,0,0], "edge_u": [1,0,0], "edge_v": [2,0,0], "material": "m"}]})")
          .find("shapes[0]"),
      std::string::npos);
  // JSON has no Inf: an overflowing literal is refused as not finite.
  EXPECT_NE(
      error_of(
          R"({"materials": {"m": {}}, "shapes": [{"type": "sphere", "center": [1e999,0,0], "radius": 1, "material": "m"}]})")
          .find("finite"),
      std::string::npos);
}

}  // namespace
}  // namespace stratum::render
