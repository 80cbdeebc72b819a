#pragma once
/// The registry's warp families, one source file each.
#include <vector>

#include "stratum/warp_registry.hpp"

namespace stratum::registry_families {
std::vector<WarpInfo> warps_disk_sphere();   // warps_disk_sphere.cpp: disk-polar, disk-concentric, hemisphere-*,
                                             // sphere-uniform, cone, triangle
std::vector<WarpInfo> warps_densities_1d();  // warps_densities_1d.cpp: linear, tent, exponential, normal, bilinear
std::vector<WarpInfo> warps_spherical_polygons();  // warps_spherical_polygons.cpp: spherical-triangle,
                                                   // spherical-rectangle, projected variants
std::vector<WarpInfo> warps_tabulated();           // warps_tabulated.cpp: piecewise-1d, piecewise-2d, alias
}  // namespace stratum::registry_families
