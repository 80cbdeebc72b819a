/// The six test-integrand families of Genz (1984, "Testing multidimensional
/// integration routines", Tools, Methods and Languages for Scientific and
/// Engineering Computation, North-Holland, pp. 81–94), written as in
/// Surjanovic and Bingham's Virtual Library of Simulation Experiments
/// (sfu.ca/~ssurjano/integration.html), with parameters a (difficulty) and
/// u (location), each one number used in every dimension or d numbers;
/// defaults a = 5, u = 0.5 (the Library's plots). Exact integrals are the
/// products of one-dimensional closed forms (the oscillatory one as in
/// Kaarnioja 2024, "Explicit solutions of Genz test integrals"); the corner
/// peak's is a positive one-dimensional integral, see below.
#include <boost/math/quadrature/exp_sinh.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "integrand_families.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis::integrand_families {

namespace {

/// a or u expanded to d numbers (one number is repeated); checks the length
/// (the schema has checked each number's range).
std::vector<double> expand(const IntegrandParams& params, const std::string& name, unsigned d) {
  const auto& given = params.at(name);
  require(given.size() == 1 || given.size() == d, name, std::to_string(given.size()) + " numbers",
          "needs 1 number or d = " + std::to_string(d) + " numbers");
  return given.size() == 1 ? std::vector<double>(d, given.front()) : given;
}

IntegrandInfo genz_entry(std::string name, std::string description, std::vector<std::string> properties,
                         unsigned max_dim, std::string a_description, Range a_range) {
  IntegrandInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  info.min_dim = 1;
  info.max_dim = max_dim;
  info.default_dim = 2;
  info.properties = std::move(properties);
  info.params = {
      params::reals("a", std::move(a_description) + "; 1 number (every dimension) or d numbers", "5", a_range,
                    {1, max_dim}),
      params::reals("u", "location; 1 number (every dimension) or d numbers", "0.5", closed(0, 1), {1, max_dim})};
  return info;
}

/// ∫_{[0,1]^d} (1 + a·x)^-(d+1) dx. Integrating one coordinate at a time gives
/// the alternating sum (1/(d! Π a_j)) Σ_{v ∈ {0,1}^d} (−1)^|v| / (1 + a·v),
/// which cancels badly as d grows; writing 1/(1 + a·v) = ∫_0^∞ e^{−t(1+a·v)} dt
/// turns the sum into ∫_0^∞ e^{−t} Π_j (1 − e^{−a_j t}) dt, a positive
/// integrand that Boost's exp-sinh quadrature evaluates to ~1e-15 relative.
double corner_peak_integral(const std::vector<double>& a) {
  const auto integrand = [&a](double t) {
    double product = std::exp(-t);
    for (double aj : a) product *= -std::expm1(-aj * t);
    return product;
  };
  boost::math::quadrature::exp_sinh<double> quadrature;
  const double sum = quadrature.integrate(integrand);
  double log_scale = std::lgamma(static_cast<double>(a.size()) + 1);
  for (double aj : a) log_scale += std::log(aj);
  return sum * std::exp(-log_scale);
}

}  // namespace

