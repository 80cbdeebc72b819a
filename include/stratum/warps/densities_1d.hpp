#pragma once
/// Densities that renderers and studies sample by inverting their CDF: linear,
/// tent, exponential, normal and bilinear, each a triad sample / pdf / invert.
/// The linear, tent and bilinear triads follow pbrt-v4's util/sampling.h
/// (SampleLinear, SampleTent, SampleBilinear). The free functions do no
/// checks; the classes validate their parameters once at construction.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/erf.hpp>

#include "stratum/util/error.hpp"
#include "stratum/warps/disk.hpp"

namespace stratum {

/// Density ∝ (1 − x) a + x b on [0, 1] (a, b ≥ 0, a + b > 0): pdf 2((1 − x) a + x b)/(a + b).
template <class Real>
Real linear_pdf(Real x, Real a, Real b) noexcept {
  if (x < 0 || x > 1) return 0;
  return 2 * ((1 - x) * a + x * b) / (a + b);
}

/// Inverse CDF written as u (a + b) / (a + √((1 − u) a² + u b²)), which has no
/// cancellation when a ≈ b (pbrt-v4 SampleLinear). a = b = 0 (reached only by
/// the conditional of a bilinear density on a measure-zero line) returns u.
template <class Real>
Real sample_linear(Real u, Real a, Real b) noexcept {
  if (u == 0 && a == 0) return 0;
  if (a + b == 0) return u;
  const Real x = u * (a + b) / (a + std::sqrt((1 - u) * a * a + u * b * b));
  return clamp_to_unit(x);
}

/// The CDF: x (a (2 − x) + b x) / (a + b).
template <class Real>
Real invert_linear(Real x, Real a, Real b) noexcept {
  if (a + b == 0) return clamp_to_unit(x);
  return clamp_to_unit(x * (a * (2 - x) + b * x) / (a + b));
}

namespace detail {
inline void check_linear_weights(double a, double b) {
  require(a >= 0 && std::isfinite(a), "a", a, "must be >= 0 and finite");
  require(b >= 0 && std::isfinite(b), "b", b, "must be >= 0 and finite");
  if (!(a + b > 0))
    throw invalid_argument("a, b", to_message_string(a) + ", " + to_message_string(b), "must not both be zero");
}
}  // namespace detail

/// Linear density on [0, 1] with end weights a (at 0) and b (at 1).
template <class Real>
class LinearDensity {
 public:
  LinearDensity(Real a, Real b) : a_(a), b_(b) { detail::check_linear_weights(a, b); }
  Real sample(Real u) const noexcept { return sample_linear(u, a_, b_); }
  Real pdf(Real x) const noexcept { return linear_pdf(x, a_, b_); }
  Real invert(Real x) const noexcept { return invert_linear(std::clamp(x, Real(0), Real(1)), a_, b_); }

 private:
  Real a_, b_;
};

/// Tent of half-width r on [−r, r]: pdf (1 − |x|/r)/r. Each half is a linear
/// density picked by u < ½ (pbrt-v4 SampleTent), so the map is monotone.
template <class Real>
class TentDensity {
 public:
  explicit TentDensity(Real radius) : radius_(radius) {
    require(radius > 0 && std::isfinite(radius), "radius", radius, "must be > 0 and finite");
  }
  Real sample(Real u) const noexcept {
    if (u < Real(0.5)) return -radius_ + radius_ * sample_linear(2 * u, Real(0), Real(1));
    return radius_ * sample_linear(2 * u - 1, Real(1), Real(0));
  }
  Real pdf(Real x) const noexcept {
    const Real t = std::abs(x) / radius_;
    return t >= 1 ? Real(0) : (1 - t) / radius_;
  }
  Real invert(Real x) const noexcept {
    const Real t = std::clamp(x / radius_, Real(-1), Real(1));
    if (t < 0) return clamp_to_unit(invert_linear(t + 1, Real(0), Real(1)) / 2);
    return clamp_to_unit(Real(0.5) + invert_linear(t, Real(1), Real(0)) / 2);
  }

