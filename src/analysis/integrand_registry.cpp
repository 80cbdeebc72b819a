/// The integrand registry: lookup, parameter checks and checked evaluation.
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "integrand_families.hpp"
#include "stratum/analysis/integrands.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {

const std::vector<IntegrandInfo>& integrands() {
  static const std::vector<IntegrandInfo> all = [] {
    std::vector<IntegrandInfo> list;
    namespace f = integrand_families;
    for (auto family : {f::planar, f::genz}) {
      auto part = family();
      list.insert(list.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
    }
    return list;
  }();
  return all;
}

const IntegrandInfo& find_integrand(std::string_view name) {
  const auto& all = integrands();
  for (const auto& integrand : all)
    if (integrand.name == name) return integrand;
  std::string names;
  for (const auto& integrand : all) names += (names.empty() ? "" : ", ") + integrand.name;
  throw invalid_argument("integrand", name.empty() ? "''" : std::string(name), "valid integrands are " + names);
}

/// The schema's entry for `key`, or an error listing what the integrand takes.
static const Param& integrand_param(const IntegrandInfo& info, const std::string& key, const std::string& value_text) {
  if (const Param* param = find_param(info.params, key)) return *param;
  refuse_unknown_param(info.name, info.params, key, value_text, "integrand-param");
}

/// Parameters inside their ranges can still leave double precision
/// (genz-gaussian a=1e200: a^2 = inf, and inf * 0 = nan at x = u): the
/// integral and the values at 17 points of the diagonal (t, ..., t), t =
/// 0, 1/16, ..., 1, must be finite, or the parameters are refused here
/// rather than giving nan as a result.
static void check_representable(const IntegrandInfo& info, const IntegrandParams& given, const Integrand& integrand) {
  std::string given_text;
  for (const auto& [key, values] : given) {
    std::string list;
    for (double v : values) {
      char buffer[32];
      list += (list.empty() ? "" : ",") + std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
    }
    given_text += (given_text.empty() ? "" : " ") + key + "=" + list;
  }
  auto refuse = [&](const std::string& what) {
    throw invalid_argument(given.empty() ? "integrand" : "integrand-param", given.empty() ? info.name : given_text,
                           what + ": the parameters leave double precision");
  };
  const double exact = integrand.exact();
  if (!std::isfinite(exact)) refuse(info.name + "'s integral is " + to_message_string(exact));
  const std::size_t d = integrand.dimension(), count = 17;
  std::vector<double> points(count * d), values(count);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = 0; j < d; ++j) points[i * d + j] = double(i) / 16;
  integrand.evaluate(points.data(), count, values.data());
  for (std::size_t i = 0; i < count; ++i)
    if (!std::isfinite(values[i]))
      refuse(info.name + " is " + to_message_string(values[i]) + " at x = (" + to_message_string(points[i * d]) +
             (d > 1 ? ", ..." : "") + ")");
}

std::unique_ptr<const Integrand> make_integrand(std::string_view name, unsigned d, const IntegrandParams& params) {
  const IntegrandInfo& info = find_integrand(name);
  if (d == 0) d = info.default_dim;
  require(
      d >= info.min_dim && d <= info.max_dim, "d", d,
      info.name + " is defined for d in [" + std::to_string(info.min_dim) + ", " + std::to_string(info.max_dim) + "]");
  IntegrandParams filled;
  for (const auto& param : info.params) filled[param.name] = as_reals(parse_param(param, param.default_value));
  for (const auto& [key, values] : params) {
    std::string text;
    for (double v : values) text += (text.empty() ? "" : ",") + to_message_string(v);
    check_param(integrand_param(info, key, text), values);
    filled[key] = values;
  }
  auto integrand = info.make(d, filled);
  check_representable(info, params, *integrand);
  return integrand;
}

IntegrandParams parse_integrand_params(std::string_view integrand, const std::map<std::string, std::string>& text) {
  const IntegrandInfo& info = find_integrand(integrand);
  IntegrandParams params;
  for (const auto& [key, value] : text) params[key] = as_reals(parse_param(integrand_param(info, key, value), value));
  return params;
}

std::vector<double> evaluate_integrand(const Integrand& integrand, const double* points, std::size_t n) {
  const std::size_t d = integrand.dimension();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < d; ++j) {
      const double v = points[i * d + j];
      if (!(std::isfinite(v) && v >= 0.0 && v <= 1.0))
        throw invalid_argument("point[" + std::to_string(i) + "][" + std::to_string(j) + "]", to_message_string(v),
                               "coordinates must be finite and in [0, 1]");
    }
  std::vector<double> values(n);
  integrand.evaluate(points, n, values.data());
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(values[i]))
      throw invalid_argument("point[" + std::to_string(i) + "]", "row " + std::to_string(i),
                             "the integrand's value there is " + to_message_string(values[i]) +
                                 ": not representable in double precision with these parameters");
  return values;
}

}  // namespace stratum::analysis