std::vector<IntegrandInfo> genz() {
  std::vector<IntegrandInfo> list;
  constexpr unsigned max_dim = 1024;

  auto oscillatory = genz_entry("genz-oscillatory", "cos(2 pi u_1 + sum a_i x_i) (Genz 1984, oscillatory)",
                                {"smooth", "oscillatory"}, max_dim, "frequency", any_real());
  oscillatory.make = [](unsigned d, const IntegrandParams& params) {
    const auto a = expand(params, "a", d);
    const auto u = expand(params, "u", d);
    // ∫_0^1 e^{i a x} dx = e^{i a/2} sin(a/2)/(a/2): the real part of the product.
    double phase = 2 * std::numbers::pi * u[0];
    double amplitude = 1;
    for (double aj : a) {
      phase += aj / 2;
      amplitude *= aj == 0 ? 1.0 : std::sin(aj / 2) / (aj / 2);
    }
    const double u1 = u[0];
    return make_function_integrand(d, amplitude * std::cos(phase), [a, u1](const double* x) {
      double sum = 2 * std::numbers::pi * u1;
      for (std::size_t j = 0; j < a.size(); ++j) sum += a[j] * x[j];
      return std::cos(sum);
    });
  };
  list.push_back(std::move(oscillatory));

  auto product_peak = genz_entry("genz-product-peak", "prod (a_i^-2 + (x_i - u_i)^2)^-1 (Genz 1984, product peak)",
                                 {"smooth", "peak"}, max_dim, "peak sharpness", above(0));
  product_peak.make = [](unsigned d, const IntegrandParams& params) {
    const auto a = expand(params, "a", d);
    const auto u = expand(params, "u", d);
    double exact = 1;  // ∫_0^1 dx / (a^-2 + (x−u)²) = a (atan(a(1−u)) + atan(a u))
    for (unsigned j = 0; j < d; ++j) exact *= a[j] * (std::atan(a[j] * (1 - u[j])) + std::atan(a[j] * u[j]));
    return make_function_integrand(d, exact, [a, u](const double* x) {
      double product = 1;
      for (std::size_t j = 0; j < a.size(); ++j) product /= 1 / (a[j] * a[j]) + (x[j] - u[j]) * (x[j] - u[j]);
      return product;
    });
  };
  list.push_back(std::move(product_peak));

  // d ≤ 50 keeps d! Π a_j and the integral itself inside double range for a ≈ 5.
  auto corner_peak = genz_entry("genz-corner-peak", "(1 + sum a_i x_i)^-(d+1) (Genz 1984, corner peak; u unused)",
                                {"smooth", "peak"}, 50, "peak sharpness", above(0));
  corner_peak.make = [](unsigned d, const IntegrandParams& params) {
    const auto a = expand(params, "a", d);
    expand(params, "u", d);  // accepted for a uniform interface, checked, unused
    const double exponent = -static_cast<double>(d) - 1;
    return make_function_integrand(d, corner_peak_integral(a), [a, exponent](const double* x) {
      double sum = 1;
      for (std::size_t j = 0; j < a.size(); ++j) sum += a[j] * x[j];
      return std::pow(sum, exponent);
    });
  };
  list.push_back(std::move(corner_peak));

  auto gaussian = genz_entry("genz-gaussian", "exp(-sum a_i^2 (x_i - u_i)^2) (Genz 1984, Gaussian)", {"smooth", "peak"},
                             max_dim, "width^-1", above(0));
  gaussian.make = [](unsigned d, const IntegrandParams& params) {
    const auto a = expand(params, "a", d);
    const auto u = expand(params, "u", d);
    double exact = 1;  // ∫_0^1 e^{−a²(x−u)²} dx = √π/(2a) (erf(a(1−u)) + erf(a u))
    for (unsigned j = 0; j < d; ++j)
      exact *= std::sqrt(std::numbers::pi) / (2 * a[j]) * (std::erf(a[j] * (1 - u[j])) + std::erf(a[j] * u[j]));
    return make_function_integrand(d, exact, [a, u](const double* x) {
      double sum = 0;
      for (std::size_t j = 0; j < a.size(); ++j) sum += a[j] * a[j] * (x[j] - u[j]) * (x[j] - u[j]);
      return std::exp(-sum);
    });
  };
  list.push_back(std::move(gaussian));

  auto continuous = genz_entry("genz-continuous", "exp(-sum a_i |x_i - u_i|) (Genz 1984, continuous; a kink at u)",
                               {"continuous", "kink"}, max_dim, "decay rate", above(0));
  continuous.make = [](unsigned d, const IntegrandParams& params) {
    const auto a = expand(params, "a", d);
    const auto u = expand(params, "u", d);
    double exact = 1;  // ∫_0^1 e^{−a|x−u|} dx = (2 − e^{−a u} − e^{−a(1−u)}) / a
    for (unsigned j = 0; j < d; ++j) exact *= (2 - std::exp(-a[j] * u[j]) - std::exp(-a[j] * (1 - u[j]))) / a[j];
    return make_function_integrand(d, exact, [a, u](const double* x) {
      double sum = 0;
      for (std::size_t j = 0; j < a.size(); ++j) sum += a[j] * std::abs(x[j] - u[j]);
      return std::exp(-sum);
    });
  };
  list.push_back(std::move(continuous));

  auto discontinuous =
      genz_entry("genz-discontinuous",
                 "exp(sum a_i x_i) where x_1 <= u_1 and x_2 <= u_2, else 0 (Genz 1984, discontinuous; u_3.. unused)",
                 {"discontinuous"}, max_dim, "growth rate", any_real());
  discontinuous.make = [](unsigned d, const IntegrandParams& params) {
    const auto a = expand(params, "a", d);
    const auto u = expand(params, "u", d);
    double exact = 1;  // ∫_0^v e^{a x} dx = expm1(a v)/a (= v at a = 0), v = u_j for j < 2, else 1
    for (unsigned j = 0; j < d; ++j) {
      const double v = j < 2 ? u[j] : 1.0;
      exact *= a[j] == 0 ? v : std::expm1(a[j] * v) / a[j];
    }
    const double u1 = u[0];
    const double u2 = d >= 2 ? u[1] : 1.0;
    return make_function_integrand(d, exact, [a, u1, u2](const double* x) {
      if (x[0] > u1 || (a.size() >= 2 && x[1] > u2)) return 0.0;
      double sum = 0;
      for (std::size_t j = 0; j < a.size(); ++j) sum += a[j] * x[j];
      return std::exp(sum);
    });
  };
  list.push_back(std::move(discontinuous));
  return list;
}

}  // namespace stratum::analysis::integrand_families
