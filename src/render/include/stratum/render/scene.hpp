#pragma once
/// A scene for stratum's renderer: a thin-lens camera with a shutter,
/// shapes with materials and optional linear motion, and lights. Plain
/// values: the built-in Cornell box (cornell_box()) and JSON scene files
/// (load_scene(), schema in docs/scenes.md) both produce one.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "stratum/render/vec3.hpp"

namespace stratum::render {

/// A thin-lens camera (Cook, Porter, Carpenter 1984, "Distributed ray
/// tracing": sampling the lens gives depth of field, sampling the shutter
/// motion blur). aperture_radius = 0 is a pinhole.
struct Camera {
  Vec3 position{278, 273, -800};
  Vec3 look_at{278, 273, 0};
  Vec3 up{0, 1, 0};
  double fov_degrees = 39.3077;  ///< vertical field of view
  int width = 256;
  int height = 256;
  double aperture_radius = 0;  ///< lens radius, scene units
  double focus_distance = 1;   ///< distance to the plane in focus (used when aperture_radius > 0)
  double shutter_open = 0;
  double shutter_close = 1;
};

/// diffuse: Lambertian; mirror: perfect specular reflection; glossy: the
/// normalized (modified) Phong lobe around the mirror direction (Lafortune,
/// Willems 1994, see render/bsdf.hpp).
enum class MaterialType { diffuse, mirror, glossy };

struct Material {
  std::string name;
  MaterialType type = MaterialType::diffuse;
  Vec3 reflectance{0.5, 0.5, 0.5};  ///< RGB albedo (diffuse), specular colour (mirror, glossy)
  Vec3 emission{0, 0, 0};           ///< RGB radiance leaving the surface (area lights)
  double exponent = 20;             ///< glossy: Phong exponent (larger: sharper highlight), in [0, 1e6]
};

enum class ShapeType { sphere, quad, triangles, disk };

/// A shape; `motion` is its translation at shutter close relative to
/// shutter open (linear in time, Embree's two time steps).
struct Shape {
  ShapeType type = ShapeType::quad;
  std::size_t material = 0;  ///< index into Scene::materials
  Vec3 center{}, motion{};
  double radius = 0;                  ///< sphere, disk
  Vec3 normal{};                      ///< disk: unit normal (the emitting side); centre and radius above
  Vec3 corner{}, edge_u{}, edge_v{};  ///< quad: corner + s·edge_u + t·edge_v, s, t ∈ [0,1]
  std::vector<Vec3> vertices;         ///< triangles
  std::vector<std::array<unsigned, 3>> indices;
  /// triangles: running sums of the triangles' areas (filled by
  /// validate_scene), for picking a triangle by area when sampling a light.
  std::vector<double> triangle_cdf;
};

enum class LightType { area, point, environment };

/// Lights: an emitting shape (area: its material's emission), a point light
/// (intensity), or a constant environment (radiance from every direction).
struct Light {
  LightType type = LightType::area;
  std::size_t shape = 0;  ///< area: index into Scene::shapes
  Vec3 position{};        ///< point
  Vec3 intensity{};       ///< point: W/sr per channel
  Vec3 radiance{};        ///< environment
};

struct Scene {
  std::string name = "scene";
  Camera camera;
  std::vector<Material> materials;
  std::vector<Shape> shapes;
  std::vector<Light> lights;
};

/// The Cornell box as measured by the Cornell Program of Computer Graphics
/// ("Cornell box data", graphics.cornell.edu/online/box/data.html: geometry
/// in millimetres, camera at (278, 273, −800) looking down +z, 35 mm lens on
/// a 25 mm film), with the usual RGB reflectances (white 0.73, red
/// (0.63, 0.065, 0.05), green (0.14, 0.45, 0.091), as in pbrt's and
/// Mitsuba's Cornell scenes) and the ceiling light. For the lecture's
/// camera integral (LECTURE.md §1) it adds a sphere moving during the
/// shutter (motion blur) and a thin lens focused on the tall block (depth
/// of field).
Scene cornell_box();

/// A floor in the penumbras of three bars under a large light, seen from
/// above (128 × 128): error over the whole image, for measuring where a
/// render's error goes (docs/render.md; the same as scenes/penumbra.json).
Scene penumbra_scene();

/// Reads and validates a JSON scene (docs/scenes.md). Throws
/// stratum::invalid_argument naming the line and column of a syntax error,
/// or the key ("shapes[2].radius") of an unknown key or a bad value.
/// Warnings (skipped degenerate triangles) go to `warnings`.
Scene load_scene(const std::string& path, std::vector<std::string>* warnings = nullptr);

/// Parses and validates a JSON scene from text; `origin` names it in messages.
Scene parse_scene(const std::string& text, const std::string& origin, std::vector<std::string>* warnings = nullptr);

/// Checks a scene: finite numbers, indices in range, positive radii and
/// sizes, non-degenerate quads; degenerate triangles are dropped with a
/// warning written to `warnings`.
void validate_scene(Scene& scene, std::vector<std::string>* warnings = nullptr);

}  // namespace stratum::render
