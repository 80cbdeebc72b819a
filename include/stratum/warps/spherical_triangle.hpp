#pragma once
/// Uniform sampling of the solid angle subtended by a triangle (Arvo 1995,
/// "Stratified sampling of spherical triangles", SIGGRAPH '95), with its
/// inverse. Lecture §3: sampling a light by solid angle instead of by area
/// removes the 1/r² and cosine factors of the geometry term from the
/// estimator, so a small or near light no longer gives fireflies.
///
/// The map is area-preserving onto the sphere (its Jacobian is the solid angle
/// Ω everywhere), so strata of [0,1)² become equal-solid-angle strata of the
/// spherical triangle: u0 chooses the sub-triangle A B Ĉ of area u0·Ω (Ĉ on
/// the arc from A to C), u1 the point on the arc from B to Ĉ, uniformly in
/// cos of the angle to B. The inverse intersects the great circle through B
/// and ω with the arc AC to recover Ĉ, and measures the sub-triangle's area
/// with the formula of Van Oosterom and Strackee (1983, "The solid angle of a
/// plane triangle").
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <string>

#include "stratum/util/error.hpp"
#include "stratum/warps/disk.hpp"  // clamp_to_unit
#include "stratum/warps/vector3.hpp"

namespace stratum {

/// The solid angle of the triangle of unit vectors (a, b, c) by Van Oosterom
/// and Strackee (1983): tan(Ω/2) = |a·(b×c)| / (1 + a·b + b·c + c·a).
template <class Real>
Real spherical_triangle_area(const Vector3<Real>& a, const Vector3<Real>& b, const Vector3<Real>& c) noexcept {
  using namespace vector3;
  const Real numerator = std::abs(dot(a, cross(b, c)));
  const Real denominator = Real(1) + dot(a, b) + dot(b, c) + dot(c, a);
  return Real(2) * std::atan2(numerator, denominator);
}

template <class Real = double>
class SphericalTriangle {
 public:
  /// The triangle (v0, v1, v2) seen from `origin`. Throws invalid_argument
  /// naming `vertices` when a vertex is the origin or the triangle subtends
  /// no solid angle (collinear vertices, or a plane through the origin).
  SphericalTriangle(const Vector3<Real>& v0, const Vector3<Real>& v1, const Vector3<Real>& v2,
                    const Vector3<Real>& origin = {0, 0, 0}) {
    using namespace vector3;
    const std::array<Vector3<Real>, 3> v{v0, v1, v2};
    for (std::size_t i = 0; i < 3; ++i)
      if (!(length(sub(v[i], origin)) > Real(0)))
        throw invalid_argument("vertices", to_text(v[i]), "each vertex must differ from the origin " + to_text(origin));
    a_ = normalize(sub(v0, origin)), b_ = normalize(sub(v1, origin)), c_ = normalize(sub(v2, origin));
    // Girard: the area is the spherical excess α + β + γ − π, the angles
    // being those between the great-circle planes through each pair.
    const Vector3<Real> n_ab = normalize(cross(a_, b_)), n_bc = normalize(cross(b_, c_)),
                        n_ca = normalize(cross(c_, a_));
    const bool planes_defined = length(n_ab) > Real(0) && length(n_bc) > Real(0) && length(n_ca) > Real(0);
    alpha_ = angle_between(n_ab, scale(n_ca, Real(-1)));
    const Real beta = angle_between(n_bc, scale(n_ab, Real(-1)));
    const Real gamma = angle_between(n_ca, scale(n_bc, Real(-1)));
    area_ = planes_defined ? alpha_ + beta + gamma - std::numbers::pi_v<Real> : Real(0);
    const Real min_area = sizeof(Real) == sizeof(float) ? Real(1e-5) : Real(1e-12);
    if (!(std::isfinite(area_) && area_ > min_area))
      throw invalid_argument("vertices", to_text(v0) + ", " + to_text(v1) + ", " + to_text(v2),
                             "the triangle seen from the origin " + to_text(origin) + " subtends " +
                                 to_message_string(area_) + " sr; it must subtend a positive solid angle (> " +
                                 to_message_string(min_area) +
                                 " sr): vertices not collinear and their plane not through the origin");
    cos_alpha_ = std::cos(alpha_), sin_alpha_ = std::sin(alpha_);
    cos_c_ = dot(a_, b_);
    c_perp_a_ = perpendicular_part(c_, a_);
    // Inward normals of the three great-circle edges: a direction is inside
    // when it lies on the inner side of all three.
    const Real orientation = dot(a_, cross(b_, c_)) > Real(0) ? Real(1) : Real(-1);
    inward_[0] = scale(n_ab, orientation), inward_[1] = scale(n_bc, orientation), inward_[2] = scale(n_ca, orientation);
  }

