#pragma once
/// Maps from the unit square to the unit disk, each a triad sample / pdf /
/// invert (as pbrt-v4's util/sampling.h). Both maps have constant Jacobian
/// (area-preserving up to the factor π), so the pdf is 1/π per unit area on
/// the disk and a stratified square stays stratified on the disk.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "stratum/util/host_device.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

/// A value in [0, 1) for the unit square's coordinates: rounding in an inverse
/// may land on 1 or slightly below 0.
template <class Real>
STRATUM_HOST_DEVICE constexpr Real clamp_to_unit(Real value) noexcept {
  constexpr Real below_one =
      sizeof(Real) == sizeof(float) ? Real(one_minus_epsilon_float) : Real(one_minus_epsilon_double);
  return std::clamp(value, Real(0), below_one);
}

/// The polar angle of (x, y) in [0, 2π).
template <class Real>
STRATUM_HOST_DEVICE Real angle_0_2pi(Real y, Real x) noexcept {
  const Real phi = std::atan2(y, x);
  return phi < 0 ? phi + 2 * std::numbers::pi_v<Real> : phi;
}

/// Uniform density on the unit disk: 1/π inside (boundary included), 0 outside.
template <class Real>
STRATUM_HOST_DEVICE Real uniform_disk_pdf(std::array<Real, 2> p) noexcept {
  return p[0] * p[0] + p[1] * p[1] <= Real(1) ? std::numbers::inv_pi_v<Real> : Real(0);
}

/// Equi-areal polar map: θ = 2π u0, r = √u1 (the square root makes the
/// Jacobian r dr dθ constant; LECTURE.md §5). Strata become annular sectors,
/// long and thin near the rim.
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 2> sample_polar_disk(std::array<Real, 2> u) noexcept {
  const Real r = std::sqrt(u[1]);
  const Real theta = 2 * std::numbers::pi_v<Real> * u[0];
  return {r * std::cos(theta), r * std::sin(theta)};
}

template <class Real>
STRATUM_HOST_DEVICE Real polar_disk_pdf(std::array<Real, 2> p) noexcept {
  return uniform_disk_pdf(p);
}

/// u0 = θ / 2π, u1 = r²; the seam θ = 0 maps to u0 = 0.
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 2> invert_polar_disk(std::array<Real, 2> p) noexcept {
  const Real theta = angle_0_2pi(p[1], p[0]);
  return {clamp_to_unit(theta * (std::numbers::inv_pi_v<Real> / 2)), clamp_to_unit(p[0] * p[0] + p[1] * p[1])};
}

/// Concentric map of Shirley & Chiu (1997, "A low distortion map between disk
/// and square"): concentric squares of [-1,1]² go to concentric circles; on
/// the wedge |a| > |b|, r = a and φ = (π/4)(b/a). Strata stay compact (aspect
/// ratio bounded), unlike the polar map's slivers.
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 2> sample_concentric_disk(std::array<Real, 2> u) noexcept {
  const Real a = 2 * u[0] - 1, b = 2 * u[1] - 1;
  if (a == 0 && b == 0) return {0, 0};
  constexpr Real quarter_pi = std::numbers::pi_v<Real> / 4;
  Real r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a, phi = quarter_pi * (b / a);
  } else {
    r = b, phi = 2 * quarter_pi - quarter_pi * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

template <class Real>
STRATUM_HOST_DEVICE Real concentric_disk_pdf(std::array<Real, 2> p) noexcept {
  return uniform_disk_pdf(p);
}

/// Inverse of the concentric map: on the wedge |x| ≥ |y|, a = ±r (sign of x)
/// and b = a (4/π) atan(y/x); on the other wedge the roles swap. The
/// diagonals are the measure-zero seams between the wedges.
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 2> invert_concentric_disk(std::array<Real, 2> p) noexcept {
  const Real x = p[0], y = p[1];
  const Real r = std::sqrt(x * x + y * y);
  if (r == 0) return {Real(0.5), Real(0.5)};
  constexpr Real four_over_pi = 4 * std::numbers::inv_pi_v<Real>;
  Real a, b;
  if (std::abs(x) >= std::abs(y)) {
    a = std::copysign(r, x), b = a * four_over_pi * std::atan(y / x);
  } else {
    b = std::copysign(r, y), a = b * four_over_pi * std::atan(x / y);
  }
  return {clamp_to_unit((a + 1) / 2), clamp_to_unit((b + 1) / 2)};
}

}  // namespace stratum
