#pragma once
/// Approximate projected-solid-angle sampling of spherical triangles and
/// rectangles, as pbrt-v4 does for its triangle and bilinear-patch lights
/// (Pharr, Jakob, Humphreys 2023, "Physically Based Rendering", 4th ed.),
/// after Hart, Pharr, Müller, Lopes, McGuire, Shirley 2020, "Practical product
/// sampling by fitting and composing warps" (EGSR). Lecture §3: irradiance
/// E = ∫ L cos θ dω wants p ∝ cos θ over the light's solid angle.
///
/// Exact sampling of cos θ / (projected solid angle) over a spherical polygon
/// needs an iterative or far costlier map (Arvo 2001, "Stratified sampling of
/// 2-manifolds"; Peters 2021, "BRDF importance sampling for polygonal
/// lights"). Instead u is first warped by the bilinear density whose corner
/// weights are |n·ω| at the directions of the polygon's corners, then mapped
/// through the uniform spherical warp. The product is exact where cos θ is
/// bilinear in the spherical warp's parameters and approximates
/// cos θ / projected-solid-angle otherwise; its pdf is always exact:
///   p(ω) = bilinear_pdf(invert_spherical(ω)) / Ω.
/// As in pbrt-v4, each weight is at least 0.01, so the density stays positive
/// over the whole polygon even where a corner is at grazing incidence. The
/// approximation helps when cos θ varies between the corners; a light that
/// spans a wide cone around the normal (corners at grazing angles, peak in the
/// middle) gets a nearly uniform bilinear density and no variance reduction
/// (see the irradiance test in tests/warps/projected_solid_angle_test.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "stratum/util/error.hpp"
#include "stratum/warps/densities_1d.hpp"
#include "stratum/warps/spherical_rectangle.hpp"
#include "stratum/warps/spherical_triangle.hpp"
#include "stratum/warps/vector3.hpp"

namespace stratum {

/// A uniform spherical warp (SphericalTriangle or SphericalRectangle) preceded
/// by the bilinear cosine warp for a receiving surface with normal `normal`.
template <class Spherical, class Real = double>
class ProjectedSolidAngle {
 public:
  /// Throws invalid_argument naming `normal` when it is the zero vector.
  ProjectedSolidAngle(const Spherical& spherical, const Vector3<Real>& normal)
      : spherical_(spherical), bilinear_(corner_weights(spherical, normal)) {}

  const Spherical& spherical() const noexcept { return spherical_; }
  const BilinearDensity<Real>& bilinear() const noexcept { return bilinear_; }

  Vector3<Real> sample(std::array<Real, 2> u) const noexcept { return spherical_.sample(bilinear_.sample(u)); }
  Real pdf(const Vector3<Real>& w) const noexcept {
    if (!spherical_.contains(w)) return Real(0);
    return bilinear_.pdf(spherical_.invert(w)) / spherical_.solid_angle();
  }
  std::array<Real, 2> invert(const Vector3<Real>& w) const noexcept {
    const auto b = bilinear_.invert(spherical_.invert(w));
    return {clamp_to_unit(b[0]), clamp_to_unit(b[1])};
  }

  /// max(0.01, |n·ω|) at the images of u = (0,0), (1,0), (0,1), (1,1).
  static std::array<Real, 4> corner_weights(const Spherical& spherical, const Vector3<Real>& normal) {
    using namespace vector3;
    if (!(length(normal) > Real(0))) throw invalid_argument("normal", to_text(normal), "must be a non-zero vector");
    const Vector3<Real> n = normalize(normal);
    const auto corners = spherical.corner_directions();
    std::array<Real, 4> w{};
    for (std::size_t i = 0; i < 4; ++i) w[i] = std::max(Real(0.01), std::abs(dot(n, corners[i])));
    return w;
  }

 private:
  Spherical spherical_;
  BilinearDensity<Real> bilinear_;
};

template <class Real = double>
using ProjectedSphericalTriangle = ProjectedSolidAngle<SphericalTriangle<Real>, Real>;
template <class Real = double>
using ProjectedSphericalRectangle = ProjectedSolidAngle<SphericalRectangle<Real>, Real>;

}  // namespace stratum
