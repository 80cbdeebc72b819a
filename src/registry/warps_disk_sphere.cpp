/// Registry entries for the disk, sphere, cone and triangle warps
/// (core triads in include/stratum/warps/{disk,sphere,triangle}.hpp).
#include <array>
#include <string>

#include "stratum/warps/disk.hpp"
#include "stratum/warps/sphere.hpp"
#include "stratum/warps/triangle.hpp"
#include "warp_families.hpp"
#include "warp_triad.hpp"

namespace stratum::registry_families {
namespace {

using A2 = std::array<double, 2>;
using A3 = std::array<double, 3>;

std::unique_ptr<const Warp> make_triangle(const WarpParams& params) {
  const auto& v = params.at("vertices");
  require(v.size() == 6 || v.size() == 9, "vertices", to_message_string(v.size()) + " numbers",
          "needs 6 (3x2) or 9 (3x3) numbers, row-major");
  if (v.size() == 6) return make_triad<2, 2>(UniformTriangle<double, 2>({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}));
  return make_triad<2, 3>(UniformTriangle<double, 3>({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}));
}

}  // namespace

std::vector<WarpInfo> warps_disk_sphere() {
  std::vector<WarpInfo> list;
  list.push_back({"disk-polar",
                  "equi-areal polar map: theta = 2 pi u0, r = sqrt(u1)",
                  "disk",
                  "area",
                  true,
                  {},
                  [](const WarpParams&) {
                    return make_triad<2, 2>(
                        function_triad(sample_polar_disk<double>, polar_disk_pdf<double>, invert_polar_disk<double>));
                  }});
  list.push_back({"disk-concentric",
                  "Shirley-Chiu 1997 concentric map: squares to circles, low distortion",
                  "disk",
                  "area",
                  true,
                  {},
                  [](const WarpParams&) {
                    return make_triad<2, 2>(function_triad(sample_concentric_disk<double>, concentric_disk_pdf<double>,
                                                           invert_concentric_disk<double>));
                  }});
  list.push_back({"hemisphere-uniform",
                  "uniform directions on the hemisphere z >= 0: z = u0, phi = 2 pi u1",
                  "hemisphere",
                  "solid angle",
                  true,
                  {},
                  [](const WarpParams&) {
                    return make_triad<2, 3>(function_triad(sample_uniform_hemisphere<double>,
                                                           uniform_hemisphere_pdf<double>,
                                                           invert_uniform_hemisphere<double>));
                  }});
  list.push_back({"hemisphere-cosine",
                  "cosine-weighted hemisphere around +z (concentric disk lifted), pdf cos(theta)/pi",
                  "hemisphere",
                  "solid angle",
                  false,
                  {},
                  [](const WarpParams&) {
                    return make_triad<2, 3>(function_triad(sample_cosine_hemisphere<double>,
                                                           cosine_hemisphere_pdf<double>,
                                                           invert_cosine_hemisphere<double>));
                  }});
  list.push_back({"sphere-uniform",
                  "uniform directions on the unit sphere: z = 1 - 2 u0, phi = 2 pi u1",
                  "sphere",
                  "solid angle",
                  true,
                  {},
                  [](const WarpParams&) {
                    return make_triad<2, 3>(function_triad(sample_uniform_sphere<double>, uniform_sphere_pdf<double>,
                                                           invert_uniform_sphere<double>));
                  }});
  list.push_back({"cone",
                  "uniform directions in the cap cos(theta) >= cos_theta_max around +z",
                  "spherical cap",
                  "solid angle",
                  true,
                  {params::real("cos_theta_max", "cosine of the cap's half-angle", "0.5", half_open(-1, 1))},
                  [](const WarpParams& params) {
                    return make_triad<2, 3>(UniformCone<double>(scalar_param(params, "cos_theta_max")));
                  }});
  list.push_back({"triangle",
                  "uniform points in a triangle (Heitz 2019 low-distortion map), in its own space",
                  "triangle",
                  "area",
                  true,
                  {params::reals("vertices", "3x2 or 3x3 vertices, row-major (6 or 9 numbers)", "0,0,1,0,0,1",
                                 any_real(), {6, 9})},
                  make_triangle});
  return list;
}

}  // namespace stratum::registry_families
