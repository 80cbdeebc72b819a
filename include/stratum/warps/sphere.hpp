#pragma once
/// Maps from the unit square to directions (unit vectors) around +z: uniform
/// hemisphere, cosine-weighted hemisphere, uniform sphere and uniform cone,
/// each a triad sample / pdf / invert (pbrt-v4 util/sampling.h). Densities are
/// per steradian. Points passed to pdf and invert are taken to be unit vectors.
///
/// The uniform maps use Archimedes' hat-box theorem: z = cos θ uniform on an
/// interval and φ uniform give equal solid angle for equal (z, φ) area, so
/// they are area-preserving up to a constant and keep strata. The cosine map
/// is not (its density cos θ / π varies).
#include <array>
#include <cmath>
#include <numbers>

#include "stratum/util/error.hpp"
#include "stratum/util/host_device.hpp"
#include "stratum/warps/disk.hpp"

namespace stratum {

namespace detail {
/// Direction with cos θ = z and azimuth φ = 2π u.
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 3> direction_from_z(Real z, Real u) noexcept {
  const Real sin_theta = std::sqrt(std::max(Real(0), 1 - z * z));
  const Real phi = 2 * std::numbers::pi_v<Real> * u;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), z};
}
template <class Real>
STRATUM_HOST_DEVICE Real azimuth_fraction(const std::array<Real, 3>& p) noexcept {
  return clamp_to_unit(angle_0_2pi(p[1], p[0]) * (std::numbers::inv_pi_v<Real> / 2));
}
}  // namespace detail

/// Uniform on the hemisphere z ≥ 0: z = u0, φ = 2π u1; pdf 1/(2π).
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 3> sample_uniform_hemisphere(std::array<Real, 2> u) noexcept {
  return detail::direction_from_z(u[0], u[1]);
}
template <class Real>
STRATUM_HOST_DEVICE Real uniform_hemisphere_pdf(std::array<Real, 3> p) noexcept {
  return p[2] >= 0 ? std::numbers::inv_pi_v<Real> / 2 : Real(0);
}
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 2> invert_uniform_hemisphere(std::array<Real, 3> p) noexcept {
  return {clamp_to_unit(p[2]), detail::azimuth_fraction(p)};
}

/// Uniform on the sphere: z = 1 − 2 u0, φ = 2π u1; pdf 1/(4π).
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 3> sample_uniform_sphere(std::array<Real, 2> u) noexcept {
  return detail::direction_from_z(1 - 2 * u[0], u[1]);
}
template <class Real>
STRATUM_HOST_DEVICE Real uniform_sphere_pdf(std::array<Real, 3> /*p*/) noexcept {
  return std::numbers::inv_pi_v<Real> / 4;
}
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 2> invert_uniform_sphere(std::array<Real, 3> p) noexcept {
  return {clamp_to_unit((1 - p[2]) / 2), detail::azimuth_fraction(p)};
}

/// Cosine-weighted hemisphere (Malley's method): a uniform point of the
/// concentric disk (Shirley & Chiu 1997) lifted to the hemisphere, z =
/// √(1 − x² − y²); pdf cos θ / π, the density that makes irradiance
/// estimates of a constant sky exact (LECTURE.md §3).
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 3> sample_cosine_hemisphere(std::array<Real, 2> u) noexcept {
  const auto d = sample_concentric_disk(u);
  return {d[0], d[1], std::sqrt(std::max(Real(0), 1 - d[0] * d[0] - d[1] * d[1]))};
}
template <class Real>
STRATUM_HOST_DEVICE Real cosine_hemisphere_pdf(std::array<Real, 3> p) noexcept {
  return p[2] >= 0 ? p[2] * std::numbers::inv_pi_v<Real> : Real(0);
}
template <class Real>
STRATUM_HOST_DEVICE std::array<Real, 2> invert_cosine_hemisphere(std::array<Real, 3> p) noexcept {
  return invert_concentric_disk<Real>({p[0], p[1]});
}

/// Uniform directions in the spherical cap cos θ ≥ cos_theta_max around +z:
/// cos θ = 1 − u0 (1 − cos_theta_max), φ = 2π u1; pdf 1/(2π(1 − cos_theta_max)).
template <class Real>
class UniformCone {
 public:
  /// cos_theta_max in [−1, 1): a cap of zero solid angle (1) has no density.
  explicit UniformCone(Real cos_theta_max) : cos_theta_max_(cos_theta_max) {
    require(cos_theta_max >= -1 && cos_theta_max < 1, "cos_theta_max", cos_theta_max,
            "must be in [-1, 1) (1 would be a cap of zero solid angle)");
    pdf_ = 1 / (2 * std::numbers::pi_v<Real> * (1 - cos_theta_max));
  }
  STRATUM_HOST_DEVICE Real cos_theta_max() const noexcept { return cos_theta_max_; }

  STRATUM_HOST_DEVICE std::array<Real, 3> sample(std::array<Real, 2> u) const noexcept {
    return detail::direction_from_z(1 - u[0] * (1 - cos_theta_max_), u[1]);
  }
  STRATUM_HOST_DEVICE Real pdf(std::array<Real, 3> p) const noexcept { return p[2] >= cos_theta_max_ ? pdf_ : Real(0); }
  STRATUM_HOST_DEVICE std::array<Real, 2> invert(std::array<Real, 3> p) const noexcept {
    return {clamp_to_unit((1 - p[2]) / (1 - cos_theta_max_)), detail::azimuth_fraction(p)};
  }

 private:
  Real cos_theta_max_;
  Real pdf_;
};

}  // namespace stratum
