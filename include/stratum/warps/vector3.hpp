#pragma once
/// The few 3-vector operations the spherical warps need, on std::array so the
/// headers stay free of a geometry library and work for float and double.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "stratum/util/error.hpp"

namespace stratum {

template <class Real>
using Vector3 = std::array<Real, 3>;

namespace vector3 {

template <class Real>
constexpr Vector3<Real> add(const Vector3<Real>& a, const Vector3<Real>& b) noexcept {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class Real>
constexpr Vector3<Real> sub(const Vector3<Real>& a, const Vector3<Real>& b) noexcept {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class Real>
constexpr Vector3<Real> scale(const Vector3<Real>& a, Real s) noexcept {
  return {a[0] * s, a[1] * s, a[2] * s};
}
template <class Real>
constexpr Real dot(const Vector3<Real>& a, const Vector3<Real>& b) noexcept {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class Real>
constexpr Vector3<Real> cross(const Vector3<Real>& a, const Vector3<Real>& b) noexcept {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class Real>
Real length(const Vector3<Real>& a) noexcept {
  return std::sqrt(dot(a, a));
}
/// a / |a|; the zero vector stays zero (callers check degeneracy up front).
template <class Real>
Vector3<Real> normalize(const Vector3<Real>& a) noexcept {
  const Real l = length(a);
  return l > Real(0) ? scale(a, Real(1) / l) : a;
}
/// The part of a perpendicular to the unit vector b (one Gram–Schmidt step), normalized.
template <class Real>
Vector3<Real> perpendicular_part(const Vector3<Real>& a, const Vector3<Real>& b) noexcept {
  return normalize(sub(a, scale(b, dot(a, b))));
}
/// Angle between unit vectors, accurate near 0 and π too: 2·asin(|a − b|/2)
/// instead of acos(a·b), whose slope is infinite there.
template <class Real>
Real angle_between(const Vector3<Real>& a, const Vector3<Real>& b) noexcept {
  if (dot(a, b) < Real(0))
    return std::numbers::pi_v<Real> - Real(2) * std::asin(std::min(Real(1), length(add(a, b)) / Real(2)));
  return Real(2) * std::asin(std::min(Real(1), length(sub(a, b)) / Real(2)));
}

/// "(x, y, z)" for error messages.
template <class Real>
std::string to_text(const Vector3<Real>& a) {
  return "(" + to_message_string(a[0]) + ", " + to_message_string(a[1]) + ", " + to_message_string(a[2]) + ")";
}

}  // namespace vector3
}  // namespace stratum