 private:
  Real radius_;
};

/// Exponential with rate a on [0, ∞): x = −log(1 − u)/a, pdf a e^(−a x).
/// log1p/expm1 keep full precision for small u and x.
template <class Real>
class ExponentialDensity {
 public:
  explicit ExponentialDensity(Real rate) : rate_(rate) {
    require(rate > 0 && std::isfinite(rate), "rate", rate, "must be > 0 and finite");
  }
  Real sample(Real u) const noexcept { return -std::log1p(-u) / rate_; }
  Real pdf(Real x) const noexcept { return x < 0 ? Real(0) : rate_ * std::exp(-rate_ * x); }
  Real invert(Real x) const noexcept { return x <= 0 ? Real(0) : clamp_to_unit(-std::expm1(-rate_ * x)); }

 private:
  Real rate_;
};

/// Normal(mu, sigma) by its inverse CDF, x = mu − σ √2 erfc⁻¹(2u) (Boost.Math):
/// erfc⁻¹ of 2u keeps the lower tail accurate where 2u − 1 would round to −1.
/// u = 0 has no finite quantile; it is raised to 2⁻⁶⁴ (x ≈ mu − 9.1 σ), a
/// measure-zero change.
template <class Real>
class NormalDensity {
  using no_throw =
      boost::math::policies::policy<boost::math::policies::domain_error<boost::math::policies::ignore_error>,
                                    boost::math::policies::overflow_error<boost::math::policies::ignore_error>>;

 public:
  NormalDensity(Real mu, Real sigma) : mu_(mu), sigma_(sigma) {
    require(std::isfinite(mu), "mu", mu, "must be finite");
    require(sigma > 0 && std::isfinite(sigma), "sigma", sigma, "must be > 0 and finite");
  }
  Real sample(Real u) const noexcept {
    const Real v = std::max(u, Real(0x1p-64));
    return mu_ - sigma_ * std::numbers::sqrt2_v<Real> * boost::math::erfc_inv(2 * v, no_throw());
  }
  Real pdf(Real x) const noexcept {
    const Real z = (x - mu_) / sigma_;
    return std::exp(-z * z / 2) / (sigma_ * std::sqrt(2 * std::numbers::pi_v<Real>));
  }
  Real invert(Real x) const noexcept {
    const Real z = (x - mu_) / sigma_;
    return clamp_to_unit(boost::math::erfc(-z / std::numbers::sqrt2_v<Real>, no_throw()) / 2);
  }

 private:
  Real mu_, sigma_;
};

/// Bilinear density on [0, 1]² with corner weights w = {w(0,0), w(1,0),
/// w(0,1), w(1,1)} (pbrt-v4 SampleBilinear): y from its marginal, linear with
/// end weights w0 + w1 and w2 + w3, then x from the linear conditional at y.
template <class Real>
class BilinearDensity {
 public:
  explicit BilinearDensity(const std::array<Real, 4>& w) : w_(w) {
    bool ok = true;
    for (Real v : w) ok = ok && v >= 0 && std::isfinite(v);
    if (!(ok && w[0] + w[1] + w[2] + w[3] > 0))
      throw invalid_argument("weights",
                             to_message_string(w[0]) + ", " + to_message_string(w[1]) + ", " + to_message_string(w[2]) +
                                 ", " + to_message_string(w[3]),
                             "weights must be >= 0, finite and not all zero");
  }
  std::array<Real, 2> sample(std::array<Real, 2> u) const noexcept {
    const Real y = sample_linear(u[1], w_[0] + w_[1], w_[2] + w_[3]);
    const Real x = sample_linear(u[0], (1 - y) * w_[0] + y * w_[2], (1 - y) * w_[1] + y * w_[3]);
    return {x, y};
  }
  Real pdf(std::array<Real, 2> p) const noexcept {
    const Real x = p[0], y = p[1];
    if (x < 0 || x > 1 || y < 0 || y > 1) return 0;
    return 4 * ((1 - x) * (1 - y) * w_[0] + x * (1 - y) * w_[1] + (1 - x) * y * w_[2] + x * y * w_[3]) /
           (w_[0] + w_[1] + w_[2] + w_[3]);
  }
  std::array<Real, 2> invert(std::array<Real, 2> p) const noexcept {
    const Real x = std::clamp(p[0], Real(0), Real(1)), y = std::clamp(p[1], Real(0), Real(1));
    return {invert_linear(x, (1 - y) * w_[0] + y * w_[2], (1 - y) * w_[1] + y * w_[3]),
            invert_linear(y, w_[0] + w_[1], w_[2] + w_[3])};
  }

 private:
  std::array<Real, 4> w_;
};

}  // namespace stratum
