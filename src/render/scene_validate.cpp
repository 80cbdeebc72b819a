#include <cmath>
#include <string>

#include "stratum/render/scene.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {

namespace {

void require_finite(Vec3 v, const std::string& what) {
  if (!is_finite(v))
    throw invalid_argument(
        what, "(" + to_message_string(v.x) + ", " + to_message_string(v.y) + ", " + to_message_string(v.z) + ")",
        "must be finite");
}

void require_non_negative(Vec3 v, const std::string& what) {
  require_finite(v, what);
  require(v.x >= 0 && v.y >= 0 && v.z >= 0, what,
          "(" + to_message_string(v.x) + ", " + to_message_string(v.y) + ", " + to_message_string(v.z) + ")",
          "must be non-negative");
}

void validate_camera(const Camera& camera) {
  require_finite(camera.position, "camera.position");
  require_finite(camera.look_at, "camera.look_at");
  require_finite(camera.up, "camera.up");
  const Vec3 forward = camera.look_at - camera.position;
  require(length(forward) > 0, "camera.look_at", "(equal to camera.position)", "must differ from camera.position");
  require(length(cross(forward, camera.up)) > 1e-12 * length(forward) * length(camera.up), "camera.up",
          "(parallel to the view direction)", "must not be parallel to look_at - position");
  require(std::isfinite(camera.fov_degrees) && camera.fov_degrees > 0 && camera.fov_degrees < 180, "camera.fov",
          camera.fov_degrees, "must be in (0, 180) degrees");
  require(camera.width >= 1 && camera.width <= 16384, "camera.resolution width", camera.width, "must be in [1, 16384]");
  require(camera.height >= 1 && camera.height <= 16384, "camera.resolution height", camera.height,
          "must be in [1, 16384]");
  require(std::isfinite(camera.aperture_radius) && camera.aperture_radius >= 0, "camera.aperture_radius",
          camera.aperture_radius, "must be finite and >= 0");
  require(std::isfinite(camera.focus_distance) && camera.focus_distance > 0, "camera.focus_distance",
          camera.focus_distance, "must be finite and > 0");
  require(std::isfinite(camera.shutter_open) && std::isfinite(camera.shutter_close) &&
              camera.shutter_open <= camera.shutter_close,
          "camera.shutter", to_message_string(camera.shutter_open) + ", " + to_message_string(camera.shutter_close),
          "must be finite with open <= close");
}

}  // namespace

void validate_scene(Scene& scene, std::vector<std::string>* warnings) {
  validate_camera(scene.camera);
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& material = scene.materials[m];
    const std::string name = "materials." + material.name;
    require_non_negative(material.reflectance, name + ".reflectance");
    require_non_negative(material.emission, name + ".emission");
    require(material.reflectance.x <= 1 && material.reflectance.y <= 1 && material.reflectance.z <= 1,
            name + ".reflectance", "(a channel above 1)", "must be at most 1 per channel (energy conservation)");
    require(std::isfinite(material.exponent) && material.exponent >= 0 && material.exponent <= 1e6, name + ".exponent",
            material.exponent, "must be in [0, 1e6]");
  }
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    Shape& shape = scene.shapes[s];
    const std::string name = "shapes[" + std::to_string(s) + "]";
    require(shape.material < scene.materials.size(), name + ".material", shape.material,
            "must name a material of the scene");
    require_finite(shape.motion, name + ".motion");
    if (shape.type == ShapeType::sphere) {
      require_finite(shape.center, name + ".center");
      require(std::isfinite(shape.radius) && shape.radius > 0, name + ".radius", shape.radius,
              "must be finite and > 0");
    } else if (shape.type == ShapeType::disk) {
      require_finite(shape.center, name + ".center");
      require_finite(shape.normal, name + ".normal");
      require(std::abs(length(shape.normal) - 1) < 1e-9, name + ".normal", length(shape.normal),
              "must be a unit vector (its length is shown)");
      require(std::isfinite(shape.radius) && shape.radius > 0, name + ".radius", shape.radius,
              "must be finite and > 0");
    } else if (shape.type == ShapeType::quad) {
      require_finite(shape.corner, name + ".corner");
      require_finite(shape.edge_u, name + ".edge_u");
      require_finite(shape.edge_v, name + ".edge_v");
      require(length(cross(shape.edge_u, shape.edge_v)) > 0, name, "(zero area)",
              "a quad needs two non-parallel, non-zero edges");
    } else {
      for (std::size_t v = 0; v < shape.vertices.size(); ++v)
        require_finite(shape.vertices[v], name + ".vertices[" + std::to_string(v) + "]");
      std::vector<std::array<unsigned, 3>> kept;
      for (std::size_t t = 0; t < shape.indices.size(); ++t) {
        const auto& tri = shape.indices[t];
        for (unsigned k : tri)
          require(k < shape.vertices.size(), name + ".indices[" + std::to_string(t) + "]", k,
                  "must index the shape's vertices");
        const Vec3 a = shape.vertices[tri[0]], b = shape.vertices[tri[1]], c = shape.vertices[tri[2]];
        if (length(cross(b - a, c - a)) > 0) {
          kept.push_back(tri);
        } else if (warnings) {
          warnings->push_back(name + ": triangle " + std::to_string(t) + " has zero area and is skipped");
        }
      }
      shape.indices = std::move(kept);
      shape.triangle_cdf.clear();
      double total = 0;
      for (const auto& tri : shape.indices) {
        total += 0.5 * length(cross(shape.vertices[tri[1]] - shape.vertices[tri[0]],
                                    shape.vertices[tri[2]] - shape.vertices[tri[0]]));
        shape.triangle_cdf.push_back(total);
      }
    }
  }
  // Every emitting shape is an area light; point and environment lights are kept.
  std::vector<Light> lights;
  for (const Light& light : scene.lights) {
    if (light.type == LightType::area) continue;
    if (light.type == LightType::point) {
      require_finite(light.position, "lights.point.position");
      require_non_negative(light.intensity, "lights.point.intensity");
    } else {
      require_non_negative(light.radiance, "lights.environment.radiance");
    }
    lights.push_back(light);
  }
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    const Vec3 e = scene.materials[scene.shapes[s].material].emission;
    if (e.x > 0 || e.y > 0 || e.z > 0) lights.push_back(Light{LightType::area, s, {}, {}, {}});
  }
  scene.lights = std::move(lights);
}

}  // namespace stratum::render
