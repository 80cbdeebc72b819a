/// JSON scene files (schema: docs/scenes.md), read with nlohmann::json.
/// Every message names the file and where in it the problem is.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "stratum/io/json.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/render/bsdf.hpp"
#include "stratum/render/obj.hpp"
#include "stratum/render/scene.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {

namespace {

using nlohmann::json;

/// Reads one JSON object, knowing its place ("camera", "shapes[2]") for messages.
class Reader {
 public:
  Reader(const json& object, std::string where, const std::set<std::string>& allowed)
      : object_(object), where_(std::move(where)) {
    if (!object.is_object()) throw invalid_argument(where_, io::json_excerpt(object), "must be a JSON object");
    for (const auto& item : object.items())
      if (!allowed.count(item.key())) {
        std::string names;
        for (const auto& name : allowed) names += (names.empty() ? "" : ", ") + name;
        throw invalid_argument(where_ + "." + item.key(), "(unknown key)", "allowed keys are " + names);
      }
  }
  bool has(const std::string& key) const { return object_.contains(key); }
  const json& at(const std::string& key) const {
    if (!has(key)) throw invalid_argument(where_ + "." + key, "(missing)", "is required");
    return object_.at(key);
  }
  std::string name(const std::string& key) const { return where_ + "." + key; }
  double number(const std::string& key, double fallback) const {
    return has(key) ? to_number(at(key), name(key)) : fallback;
  }
  double number(const std::string& key) const { return to_number(at(key), name(key)); }
  Vec3 vec3(const std::string& key, Vec3 fallback) const { return has(key) ? to_vec3(at(key), name(key)) : fallback; }
  Vec3 vec3(const std::string& key) const { return to_vec3(at(key), name(key)); }
  std::string text(const std::string& key) const {
    const json& value = at(key);
    if (!value.is_string()) throw invalid_argument(name(key), io::json_excerpt(value), "must be a string");
    return value.get<std::string>();
  }

