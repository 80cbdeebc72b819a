// Registry entries for the spherical-polygon warps: uniform in the solid angle
// of a triangle (Arvo 1995) or rectangle (Ureña, Fajardo, King 2013), and
// their projected-solid-angle variants (pbrt-v4's bilinear warp product).
// Points are unit directions from the origin; pdfs are per steradian.
#include <memory>
#include <string>
#include <utility>

#include "stratum/util/error.hpp"
#include "stratum/warps/projected_solid_angle.hpp"
#include "stratum/warps/spherical_rectangle.hpp"
#include "stratum/warps/spherical_triangle.hpp"
#include "warp_families.hpp"
#include "warp_triad.hpp"

namespace stratum::registry_families {
namespace {

/// The `count` numbers of parameter `name`, or invalid_argument naming it.
const std::vector<double>& numbers(const WarpParams& params, const std::string& name, std::size_t count,
                                   const std::string& shape) {
  const auto& value = params.at(name);
  require(value.size() == count, name, "(" + std::to_string(value.size()) + " numbers)",
          "must be " + std::to_string(count) + " numbers: " + shape);
  return value;
}
Vector3<double> vector_param(const WarpParams& params, const std::string& name) {
  const auto& v = numbers(params, name, 3, "x, y, z");
  return {v[0], v[1], v[2]};
}

SphericalTriangle<double> make_triangle(const WarpParams& params) {
  const auto& v = numbers(params, "vertices", 9, "3x3 row-major, one vertex per row");
  return {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}, vector_param(params, "origin")};
}
SphericalRectangle<double> make_rectangle(const WarpParams& params) {
  return {vector_param(params, "corner"), vector_param(params, "edge_u"), vector_param(params, "edge_v"),
          vector_param(params, "origin")};
}

template <class Map>
std::unique_ptr<const Warp> wrap(Map map) {
  return make_triad<2, 3>(std::move(map));
}

/// A point or direction of 3D space.
Param vector3(std::string name, std::string description, std::string default_value) {
  return params::reals(std::move(name), std::move(description), std::move(default_value), any_real(), {3, 3});
}

std::vector<Param> triangle_params() {
  return {params::reals("vertices", "3x3 triangle vertices, row-major (one vertex per row)", "0,0,1,1,0,1,0,1,1",
                        any_real(), {9, 9}),
          vector3("origin", "the point the triangle is seen from", "0,0,0")};
}
std::vector<Param> rectangle_params() {
  return {vector3("corner", "one corner of the rectangle", "-0.5,-0.5,1"),
          vector3("edge_u", "first edge from the corner", "1,0,0"),
          vector3("edge_v", "second edge from the corner, perpendicular to edge_u", "0,1,0"),
          vector3("origin", "the point the rectangle is seen from (not on its plane)", "0,0,0")};
}
Param normal_param() { return vector3("normal", "normal of the receiving surface at the origin", "0,0,1"); }

}  // namespace

std::vector<WarpInfo> warps_spherical_polygons() {
  std::vector<WarpInfo> list;
  list.push_back({"spherical-triangle",
                  "uniform in the solid angle of a triangle seen from a point (Arvo 1995), with inverse",
                  "spherical triangle", "solid angle", true, triangle_params(),
                  [](const WarpParams& p) { return wrap(make_triangle(p)); }});
  list.push_back({"spherical-rectangle",
                  "uniform in the solid angle of a rectangle seen from a point (Urena, Fajardo, King 2013), "
                  "with inverse",
                  "spherical rectangle", "solid angle", true, rectangle_params(),
                  [](const WarpParams& p) { return wrap(make_rectangle(p)); }});
  auto projected_triangle = triangle_params();
  projected_triangle.push_back(normal_param());
  list.push_back({"spherical-triangle-projected",
                  "approximately cos-weighted (projected solid angle) over a spherical triangle: bilinear warp of "
                  "the corner cosines, then Arvo's map (pbrt-v4); exact pdf",
                  "spherical triangle", "solid angle", false, projected_triangle, [](const WarpParams& p) {
                    return wrap(ProjectedSphericalTriangle<double>(make_triangle(p), vector_param(p, "normal")));
                  }});
  auto projected_rectangle = rectangle_params();
  projected_rectangle.push_back(normal_param());
  list.push_back({"spherical-rectangle-projected",
                  "approximately cos-weighted (projected solid angle) over a spherical rectangle: bilinear warp "
                  "of the corner cosines, then Urena et al.'s map (pbrt-v4); exact pdf",
                  "spherical rectangle", "solid angle", false, projected_rectangle, [](const WarpParams& p) {
                    return wrap(ProjectedSphericalRectangle<double>(make_rectangle(p), vector_param(p, "normal")));
                  }});
  return list;
}

}  // namespace stratum::registry_families
