#pragma once
/// Uniform sampling of the solid angle subtended by a rectangle (Ureña,
/// Fajardo, King 2013, "An area-preserving parametrization for spherical
/// rectangles", EGSR), with its inverse. Lecture §3: rectangular area lights
/// sampled by solid angle, not by area.
///
/// In a local frame with the origin at o, x along edge_u, y along edge_v and
/// the rectangle in the plane z = z0 < 0, the rectangle is [x0, x1] × [y0, y1].
/// u0 picks the abscissa xu at which the sub-rectangle [x0, xu] × [y0, y1]
/// subtends u0·S (S the whole solid angle, from the four corner angles of the
/// spherical quadrilateral); u1 picks the height along the segment x = xu
/// uniformly in the sine of its elevation h = y/√(x² + y² + z0²), which is
/// uniform in solid angle along that segment. The inverse measures the
/// sub-rectangle's solid angle the same way (only two corner angles change).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "stratum/util/error.hpp"
#include "stratum/warps/disk.hpp"  // clamp_to_unit
#include "stratum/warps/vector3.hpp"

namespace stratum {

template <class Real = double>
class SphericalRectangle {
 public:
  /// The rectangle corner + s·edge_u + t·edge_v, s, t ∈ [0,1], seen from
  /// `origin`. Throws invalid_argument naming edge_u/edge_v when an edge is
  /// zero, the edges are parallel or not perpendicular, and naming `origin`
  /// when the origin lies on the rectangle's plane.
  SphericalRectangle(const Vector3<Real>& corner, const Vector3<Real>& edge_u, const Vector3<Real>& edge_v,
                     const Vector3<Real>& origin = {0, 0, 0}) {
    using namespace vector3;
    const Real length_u = length(edge_u), length_v = length(edge_v);
    if (!(length_u > Real(0)))
      throw invalid_argument("edge_u", to_text(edge_u), "must be non-zero (a rectangle with positive area)");
    if (!(length_v > Real(0)))
      throw invalid_argument("edge_v", to_text(edge_v), "must be non-zero (a rectangle with positive area)");
    const Real tolerance = sizeof(Real) == sizeof(float) ? Real(1e-4) : Real(1e-9);
    if (!(length(cross(edge_u, edge_v)) > tolerance * length_u * length_v))
      throw invalid_argument(
          "edge_v", to_text(edge_v),
          "must not be parallel to edge_u = " + to_text(edge_u) + " (a rectangle with positive area)");
    if (!(std::abs(dot(edge_u, edge_v)) <= tolerance * length_u * length_v))
      throw invalid_argument(
          "edge_v", to_text(edge_v),
          "must be perpendicular to edge_u = " + to_text(edge_u) + " (a rectangle, not a parallelogram)");
    x_ = scale(edge_u, Real(1) / length_u);
    y_ = scale(edge_v, Real(1) / length_v);
    z_ = cross(x_, y_);
    const Vector3<Real> d = sub(corner, origin);
    z0_ = dot(d, z_);
    const Real scale_of_scene = length(d) + length_u + length_v;
    if (!(std::abs(z0_) > tolerance * scale_of_scene))
      throw invalid_argument("origin", to_text(origin),
                             "must not lie on the rectangle's plane (corner " + to_text(corner) + ", edges " +
                                 to_text(edge_u) + ", " + to_text(edge_v) + ")");
    if (z0_ > Real(0)) z_ = scale(z_, Real(-1)), z0_ = -z0_;
    x0_ = dot(d, x_), y0_ = dot(d, y_);
    x1_ = x0_ + length_u, y1_ = y0_ + length_v;
    // Normals of the planes through the origin and each edge (Ureña et al., Alg. 1).
    n0_ = normalize(Vector3<Real>{0, z0_, -y0_});
    const Vector3<Real> n1 = normalize(Vector3<Real>{-z0_, 0, x1_});
    n2_ = normalize(Vector3<Real>{0, -z0_, y1_});
    n3_ = normalize(Vector3<Real>{z0_, 0, -x0_});
    const Real g2 = interior_angle(n2_, n3_), g3 = interior_angle(n3_, n0_);
    b0_ = n0_[2], b1_ = n2_[2];
    k_ = Real(2) * std::numbers::pi_v<Real> - g2 - g3;
    solid_angle_ = interior_angle(n0_, n1) + interior_angle(n1, n2_) - k_;
    const Real min_area = sizeof(Real) == sizeof(float) ? Real(1e-5) : Real(1e-12);
    if (!(std::isfinite(solid_angle_) && solid_angle_ > min_area))
      throw invalid_argument("origin", to_text(origin),
                             "the rectangle subtends " + to_message_string(solid_angle_) +
                                 " sr from it; it must subtend more than " + to_message_string(min_area) + " sr");
  }