  Real solid_angle() const noexcept { return area_; }
  /// Unit directions from the origin to the vertices.
  const Vector3<Real>& a() const noexcept { return a_; }
  const Vector3<Real>& b() const noexcept { return b_; }
  const Vector3<Real>& c() const noexcept { return c_; }
  /// Images of u = (0,0), (1,0), (0,1), (1,1): B, B, A, C (u1 = 0 is vertex B;
  /// u1 = 1 runs along the arc from A to C). The projected-solid-angle warp
  /// weights these corners.
  std::array<Vector3<Real>, 4> corner_directions() const noexcept { return {b_, b_, a_, c_}; }

  /// Arvo's algorithm (1995, Fig. 2): a unit direction uniform in solid angle.
  Vector3<Real> sample(std::array<Real, 2> u) const noexcept {
    using namespace vector3;
    const Real u0 = u[0], u1 = u[1];
    // Choose Ĉ on arc AC so that triangle A B Ĉ has area u0·Ω.
    const Real sub_area = u0 * area_;
    const Real s = std::sin(sub_area - alpha_), t = std::cos(sub_area - alpha_);
    const Real p = t - cos_alpha_;
    const Real q = s + sin_alpha_ * cos_c_;
    const Real denominator = (q * s + p * t) * sin_alpha_;
    Real cos_b = denominator != Real(0) ? ((q * t - p * s) * cos_alpha_ - q) / denominator : Real(1);
    cos_b = std::clamp(cos_b, Real(-1), Real(1));
    const Vector3<Real> c_hat =
        add(scale(a_, cos_b), scale(c_perp_a_, std::sqrt(std::max(Real(0), Real(1) - cos_b * cos_b))));
    // Then the point on arc B Ĉ, uniform in z = cos(angle to B).
    const Real z = Real(1) - u1 * (Real(1) - dot(c_hat, b_));
    const Real r = std::sqrt(std::max(Real(0), Real(1) - z * z));
    return normalize(add(scale(b_, z), scale(perpendicular_part(c_hat, b_), r)));
  }

  /// 1/Ω for directions inside the triangle's cone, 0 outside (w need not be unit).
  Real pdf(const Vector3<Real>& w) const noexcept { return contains(w) ? Real(1) / area_ : Real(0); }

  /// Whether w points into the triangle's cone; directions on its edges count
  /// (with a few ulps of slack, so that samples on an edge keep their density).
  bool contains(const Vector3<Real>& direction) const noexcept {
    using namespace vector3;
    if (!(length(direction) > Real(0))) return false;
    const Vector3<Real> w = normalize(direction);
    constexpr Real slack = -Real(64) * std::numeric_limits<Real>::epsilon();
    return dot(w, inward_[0]) >= slack && dot(w, inward_[1]) >= slack && dot(w, inward_[2]) >= slack;
  }

  /// The u in [0,1)² whose sample is w (w inside the triangle; need not be unit).
  std::array<Real, 2> invert(const Vector3<Real>& direction) const noexcept {
    using namespace vector3;
    const Vector3<Real> w = normalize(direction);
    // Ĉ: where the great circle through B and w meets the arc AC.
    const Vector3<Real> plane_bw = cross(b_, w);
    if (length(plane_bw) <= Real(0)) return {Real(0), Real(0)};  // w = B: u1 = 0, any u0
    Vector3<Real> c_hat = normalize(cross(plane_bw, cross(a_, c_)));
    if (dot(c_hat, add(a_, c_)) < Real(0)) c_hat = scale(c_hat, Real(-1));
    const Real u0 = spherical_triangle_area(a_, b_, c_hat) / area_;
    const Real span = Real(1) - dot(c_hat, b_);
    const Real u1 = span > Real(0) ? (Real(1) - dot(w, b_)) / span : Real(0);
    return {clamp_to_unit(u0), clamp_to_unit(u1)};
  }

 private:
  Vector3<Real> a_{}, b_{}, c_{}, c_perp_a_{};
  std::array<Vector3<Real>, 3> inward_{};
  Real alpha_ = 0, area_ = 0, cos_alpha_ = 1, sin_alpha_ = 0, cos_c_ = 1;
};

}  // namespace stratum
