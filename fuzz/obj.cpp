// Fuzz target: the Wavefront OBJ reader (render/obj.hpp) on any text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "stratum/render/obj.hpp"
#include "stratum/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const stratum::render::ObjMesh mesh = stratum::render::parse_obj(text, "fuzz.obj");
    // Every triangle it returns indexes a vertex it returns.
    for (const auto& triangle : mesh.triangles)
      for (const auto index : triangle)
        if (index >= mesh.vertices.size()) __builtin_trap();
  } catch (const stratum::invalid_argument&) {
  }
  return 0;
}