  Real solid_angle() const noexcept { return solid_angle_; }
  /// Images of u = (0,0), (1,0), (0,1), (1,1): the directions to corner,
  /// corner + edge_u, corner + edge_v and the opposite corner.
  std::array<Vector3<Real>, 4> corner_directions() const noexcept {
    return {world(x0_, y0_), world(x1_, y0_), world(x0_, y1_), world(x1_, y1_)};
  }

  /// A unit direction uniform in the rectangle's solid angle (Ureña et al. 2013, Alg. 1).
  Vector3<Real> sample(std::array<Real, 2> u) const noexcept {
    const Real u0 = u[0], u1 = u[1];
    const Real au = u0 * solid_angle_ + k_;
    const Real sin_au = std::sin(au);
    Real xu = 0;
    if (sin_au != Real(0)) {
      const Real fu = (std::cos(au) * b0_ - b1_) / sin_au;
      const Real cu = std::clamp(std::copysign(Real(1), fu) / std::sqrt(fu * fu + b0_ * b0_), Real(-1), Real(1));
      const Real sine = std::sqrt(std::max(Real(0), Real(1) - cu * cu));
      xu = sine > Real(0) ? -(cu * z0_) / sine : (cu > 0 ? x1_ : x0_);
    }
    xu = std::clamp(xu, x0_, x1_);
    const Real d = std::sqrt(xu * xu + z0_ * z0_);
    const Real h0 = y0_ / std::sqrt(d * d + y0_ * y0_), h1 = y1_ / std::sqrt(d * d + y1_ * y1_);
    const Real hv = h0 + u1 * (h1 - h0), hv2 = hv * hv;
    const Real yv = hv2 < Real(1) ? std::clamp(hv * d / std::sqrt(Real(1) - hv2), y0_, y1_) : y1_;
    return world(xu, yv);
  }

  /// 1/S for directions whose ray from the origin hits the rectangle, else 0.
  Real pdf(const Vector3<Real>& w) const noexcept { return contains(w) ? Real(1) / solid_angle_ : Real(0); }

  /// Whether the ray along w hits the rectangle; points on its edges count
  /// (with a few ulps of slack, so that samples on an edge keep their density).
  bool contains(const Vector3<Real>& w) const noexcept {
    Real x = 0, y = 0;
    if (!hit(w, x, y)) return false;
    const Real slack_x = edge_slack * (x1_ - x0_), slack_y = edge_slack * (y1_ - y0_);
    return x >= x0_ - slack_x && x <= x1_ + slack_x && y >= y0_ - slack_y && y <= y1_ + slack_y;
  }

  /// The u in [0,1)² whose sample is w (w a direction towards the rectangle).
  std::array<Real, 2> invert(const Vector3<Real>& w) const noexcept {
    Real xu = 0, yv = 0;
    if (!hit(w, xu, yv)) return {Real(0), Real(0)};
    xu = std::clamp(xu, x0_, x1_), yv = std::clamp(yv, y0_, y1_);
    // Solid angle of [x0, xu] × [y0, y1]: the edge x = xu has a new plane normal.
    const Vector3<Real> n1 = vector3::normalize(Vector3<Real>{-z0_, 0, xu});
    const Real sub_area = interior_angle(n0_, n1) + interior_angle(n1, n2_) - k_;
    const Real d = std::sqrt(xu * xu + z0_ * z0_);
    const Real h0 = y0_ / std::sqrt(d * d + y0_ * y0_), h1 = y1_ / std::sqrt(d * d + y1_ * y1_);
    const Real hv = yv / std::sqrt(d * d + yv * yv);
    const Real u1 = h1 > h0 ? (hv - h0) / (h1 - h0) : Real(0);
    return {clamp_to_unit(sub_area / solid_angle_), clamp_to_unit(u1)};
  }

 private:
  static constexpr Real edge_slack = Real(64) * std::numeric_limits<Real>::epsilon();
  /// The interior angle between two edge planes with normals a and b: acos(−a·b).
  static Real interior_angle(const Vector3<Real>& a, const Vector3<Real>& b) noexcept {
    return vector3::angle_between(a, vector3::scale(b, Real(-1)));
  }
  /// The unit direction to the local point (x, y, z0).
  Vector3<Real> world(Real x, Real y) const noexcept {
    using namespace vector3;
    return normalize(add(add(scale(x_, x), scale(y_, y)), scale(z_, z0_)));
  }
  /// Local (x, y) where the ray from the origin along w meets the plane.
  bool hit(const Vector3<Real>& w, Real& x, Real& y) const noexcept {
    using namespace vector3;
    const Real wz = dot(w, z_);
    if (!(wz < Real(0))) return false;
    const Real t = z0_ / wz;
    x = t * dot(w, x_), y = t * dot(w, y_);
    return true;
  }

  Vector3<Real> x_{}, y_{}, z_{}, n0_{}, n2_{}, n3_{};
  Real z0_ = 0, x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0, b0_ = 0, b1_ = 0, k_ = 0, solid_angle_ = 0;
};

}  // namespace stratum
