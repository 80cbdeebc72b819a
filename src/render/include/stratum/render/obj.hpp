#pragma once
/// A minimal Wavefront OBJ reader for triangle meshes in scene files: `v x y z`
/// vertices and `f` faces (polygons are split into a fan of triangles; the
/// forms i, i/t, i//n, i/t/n and negative, relative indices are accepted).
/// Texture coordinates, normals, groups, objects, smoothing groups and
/// material statements are ignored; any other statement is an error.
#include <array>
#include <string>
#include <vector>

#include "stratum/render/vec3.hpp"

namespace stratum::render {

struct ObjMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<unsigned, 3>> triangles;  ///< 0-based vertex indices
};

/// Reads `path`. Throws stratum::invalid_argument naming the file, and the
/// line for a malformed vertex, an unknown statement, a face with fewer than
/// 3 vertices or a face index that is 0 or names no vertex defined so far.
ObjMesh read_obj(const std::string& path);

/// The same from text; `origin` names it in messages.
ObjMesh parse_obj(const std::string& text, const std::string& origin);

}  // namespace stratum::render
