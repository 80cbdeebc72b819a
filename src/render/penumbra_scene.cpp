/// render::penumbra_scene(): a floor in the penumbras of three bars under a
/// large light, seen from above, so that a render's error covers the whole
/// image (the scene of the blue-noise error measurements, docs/render.md).
/// The same scene as scenes/penumbra.json (tested).
#include "stratum/render/scene.hpp"

namespace stratum::render {

Scene penumbra_scene() {
  static constexpr const char* text = R"({"name": "penumbra",
 "camera": {"position": [0, 6, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 60, "resolution": [128, 128]},
 "materials": {"floor": {"reflectance": [0.8, 0.8, 0.8]}, "bar": {"reflectance": [0.5, 0.5, 0.5]},
               "lamp": {"reflectance": [0, 0, 0], "emission": [6, 6, 6]}},
 "shapes": [
  {"type": "quad", "corner": [-8, 0, 8], "edge_u": [16, 0, 0], "edge_v": [0, 0, -16], "material": "floor"},
  {"type": "quad", "corner": [3, 5, -4], "edge_u": [5, 0, 0], "edge_v": [0, 0, 8], "material": "lamp"},
  {"type": "quad", "corner": [-2.2, 2, -5], "edge_u": [0.5, 0, 0], "edge_v": [0, 0, 10], "material": "bar"},
  {"type": "quad", "corner": [-0.2, 2, -5], "edge_u": [0.5, 0, 0], "edge_v": [0, 0, 10], "material": "bar"},
  {"type": "quad", "corner": [1.8, 2, -5], "edge_u": [0.5, 0, 0], "edge_v": [0, 0, 10], "material": "bar"}]})";
  return parse_scene(text, "the built-in penumbra scene");
}

}  // namespace stratum::render
