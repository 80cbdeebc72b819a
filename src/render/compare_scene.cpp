/// The scenes of comparisons and their fingerprints (cache keys of
/// references, src/render/include/stratum/render/compare.hpp).
#include <bit>
#include <cstdio>

#include "stratum/render/compare.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {

namespace {

/// Folds values into a running hash: doubles by their bits, so any change
/// of any number changes the key.
class Fingerprint {
 public:
  Fingerprint& add(double value) { return add_bits(std::bit_cast<std::uint64_t>(value == 0 ? 0.0 : value)); }
  Fingerprint& add(const Vec3& v) { return add(v[0]).add(v[1]).add(v[2]); }
  Fingerprint& add_bits(std::uint64_t bits) {
    state_ = hash64(state_, bits);
    return *this;
  }
  Fingerprint& add(const std::string& text) {
    add_bits(text.size());
    for (const char c : text) add_bits(static_cast<unsigned char>(c));
    return *this;
  }
  std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = 0x5354524154554dULL;
};

}  // namespace

std::string scene_fingerprint(const Scene& scene) {
  Fingerprint f;
  const Camera& c = scene.camera;
  f.add(c.position)
      .add(c.look_at)
      .add(c.up)
      .add(c.fov_degrees)
      .add_bits(std::uint64_t(c.width))
      .add_bits(std::uint64_t(c.height));
  f.add(c.aperture_radius).add(c.focus_distance).add(c.shutter_open).add(c.shutter_close);
  f.add_bits(scene.materials.size());
  for (const Material& m : scene.materials)
    f.add_bits(std::uint64_t(m.type)).add(m.reflectance).add(m.emission).add(m.exponent);
  f.add_bits(scene.shapes.size());
  for (const Shape& s : scene.shapes) {
    f.add_bits(std::uint64_t(s.type)).add_bits(s.material).add(s.center).add(s.motion).add(s.radius);
    f.add(s.corner).add(s.edge_u).add(s.edge_v).add_bits(s.vertices.size()).add_bits(s.indices.size());
    for (const Vec3& v : s.vertices) f.add(v);
    for (const auto& t : s.indices) f.add_bits(t[0]).add_bits(t[1]).add_bits(t[2]);
  }
  f.add_bits(scene.lights.size());
  for (const Light& l : scene.lights)
    f.add_bits(std::uint64_t(l.type)).add_bits(l.shape).add(l.position).add(l.intensity).add(l.radiance);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(f.value()));
  return hex;
}

ComparisonScene comparison_scene(const std::string& path, bool keep_motion, int width, int height) {
  require(width >= 1 && width <= 16384, "width", width, "must be in [1, 16384]");
  require(height >= 1 && height <= 16384, "height", height, "must be in [1, 16384]");
  ComparisonScene result;
  if (path.empty()) {
    result.scene = cornell_box();
    result.scene.camera.aperture_radius = 0;
    if (!keep_motion)
      for (auto& shape : result.scene.shapes) shape.motion = {};
    result.scene.name += keep_motion ? "-pinhole" : "-static";
    result.note = std::string("the built-in Cornell box without its lens (a pinhole camera)") +
                  (keep_motion ? "" : " and without its motion (static shapes)") +
                  ": each comparison isolates its own integral; give a SCENE to keep them";
  } else {
    result.scene = load_scene(path);
  }
  result.scene.camera.width = width;
  result.scene.camera.height = height;
  result.key = scene_fingerprint(result.scene);
  return result;
}

}  // namespace stratum::render
