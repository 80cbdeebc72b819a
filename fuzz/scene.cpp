// Fuzz target: the JSON scene reader (render/scene.hpp: parse_scene), with
// its nesting and size limits and the OBJ meshes a scene may name.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "stratum/render/scene.hpp"
#include "stratum/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> warnings;
  try {
    stratum::render::parse_scene(text, "fuzz.json", &warnings);
  } catch (const stratum::invalid_argument&) {
  }
  return 0;
}
