/// Wavefront OBJ (the v and f statements; format as documented with Alias
/// Wavefront's Advanced Visualizer, appendix B1 "Object files").
#include "stratum/render/obj.hpp"

#include "stratum/io/output_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "stratum/util/error.hpp"

namespace stratum::render {

namespace {

struct Face {
  std::vector<long long> indices;  ///< as written (1-based; negative: relative to the vertices so far)
  std::size_t vertices_before = 0;
  std::size_t line = 0;
};

std::string place(const std::string& origin, std::size_t line) { return origin + ", line " + std::to_string(line); }

bool parse_double(const std::string& token, double& value) {
  std::istringstream in(token);
  in.imbue(std::locale::classic());
  in >> value;
  return in && in.peek() == std::char_traits<char>::eof() && std::isfinite(value);
}

}  // namespace

ObjMesh parse_obj(const std::string& text, const std::string& origin) {
  static const std::set<std::string> ignored{"vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib", "l", "p"};
  ObjMesh mesh;
  std::vector<Face> faces;
  std::istringstream lines(text);
  std::string line;
  for (std::size_t number = 1; std::getline(lines, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream in(line);
    std::string keyword;
    if (!(in >> keyword)) continue;
    std::vector<std::string> tokens;
    for (std::string token; in >> token;) tokens.push_back(token);
    if (keyword == "v") {
      double c[3];
      const bool ok = (tokens.size() == 3 || tokens.size() == 4) && parse_double(tokens[0], c[0]) &&
                      parse_double(tokens[1], c[1]) && parse_double(tokens[2], c[2]);
      if (!ok) throw invalid_argument(place(origin, number), line, "a vertex must be 'v x y z' with finite numbers");
      mesh.vertices.push_back({c[0], c[1], c[2]});
    } else if (keyword == "f") {
      if (tokens.size() < 3) throw invalid_argument(place(origin, number), line, "a face needs at least 3 vertices");
      Face face{{}, mesh.vertices.size(), number};
      for (const std::string& token : tokens) {
        const std::string index = token.substr(0, token.find('/'));
        long long value = 0;
        const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), value);
        if (error != std::errc{} || end != index.data() + index.size() || value == 0)
          throw invalid_argument(place(origin, number), token, "a face index must be a non-zero integer");
        face.indices.push_back(value);
      }
      faces.push_back(std::move(face));
    } else if (!ignored.count(keyword)) {
      throw invalid_argument(
          place(origin, number), keyword,
          "unknown OBJ statement (allowed: v, f; ignored: vt, vn, vp, g, o, s, usemtl, mtllib, l, p)");
    }
  }
  for (const Face& face : faces) {
    std::vector<unsigned> resolved;
    for (long long value : face.indices) {
      const long long zero_based = value > 0 ? value - 1 : static_cast<long long>(face.vertices_before) + value;
      if (zero_based < 0 || zero_based >= static_cast<long long>(mesh.vertices.size()))
        throw invalid_argument(
            place(origin, face.line), std::to_string(value),
            "face index names no vertex (the file has " + std::to_string(mesh.vertices.size()) + " vertices)");
      resolved.push_back(static_cast<unsigned>(zero_based));
    }
    for (std::size_t k = 1; k + 1 < resolved.size(); ++k)
      mesh.triangles.push_back({resolved[0], resolved[k], resolved[k + 1]});
  }
  if (mesh.triangles.empty()) throw invalid_argument("mesh", origin, "has no faces");
  return mesh;
}

ObjMesh read_obj(const std::string& path) {
  io::refuse_special_file("mesh file", path);  // a FIFO or /dev/zero would never end
  std::ifstream in(path, std::ios::binary);
  if (!in) throw invalid_argument("mesh file", path, "must be a readable OBJ file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_obj(text.str(), path);
}

}  // namespace stratum::render
