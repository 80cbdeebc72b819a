#include <initializer_list>

#include "stratum/render/scene.hpp"

namespace stratum::render {

namespace {

/// A planar polygon of the published data as two triangles (the measured
/// walls are not exact parallelograms, so they stay triangles).
void add_polygon(Scene& scene, std::size_t material, std::initializer_list<Vec3> corners) {
  Shape shape;
  shape.type = ShapeType::triangles;
  shape.material = material;
  shape.vertices.assign(corners.begin(), corners.end());
  for (unsigned i = 1; i + 1 < shape.vertices.size(); ++i) shape.indices.push_back({0, i, i + 1});
  scene.shapes.push_back(std::move(shape));
}

/// A block of the published data: its top and its four sides.
void add_block(Scene& scene, std::size_t material, const std::array<Vec3, 4>& top) {
  add_polygon(scene, material, {top[0], top[1], top[2], top[3]});
  for (int i = 0; i < 4; ++i) {
    const Vec3 a = top[i], b = top[(i + 1) % 4];
    add_polygon(scene, material, {Vec3{a.x, 0, a.z}, a, b, Vec3{b.x, 0, b.z}});
  }
}

}  // namespace

Scene cornell_box() {
  Scene scene;
  scene.name = "cornell-box";
  Camera& camera = scene.camera;
  camera.position = {278, 273, -800};
  camera.look_at = {278, 273, 0};
  camera.up = {0, 1, 0};
  camera.fov_degrees = 39.3077;  // 2·atan(12.5 / 35): the 35 mm lens on 25 mm film
  camera.width = camera.height = 256;
  camera.focus_distance = 1047;  // the front edge of the tall block, (423, ·, 247)
  camera.aperture_radius = 8;
  camera.shutter_open = 0;
  camera.shutter_close = 1;

  scene.materials = {
      {"white", MaterialType::diffuse, {0.73, 0.73, 0.73}, {}},
      {"red", MaterialType::diffuse, {0.63, 0.065, 0.05}, {}},
      {"green", MaterialType::diffuse, {0.14, 0.45, 0.091}, {}},
      {"light", MaterialType::diffuse, {0.78, 0.78, 0.78}, {17, 12, 4}},
  };
  const std::size_t white = 0, red = 1, green = 2, light = 3;

  add_polygon(scene, white, {{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}});                // floor
  add_polygon(scene, white, {{556, 548.8, 0}, {556, 548.8, 559.2}, {0, 548.8, 559.2}, {0, 548.8, 0}});    // ceiling
  add_polygon(scene, white, {{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}});  // back
  add_polygon(scene, green, {{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}});                // right
  add_polygon(scene, red, {{552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}, {556, 548.8, 0}});      // left
  add_block(scene, white, {Vec3{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}});        // short
  add_block(scene, white, {Vec3{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}});      // tall

  // The light: 130 × 105 at the ceiling's height, lowered by 0.01 so that it
  // is not coplanar with the ceiling.
  Shape lamp;
  lamp.type = ShapeType::quad;
  lamp.material = light;
  lamp.corner = {343, 548.79, 227};
  lamp.edge_u = {0, 0, 105};  // edge_u × edge_v points down: the side that emits
  lamp.edge_v = {-130, 0, 0};
  scene.shapes.push_back(lamp);

  // A sphere on the floor in front of the tall block, moving 50 mm towards
  // the short block while the shutter is open.
  Shape ball;
  ball.type = ShapeType::sphere;
  ball.material = white;
  ball.center = {420, 70, 130};
  ball.radius = 70;
  ball.motion = {-50, 0, 0};
  scene.shapes.push_back(ball);

  validate_scene(scene);
  return scene;
}

}  // namespace stratum::render
