// Registry entries for the tabulated warps: piecewise-constant densities on
// [0,1] and [0,1]² (pbrt-v4's PiecewiseConstant1D/2D) and the alias method.
//
// `alias` in an array API: the chosen index i of n weights and the leftover r
// of u (uniform in [0,1) given i) are returned as one number x = (i + r)/n in
// [0,1), so i = floor(n·x). Its pdf is pmf(i)·n per unit length: the same
// distribution as piecewise-1d over the same values, reached in O(1) instead
// of a binary search. The inverse maps x back to the u that produced it.
#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <utility>

#include "stratum/util/error.hpp"
#include "stratum/warps/alias_table.hpp"
#include "stratum/warps/piecewise_1d.hpp"
#include "stratum/warps/piecewise_2d.hpp"
#include "warp_families.hpp"
#include "warp_triad.hpp"

namespace stratum::registry_families {
namespace {

class AliasWarp final : public Warp {
 public:
  explicit AliasWarp(std::span<const double> weights) : table_(weights, "values") {}
  unsigned input_dim() const override { return 1; }
  unsigned output_dim() const override { return 1; }
  void sample(const double* u, std::size_t n, double* out) const override {
    const double size = static_cast<double>(table_.size());
    for (std::size_t i = 0; i < n; ++i) {
      const auto s = table_.sample(u[i]);
      out[i] = clamp_to_unit((static_cast<double>(s.index) + s.leftover) / size);
    }
  }
  void pdf(const double* p, std::size_t n, double* out) const override {
    for (std::size_t i = 0; i < n; ++i)
      out[i] = (p[i] >= 0 && p[i] <= 1) ? table_.pmf(index_of(p[i])) * static_cast<double>(table_.size()) : 0.0;
  }
  void invert(const double* p, std::size_t n, double* u) const override {
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t index = index_of(p[i]);
      const double leftover =
          std::clamp(p[i] * static_cast<double>(table_.size()) - static_cast<double>(index), 0.0, 1.0);
      u[i] = table_.invert(index, clamp_to_unit(leftover));
    }
  }

 private:
  std::size_t index_of(double x) const {
    const double scaled = std::clamp(x, 0.0, 1.0) * static_cast<double>(table_.size());
    return std::min(table_.size() - 1, static_cast<std::size_t>(scaled));
  }
  AliasTable<double> table_;
};

/// A 1-element parameter holding a positive integer (a table's width or height).
std::size_t positive_integer(const WarpParams& params, const std::string& name) {
  const auto& value = params.at(name);
  require(value.size() == 1, name, "(" + std::to_string(value.size()) + " numbers)", "must be one positive integer");
  const double v = value[0];
  require(v >= 1 && v <= 1e12 && v == std::floor(v), name, v, "must be a positive integer");
  return static_cast<std::size_t>(v);
}

}  // namespace

std::vector<WarpInfo> warps_tabulated() {
  std::vector<WarpInfo> list;
  list.push_back({"piecewise-1d",
                  "density proportional to a tabulated function on width equal bins of [0,1] (pbrt-v4 "
                  "PiecewiseConstant1D), by CDF inversion",
                  "interval",
                  "length",
                  false,
                  {params::reals("values", "the function's values, not all zero", "", at_least(0)),
                   params::integer("width", "how many values (bins)", "", closed(1, 0x1p40))},
                  [](const WarpParams& p) -> std::unique_ptr<const Warp> {
                    const std::size_t width = positive_integer(p, "width");
                    const auto& values = p.at("values");
                    require(values.size() == width, "values", "(" + std::to_string(values.size()) + " values)",
                            "must hold width = " + std::to_string(width) + " values");
                    return make_triad<1, 1>(PiecewiseConstant1D<double>(values));
                  }});
  list.push_back({"piecewise-2d",
                  "density proportional to a tabulated function on a width x height grid of [0,1]^2 (e.g. an "
                  "environment map): marginal rows, then conditional columns (pbrt-v4 PiecewiseConstant2D)",
                  "square",
                  "area",
                  false,
                  {params::reals("values", "height rows of width values, row-major; not all zero", "", at_least(0)),
                   params::integer("width", "values per row (x bins)", "", closed(1, 0x1p40)),
                   params::integer("height", "rows (y bins)", "", closed(1, 0x1p40))},
                  [](const WarpParams& p) -> std::unique_ptr<const Warp> {
                    const std::size_t width = positive_integer(p, "width"), height = positive_integer(p, "height");
                    return make_triad<2, 2>(PiecewiseConstant2D<double>(p.at("values"), width, height));
                  }});
  list.push_back(
      {"alias",
       "alias method (Walker 1977, Vose 1991): index i of n weights with probability w_i / sum in O(1); "
       "returns x = (i + leftover)/n in [0,1), so i = floor(n x); pdf = pmf(i) n",
       "interval",
       "length",
       false,
       {params::reals("values", "the n weights, not all zero", "", at_least(0))},
       [](const WarpParams& p) -> std::unique_ptr<const Warp> { return std::make_unique<AliasWarp>(p.at("values")); }});
  return list;
}

}  // namespace stratum::registry_families