  static double to_number(const json& value, const std::string& where) {
    // JSON has no NaN or Inf; nlohmann reads huge literals as inf, which is refused.
    if (!value.is_number()) throw invalid_argument(where, io::json_excerpt(value), "must be a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) throw invalid_argument(where, io::json_excerpt(value), "must be finite");
    return x;
  }
  static Vec3 to_vec3(const json& value, const std::string& where) {
    if (!value.is_array() || value.size() != 3)
      throw invalid_argument(where, io::json_excerpt(value), "must be an array of 3 numbers");
    return {to_number(value[0], where + "[0]"), to_number(value[1], where + "[1]"), to_number(value[2], where + "[2]")};
  }

 private:
  const json& object_;
  std::string where_;
};

Camera read_camera(const json& value) {
  const Reader r(value, "camera",
                 {"position", "look_at", "up", "fov", "resolution", "aperture_radius", "focus_distance", "shutter"});
  Camera camera;
  camera.position = r.vec3("position", camera.position);
  camera.look_at = r.vec3("look_at", camera.look_at);
  camera.up = r.vec3("up", camera.up);
  camera.fov_degrees = r.number("fov", camera.fov_degrees);
  camera.aperture_radius = r.number("aperture_radius", 0);
  camera.focus_distance = r.number("focus_distance", length(camera.look_at - camera.position));
  if (r.has("resolution")) {
    const json& res = r.at("resolution");
    if (!res.is_array() || res.size() != 2 || !res[0].is_number_integer() || !res[1].is_number_integer())
      throw invalid_argument("camera.resolution", io::json_excerpt(res),
                             "must be [width, height], two positive integers");
    const auto w = res[0].get<std::int64_t>(), h = res[1].get<std::int64_t>();
    require(w >= 1 && w <= 16384 && h >= 1 && h <= 16384, "camera.resolution", io::json_excerpt(res),
            "each side must be in [1, 16384]");
    camera.width = static_cast<int>(w);
    camera.height = static_cast<int>(h);
  }
  if (r.has("shutter")) {
    const json& shutter = r.at("shutter");
    if (!shutter.is_array() || shutter.size() != 2)
      throw invalid_argument("camera.shutter", io::json_excerpt(shutter), "must be [open, close]");
    camera.shutter_open = Reader::to_number(shutter[0], "camera.shutter[0]");
    camera.shutter_close = Reader::to_number(shutter[1], "camera.shutter[1]");
  }
  return camera;
}

std::vector<Material> read_materials(const json& value, std::map<std::string, std::size_t>& index) {
  if (!value.is_object())
    throw invalid_argument("materials", io::json_excerpt(value), "must be an object of named materials");
  std::vector<Material> materials;
  for (const auto& item : value.items()) {
    const Reader r(item.value(), "materials." + item.key(), {"type", "reflectance", "emission", "exponent"});
    Material material;
    material.name = item.key();
    const std::string type = r.has("type") ? r.text("type") : "diffuse";
    if (type == "diffuse") material.type = MaterialType::diffuse;
    else if (type == "mirror") material.type = MaterialType::mirror;
    else if (type == "glossy") material.type = MaterialType::glossy;
    else throw invalid_argument(r.name("type"), type, "allowed types are diffuse, mirror, glossy");
    if (r.has("exponent") && material.type != MaterialType::glossy)
      throw invalid_argument(r.name("exponent"), io::json_excerpt(r.at("exponent")),
                             "applies to glossy materials only");
    material.exponent = r.number("exponent", material.exponent);
    material.reflectance = r.vec3("reflectance", material.reflectance);
    material.emission = r.vec3("emission", {});
    index[material.name] = materials.size();
    materials.push_back(material);
  }
  return materials;
}

/// A disk as the regular polygon of `segments` sides inscribed in it, a fan
/// of triangles around the centre, oriented so that (v1 − v0) × (v2 − v0)
/// is the disk's normal.
void make_disk(Shape& shape, Vec3 center, Vec3 normal, double radius, int segments) {
  const Frame frame(normalize(normal));
  shape.vertices = {center};
  for (int k = 0; k < segments; ++k) {
    const double phi = 2 * std::numbers::pi * k / segments;
    shape.vertices.push_back(center + radius * (std::cos(phi) * frame.s + std::sin(phi) * frame.t));
  }
  for (unsigned k = 0; k < unsigned(segments); ++k)
    shape.indices.push_back({0, 1 + k, 1 + (k + 1) % unsigned(segments)});
}

Shape read_shape(const json& value, const std::string& where, const std::map<std::string, std::size_t>& materials,
                 const std::filesystem::path& directory) {
  const Reader r(value, where,
                 {"type", "material", "motion", "center", "radius", "corner", "edge_u", "edge_v", "vertices", "indices",
                  "normal", "segments", "file"});
  Shape shape;
  const std::string material = r.text("material");
  const auto found = materials.find(material);
  if (found == materials.end())
    throw invalid_argument(r.name("material"), material, "must name an entry of \"materials\"");
  shape.material = found->second;
  shape.motion = r.vec3("motion", {});
  const std::string type = r.text("type");
  if (type == "sphere") {
    shape.type = ShapeType::sphere;
    shape.center = r.vec3("center");
    shape.radius = r.number("radius");
  } else if (type == "quad") {
    shape.type = ShapeType::quad;
    shape.corner = r.vec3("corner");
    shape.edge_u = r.vec3("edge_u");
    shape.edge_v = r.vec3("edge_v");
  } else if (type == "triangles") {
    shape.type = ShapeType::triangles;
    const json& vertices = r.at("vertices");
    if (!vertices.is_array())
      throw invalid_argument(r.name("vertices"), io::json_excerpt(vertices), "must be an array of [x, y, z]");
    for (std::size_t v = 0; v < vertices.size(); ++v)
      shape.vertices.push_back(Reader::to_vec3(vertices[v], r.name("vertices") + "[" + std::to_string(v) + "]"));
    const json& indices = r.at("indices");
    if (!indices.is_array())
      throw invalid_argument(r.name("indices"), io::json_excerpt(indices), "must be an array of [i, j, k]");
    for (std::size_t t = 0; t < indices.size(); ++t) {
      const json& tri = indices[t];
      const std::string where = r.name("indices") + "[" + std::to_string(t) + "]";
      const bool ok = tri.is_array() && tri.size() == 3 && tri[0].is_number_unsigned() && tri[1].is_number_unsigned() &&
                      tri[2].is_number_unsigned();
      if (!ok) throw invalid_argument(where, io::json_excerpt(tri), "must be 3 vertex indices");
      std::array<unsigned, 3> index{};
      for (int k = 0; k < 3; ++k) {
        // Checked before narrowing: 4294967298 would otherwise become 2.
        const auto value = tri[k].get<std::uint64_t>();
        if (value > std::numeric_limits<unsigned>::max())
          throw invalid_argument(where + "[" + std::to_string(k) + "]", std::to_string(value),
                                 "must be a vertex index below " + std::to_string(vertices.size()));
        index[k] = static_cast<unsigned>(value);
      }
      shape.indices.push_back({index[0], index[1], index[2]});
    }
  } else if (type == "disk") {
    // Divided by its largest component before normalizing, so that a huge or
    // tiny (but non-zero) normal neither overflows nor underflows to zero.
    const Vec3 given = r.vec3("normal");
    const double scale = std::max({std::abs(given.x), std::abs(given.y), std::abs(given.z)});
    require(scale > 0, r.name("normal"), io::json_excerpt(r.at("normal")), "must be a non-zero vector");
    const Vec3 normal = given / scale;
    const double radius = r.number("radius");
    require(radius > 0, r.name("radius"), radius, "must be > 0");
    if (r.has("segments")) {  // the inscribed polygon, on request
      shape.type = ShapeType::triangles;
      const double segments = r.number("segments");
      require(segments >= 3 && segments <= 65536 && segments == std::floor(segments), r.name("segments"), segments,
              "must be an integer in [3, 65536]");
      make_disk(shape, r.vec3("center"), normal, radius, int(segments));
    } else {  // the exact disk
      shape.type = ShapeType::disk;
      shape.center = r.vec3("center");
      shape.normal = normalize(normal);
      shape.radius = radius;
    }
  } else if (type == "mesh") {
    shape.type = ShapeType::triangles;
    const std::filesystem::path file = r.text("file");
    ObjMesh mesh = read_obj((file.is_absolute() ? file : directory / file).string());
    shape.vertices = std::move(mesh.vertices);
    shape.indices = std::move(mesh.triangles);
  } else {
    throw invalid_argument(r.name("type"), type, "allowed shape types are sphere, quad, triangles, disk, mesh");
  }
  return shape;
}

Light read_light(const json& value, const std::string& where) {
  const Reader r(value, where, {"type", "position", "intensity", "radiance"});
  Light light;
  const std::string type = r.text("type");
  if (type == "point") {
    light.type = LightType::point;
    light.position = r.vec3("position");
    light.intensity = r.vec3("intensity");
  } else if (type == "environment") {
    light.type = LightType::environment;
    light.radiance = r.vec3("radiance");
  } else {
    throw invalid_argument(
        r.name("type"), type,
        "allowed light types are point, environment (area lights are shapes with an emitting material)");
  }
  return light;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& origin, std::vector<std::string>* warnings) {
  // Nesting capped, errors with line, column and an excerpt (io::parse_json).
  const json document = io::parse_json(text, "scene", origin);
  const Reader r(document, "scene", {"name", "camera", "materials", "shapes", "lights"});
  Scene scene;
  scene.name = r.has("name") ? r.text("name") : std::filesystem::path(origin).stem().string();
  if (r.has("camera")) scene.camera = read_camera(r.at("camera"));
  std::map<std::string, std::size_t> materials;
  scene.materials = read_materials(r.at("materials"), materials);
  const json& shapes = r.at("shapes");
  if (!shapes.is_array()) throw invalid_argument("shapes", io::json_excerpt(shapes), "must be an array");
  for (std::size_t s = 0; s < shapes.size(); ++s)
    scene.shapes.push_back(read_shape(shapes[s], "shapes[" + std::to_string(s) + "]", materials,
                                      std::filesystem::path(origin).parent_path()));
  if (r.has("lights")) {
    const json& lights = r.at("lights");
    if (!lights.is_array()) throw invalid_argument("lights", io::json_excerpt(lights), "must be an array");
    for (std::size_t l = 0; l < lights.size(); ++l)
      scene.lights.push_back(read_light(lights[l], "lights[" + std::to_string(l) + "]"));
  }
  validate_scene(scene, warnings);
  return scene;
}

Scene load_scene(const std::string& path, std::vector<std::string>* warnings) {
  io::refuse_special_file("scene", path);  // a FIFO or /dev/zero would never end
  std::ifstream in(path, std::ios::binary);
  if (!in) throw invalid_argument("scene", path, "must be a readable JSON file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path, warnings);
}

}  // namespace stratum::render
