#include "stratum/warp_registry.hpp"

#include <cmath>
#include <string>

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

static std::string numbers_text(const std::vector<double>& values) {
  std::string text;
  for (double v : values) text += (text.empty() ? "" : ",") + to_message_string(v);
  return text;
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
  return info.make(filled);
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
  return out;
}

}  // namespace stratum
