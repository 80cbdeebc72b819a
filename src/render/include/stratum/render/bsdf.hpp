#pragma once
/// The renderer's non-specular BSDFs at one surface point, evaluated and
/// importance-sampled in world space (LECTURE.md §3: p ∝ f cos θ where it
/// can be had):
/// - diffuse (Lambert): f = ρ/π, sampled cosine-weighted (p = cos θ/π), so
///   f cos θ / p = ρ exactly;
/// - glossy: the normalized modified Phong lobe of Lafortune and Willems 1994
///   ("Using the modified Phong reflectance model for physically based
///   rendering", KU Leuven CW report 197),
///     f(ωo, ωi) = ρ (e + 2)/(2π) cos^e α,   α = angle(ωi, mirror direction of ωo),
///   zero below the surface. Its directional albedo is at most ρ for every
///   incidence and exactly ρ at normal incidence (energy conserving, tested).
///   The lobe is sampled exactly: cos α = u₀^{1/(e+1)}, φ = 2π u₁ around the
///   mirror direction, p(ωi) = (e + 1)/(2π) cos^e α (Lafortune, Willems §4;
///   pbrt 2nd ed. §14.5 for the same warp), so f cos θ / p = ρ (e+2)/(e+1) cos θ.
///   Samples below the surface get weight 0 (the pdf still counts them, as
///   MIS needs the density of the technique, not of its useful part).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "stratum/render/scene.hpp"
#include "stratum/warps/sphere.hpp"

namespace stratum::render {

/// An orthonormal basis (s, t, n), right-handed, around the unit vector n
/// (Duff et al. 2017, "Building an orthonormal basis, revisited").
struct Frame {
  Vec3 s, t, n;
  explicit Frame(Vec3 normal) : n(normal) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    s = {1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    t = {b, sign + n.y * n.y * a, -n.y};
  }
  Vec3 to_world(const std::array<double, 3>& v) const { return v[0] * s + v[1] * t + v[2] * n; }
};

/// One BSDF sample: a unit direction, its solid-angle density, and the
/// estimator weight f cos θ / p (zero when the direction is below the surface).
struct BsdfSample {
  Vec3 wi;
  Vec3 weight;
  double pdf = 0;
};

/// The BSDF of a diffuse or glossy material at a point with unit normal
/// `normal` (on the viewer's side) seen from unit direction `wo` (towards the viewer).
class Bsdf {
 public:
  Bsdf(const Material& material, Vec3 normal, Vec3 wo)
      : rho_(material.reflectance),
        n_(normal),
        glossy_(material.type == MaterialType::glossy),
        exponent_(material.exponent),
        mirror_((2 * dot(normal, wo)) * normal - wo) {}

  Vec3 normal() const noexcept { return n_; }
  bool glossy() const noexcept { return glossy_; }

  /// f(wo, wi) for a unit wi; 0 below the surface.
  Vec3 eval(Vec3 wi) const noexcept {
    if (dot(n_, wi) <= 0) return {};
    if (!glossy_) return rho_ / std::numbers::pi;
    const double c = dot(mirror_, wi);
    if (c <= 0) return {};
    return ((exponent_ + 2) / (2 * std::numbers::pi) * std::pow(c, exponent_)) * rho_;
  }

  /// The solid-angle density with which sample() draws the unit direction wi.
  double pdf(Vec3 wi) const noexcept {
    if (!glossy_) return std::max(0.0, dot(n_, wi)) / std::numbers::pi;
    const double c = dot(mirror_, wi);
    return c <= 0 ? 0.0 : (exponent_ + 1) / (2 * std::numbers::pi) * std::pow(c, exponent_);
  }

  BsdfSample sample(std::array<double, 2> u) const noexcept {
    BsdfSample s;
    if (!glossy_) {
      const auto local = sample_cosine_hemisphere(u);
      s.wi = Frame(n_).to_world(local);
      s.pdf = local[2] / std::numbers::pi;
      if (s.pdf > 0) s.weight = rho_;
      return s;
    }
    const double cos_a = std::pow(u[0], 1 / (exponent_ + 1));
    const double sin_a = std::sqrt(std::max(0.0, 1 - cos_a * cos_a));
    const double phi = 2 * std::numbers::pi * u[1];
    s.wi = normalize(Frame(mirror_).to_world({sin_a * std::cos(phi), sin_a * std::sin(phi), cos_a}));
    s.pdf = (exponent_ + 1) / (2 * std::numbers::pi) * std::pow(cos_a, exponent_);
    const double cos_i = dot(n_, s.wi);
    if (cos_i > 0 && s.pdf > 0) s.weight = ((exponent_ + 2) / (exponent_ + 1) * cos_i) * rho_;
    return s;
  }

 private:
  Vec3 rho_;
  Vec3 n_;
  bool glossy_;
  double exponent_;
  Vec3 mirror_;  ///< wo reflected about n
};

}  // namespace stratum::render
