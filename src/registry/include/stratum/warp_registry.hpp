#pragma once
/// The registry of warps: maps from the unit square (or interval) to a domain
/// (disk, hemisphere, sphere, triangle, spherical polygon, tabulated density),
/// each a triad sample / pdf / invert as in pbrt-v4's util/sampling.h. The
/// CLI (`stratum warp`), Python (`stratum.warp*`), tests and benchmarks all
/// iterate over this list; the per-sample code lives in
/// include/stratum/warps/*.hpp.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "stratum/registry/params.hpp"

namespace stratum {

/// Warp parameters by name, each a flat list of numbers: `cos_theta_max` is
/// {0.5}, `vertices` of a triangle is 6 or 9 numbers (row-major 3×2 or 3×3),
/// a tabulated function is its values with `width`/`height` beside them.
using WarpParams = std::map<std::string, std::vector<double>>;

/// A warp with its parameters validated once; the array calls do no checks
/// beyond what the registry's entry points (below) do first.
class Warp {
 public:
  virtual ~Warp() = default;
  virtual unsigned input_dim() const = 0;   ///< 1 or 2 (coordinates of u)
  virtual unsigned output_dim() const = 0;  ///< 1, 2 or 3 (coordinates of a point)
  /// u: n × input_dim in [0,1); out: n × output_dim.
  virtual void sample(const double* u, std::size_t n, double* out) const = 0;
  /// p: n × output_dim; out: n densities (0 outside the domain).
  virtual void pdf(const double* p, std::size_t n, double* out) const = 0;
  /// p: n × output_dim points of the domain; u: n × input_dim.
  virtual void invert(const double* p, std::size_t n, double* u) const = 0;
};

struct WarpInfo {
  std::string name;
  std::string description;
  std::string domain;            ///< "disk", "hemisphere", "sphere", "interval", ...
  std::string measure;           ///< what the pdf is per: "area", "solid angle", "length"
  bool area_preserving = false;  ///< constant Jacobian: strata map to equal-measure cells
  std::vector<Param> params;     ///< numbers: integer, real, integers or reals
  /// Validates `params` (defaults already filled in) and builds the warp;
  /// throws stratum::invalid_argument naming the parameter.
  std::function<std::unique_ptr<const Warp>(const WarpParams&)> make;
};

/// Every warp, in a stable order.
const std::vector<WarpInfo>& warps();

/// The warp called `name`; throws invalid_argument listing the valid names.
const WarpInfo& find_warp(std::string_view name);

/// Checks `params` against the warp's schema (unknown names, counts,
/// ranges), fills defaults, then calls info.make.
std::unique_ptr<const Warp> make_warp(std::string_view name, const WarpParams& params);

/// Parameters given as text (the CLI's `--warp-param KEY=1,2,3`), parsed by
/// the schema's one parser.
WarpParams parse_warp_params(std::string_view name, const std::map<std::string, std::string>& text);

/// Registry entry points with input checks: u must be finite and in [0,1)
/// (the message names the row and column); p must be finite.
std::vector<double> warp_sample(const Warp& warp, const double* u, std::size_t n);
std::vector<double> warp_pdf(const Warp& warp, const double* p, std::size_t n);
std::vector<double> warp_invert(const Warp& warp, const double* p, std::size_t n);

}  // namespace stratum
