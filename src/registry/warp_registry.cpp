#include "stratum/warp_registry.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "stratum/util/error.hpp"
#include "warp_families.hpp"

namespace stratum {

const std::vector<WarpInfo>& warps() {
  static const std::vector<WarpInfo> all = [] {
    std::vector<WarpInfo> list;
    namespace f = registry_families;
    for (auto family : {f::warps_disk_sphere, f::warps_densities_1d, f::warps_spherical_polygons, f::warps_tabulated}) {
      auto part = family();
      list.insert(list.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
    }
    return list;
  }();
  return all;
}

const WarpInfo& find_warp(std::string_view name) {
  const auto& all = warps();
  for (const auto& warp : all)
    if (warp.name == name) return warp;
  std::string names;
  for (const auto& warp : all) names += (names.empty() ? "" : ", ") + warp.name;
  throw invalid_argument("map", std::string(name).empty() ? "''" : std::string(name), "valid maps are " + names);
}

/// The schema's entry for `key`, or an error listing what the warp takes.
static const Param& warp_param(const WarpInfo& info, const std::string& key, const std::string& value_text) {
  if (const Param* param = find_param(info.params, key)) return *param;
  refuse_unknown_param(info.name, info.params, key, value_text, "warp-param");
}

/// Shortest text that reads back as each value ("1e-300", not 1.0000000000000001e-300).
static std::string numbers_text(const std::vector<double>& values) {
  std::string text;
  for (double v : values) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
    text += (text.empty() ? "" : ",") + std::string(buffer, end);
  }
  return text;
}

/// Probes a built warp at the centres of a 4 x 4 (or 4) grid of u: every
/// point must be finite and its pdf finite and positive. Parameters that
/// pass their ranges can still leave double precision (rate=1e-320 puts
/// the points at inf); refused here rather than printed as results.
static void check_density(const WarpInfo& info, const WarpParams& given, const Warp& warp) {
  const unsigned in = warp.input_dim(), out = warp.output_dim();
  const std::size_t count = in == 1 ? 4 : 16;
  std::vector<double> u(count * in), p(count * out), pdf(count);
  for (std::size_t i = 0; i < count; ++i)
    for (unsigned k = 0; k < in; ++k) u[i * in + k] = (double((k == 0 ? i : i / 4) % 4) + 0.5) / 4;
  warp.sample(u.data(), count, p.data());
  warp.pdf(p.data(), count, pdf.data());
  for (std::size_t i = 0; i < count; ++i) {
    bool finite = std::isfinite(pdf[i]) && pdf[i] > 0;
    for (unsigned k = 0; k < out; ++k) finite = finite && std::isfinite(p[i * out + k]);
    if (finite) continue;
    std::string given_text, point_text, u_text;
    for (const auto& [key, value] : given)
      given_text += (given_text.empty() ? "" : " ") + key + "=" + numbers_text(value);
    for (unsigned k = 0; k < out; ++k) point_text += (k ? ", " : "") + to_message_string(p[i * out + k]);
    for (unsigned k = 0; k < in; ++k) u_text += (k ? ", " : "") + to_message_string(u[i * in + k]);
    throw invalid_argument(given.empty() ? "map" : "warp-param", given.empty() ? info.name : given_text,
                           info.name + " maps u = (" + u_text + ") to (" + point_text + ") with pdf " +
                               to_message_string(pdf[i]) +
                               ": the parameters leave double precision (a point must be finite, its pdf finite "
                               "and positive)");
  }
}

std::unique_ptr<const Warp> make_warp(std::string_view name, const WarpParams& params) {
  const WarpInfo& info = find_warp(name);
  WarpParams filled = params;
  for (const auto& [key, value] : params) check_param(warp_param(info, key, numbers_text(value)), value);
  for (const auto& param : info.params) {
    if (filled.count(param.name)) continue;
    require(!param.default_value.empty(), param.name, "(missing)", info.name + " needs it: " + param.description);
    filled[param.name] = as_reals(parse_param(param, param.default_value));
  }
  auto warp = info.make(filled);
  check_density(info, params, *warp);
  return warp;
}

WarpParams parse_warp_params(std::string_view name, const std::map<std::string, std::string>& text) {
  const WarpInfo& info = find_warp(name);
  WarpParams params;
  for (const auto& [key, value] : text) params[key] = as_reals(parse_param(warp_param(info, key, value), value));
  return params;
}

namespace {
void check_rows(const char* what, const double* x, std::size_t n, unsigned dim, bool unit_interval) {
  for (std::size_t i = 0; i < n; ++i)
    for (unsigned j = 0; j < dim; ++j) {
      const double v = x[i * dim + j];
      const bool ok = std::isfinite(v) && (!unit_interval || (v >= 0.0 && v < 1.0));
      if (!ok)
        throw invalid_argument(std::string(what) + "[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                               to_message_string(v), unit_interval ? "must be in [0, 1)" : "must be finite");
    }
}
}  // namespace

std::vector<double> warp_sample(const Warp& warp, const double* u, std::size_t n) {
  check_rows("u", u, n, warp.input_dim(), true);
  std::vector<double> out(n * warp.output_dim());
  warp.sample(u, n, out.data());
  return out;
}

std::vector<double> warp_pdf(const Warp& warp, const double* p, std::size_t n) {
  check_rows("p", p, n, warp.output_dim(), false);
  std::vector<double> out(n);
  warp.pdf(p, n, out.data());
  return out;
}

std::vector<double> warp_invert(const Warp& warp, const double* p, std::size_t n) {
  check_rows("p", p, n, warp.output_dim(), false);
  std::vector<double> out(n * warp.input_dim());
  warp.invert(p, n, out.data());
  // A point outside the warp's domain (where its pdf is 0) has no u: the
  // inverses clamp, so it would come back as a u that maps elsewhere.
  const unsigned in = warp.input_dim(), dim = warp.output_dim();
  std::vector<double> density(n);
  warp.pdf(p, n, density.data());
  auto refuse = [&](std::size_t i, const std::string& why) {
    std::string point;
    for (unsigned j = 0; j < dim; ++j) point += (j ? ", " : "") + to_message_string(p[i * dim + j]);
    throw invalid_argument("p[" + std::to_string(i) + "]", "(" + point + ")", "is outside the warp's domain: " + why);
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!(density[i] > 0) || !std::isfinite(density[i]))
      refuse(i, "its pdf there is " + to_message_string(density[i]) + ", so no u maps to it");
    for (unsigned k = 0; k < in; ++k)
      if (!(out[i * in + k] >= 0.0 && out[i * in + k] <= 1.0))
        refuse(i, "its inverse u[" + std::to_string(k) + "] = " + to_message_string(out[i * in + k]) +
                      " is not in [0, 1]");
  }
  return out;
}

}  // namespace stratum
