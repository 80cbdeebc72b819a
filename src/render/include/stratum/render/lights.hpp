#pragma once
/// Sampling the renderer's lights from a shading point, and the density of
/// each technique at a given direction (what multiple importance sampling
/// needs; Veach 1997, ch. 9). LECTURE.md §3: an area light sampled
///   - by area: a uniform point y, p_A = 1/A, turned into solid angle by
///     p_ω = p_A d² / cos θ_y;
///   - by solid angle: uniform over the spherical rectangle a quad subtends
///     (Ureña, Fajardo, King 2013, "An area-preserving parametrization for
///     spherical rectangles"), p_ω = 1/Ω;
///   - by projected solid angle: the solid-angle map preceded by a bilinear
///     warp whose corner weights are the cosines at the receiver
///     (warps/projected_solid_angle.hpp; Hart et al. 2020), p ≈ cos θ / Ω⊥.
///   - spheres by solid angle: uniform over the cone of directions that
///     meets the sphere, i.e. the visible cap (Shirley, Wang, Zimmerman 1996,
///     "Monte Carlo techniques for direct lighting calculations"; pbrt-v4
///     §6.2.4), p_ω = 1/(2π(1 − cos θ_max)), sin θ_max = r/d;
///   - triangle meshes (and disks given `segments`, triangle fans) by solid
///     angle: a triangle picked by area, then uniform over the spherical
///     triangle it subtends (Arvo 1995, warps/spherical_triangle.hpp),
///     p_ω = (A_k/A)/Ω_k.
///   - exact disks by area under every strategy: a uniform point by the
///     concentric map (Shirley, Chiu 1997), p_ω = d² / (cos θ_y π r²). A disk
///     subtends no spherical polygon with a closed-form uniform map, so, as
///     pbrt-v4's Disk does, its "solid-angle" sample is the area sample with
///     its density in solid angle.
/// The projected-solid-angle strategy applies to rectangular quads; spheres
/// and triangles fall back to its solid-angle sampling, parallelogram quads
/// (and spheres seen from inside) to area sampling. Point lights are deltas;
/// the environment is sampled cosine-weighted around the receiver's normal.
#include <array>
#include <cmath>
#include <optional>

#include "stratum/render/accelerator.hpp"
#include "stratum/render/scene.hpp"

namespace stratum::render {

enum class LightStrategy { area, solid_angle, projected_solid_angle };

/// One light sample: unit direction from the shading point, distance to the
/// sampled point (infinity for the environment), the radiance arriving along
/// it before visibility (a point light's I/d²), and its solid-angle density
/// (1 for a point light, whose `delta` is set).
struct LightSample {
  Vec3 wi;
  double distance = 0;
  Vec3 radiance;
  double pdf = 0;
  bool delta = false;
};

/// What sampling one light needs from its shape, computed once per scene
/// (render() builds one per light) instead of once per sample.
struct LightGeometry {
  Vec3 normal;               ///< quad: unit normal (edge_u × edge_v); disk: its normal
  double area = 0;           ///< area of the emitting shape
  bool rectangular = false;  ///< quad with perpendicular edges (spherical-rectangle strategies)
  Vec3 emission;             ///< the shape's material's emitted radiance
  bool quad = false;         ///< the shape is a quad (area sampling inline: sample_quad_by_area)
};
LightGeometry light_geometry(const Scene& scene, const Light& light);

/// Area sampling of a quad light, inline: the renderer's most common light
/// sample, where a call and the general dispatch would cost as much as the
/// arithmetic (sample_light calls it too). A uniform point y = corner +
/// u₀ edge_u + u₁ edge_v at `time`, p_ω = d² / (cos θ_y A); empty on the
/// back side.
inline std::optional<LightSample> sample_quad_by_area(const Shape& quad, const LightGeometry& geometry, Vec3 x,
                                                      double time, std::array<double, 2> u) noexcept {
  const Vec3 y = quad.corner + u[0] * quad.edge_u + u[1] * quad.edge_v + time * quad.motion;
  const Vec3 to = y - x;
  const double d2 = dot(to, to), d = std::sqrt(d2);
  if (!(d > 0)) return std::nullopt;
  const Vec3 wi = to / d;
  const double cos_y = -dot(geometry.normal, wi);
  if (cos_y <= 0) return std::nullopt;
  return LightSample{wi, d, geometry.emission, d2 / (cos_y * geometry.area), false};
}

/// Samples `light` from x (unit normal n on the receiving side) at `time`
/// (shapes move linearly over the shutter). Empty when the sample cannot
/// contribute (the light's back side, a point on the receiver's plane).
std::optional<LightSample> sample_light(const Scene& scene, const Light& light, Vec3 x, Vec3 n, double time,
                                        std::array<double, 2> u, LightStrategy strategy);
/// The same, with the light's geometry computed beforehand (the renderer's path).
std::optional<LightSample> sample_light(const Scene& scene, const Light& light, const LightGeometry& geometry, Vec3 x,
                                        Vec3 n, double time, std::array<double, 2> u, LightStrategy strategy);

/// The solid-angle density with which sample_light(light, x, n, …) draws the
/// unit direction wi whose first hit is `hit`, a point of the light's shape
/// seen from its emitting side (for the environment: a ray that escapes, `hit`
/// ignored). 0 for point lights and for directions it never draws.
double light_pdf(const Scene& scene, const Light& light, Vec3 x, Vec3 n, double time, Vec3 wi, const Hit* hit,
                 LightStrategy strategy);
double light_pdf(const Scene& scene, const Light& light, const LightGeometry& geometry, Vec3 x, Vec3 n, double time,
                 Vec3 wi, const Hit* hit, LightStrategy strategy);

/// Area of an emitting shape (for triangle meshes, the sum over triangles).
double shape_area(const Shape& shape);

}  // namespace stratum::render
