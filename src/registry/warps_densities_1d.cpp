/// Registry entries for the 1D densities and the bilinear density
/// (core triads in include/stratum/warps/densities_1d.hpp).
#include <array>

#include "stratum/warps/densities_1d.hpp"
#include "warp_families.hpp"
#include "warp_triad.hpp"

namespace stratum::registry_families {

std::vector<WarpInfo> warps_densities_1d() {
  std::vector<WarpInfo> list;
  list.push_back(
      {"linear",
       "density proportional to (1 - x) a + x b on [0, 1]",
       "interval [0, 1]",
       "length",
       false,
       {params::real("a", "weight at x = 0", "1", at_least(0)), params::real("b", "weight at x = 1", "3", at_least(0))},
       [](const WarpParams& params) {
         return make_triad<1, 1>(LinearDensity<double>(scalar_param(params, "a"), scalar_param(params, "b")));
       }});
  list.push_back(
      {"tent",
       "tent density (1 - |x|/radius)/radius on [-radius, radius]",
       "interval [-radius, radius]",
       "length",
       false,
       {params::real("radius", "half-width", "1", above(0))},
       [](const WarpParams& params) { return make_triad<1, 1>(TentDensity<double>(scalar_param(params, "radius"))); }});
  list.push_back({"exponential",
                  "exponential density rate exp(-rate x) on [0, inf)",
                  "interval [0, inf)",
                  "length",
                  false,
                  {params::real("rate", "decay rate", "1", above(0))},
                  [](const WarpParams& params) {
                    return make_triad<1, 1>(ExponentialDensity<double>(scalar_param(params, "rate")));
                  }});
  list.push_back(
      {"normal",
       "normal density N(mu, sigma^2) by its inverse CDF",
       "real line",
       "length",
       false,
       {params::real("mu", "mean", "0", any_real()), params::real("sigma", "standard deviation", "1", above(0))},
       [](const WarpParams& params) {
         return make_triad<1, 1>(NormalDensity<double>(scalar_param(params, "mu"), scalar_param(params, "sigma")));
       }});
  list.push_back({"bilinear",
                  "bilinear density on [0, 1]^2 from 4 corner weights",
                  "square [0, 1]^2",
                  "area",
                  false,
                  {params::reals("weights", "corner weights w(0,0), w(1,0), w(0,1), w(1,1), not all zero", "1,2,3,4",
                                 at_least(0), {4, 4})},
                  [](const WarpParams& params) {
                    const auto& w = params.at("weights");
                    require(w.size() == 4, "weights", to_message_string(w.size()) + " numbers",
                            "takes exactly 4 numbers: w(0,0), w(1,0), w(0,1), w(1,1)");
                    return make_triad<2, 2>(BilinearDensity<double>({w[0], w[1], w[2], w[3]}));
                  }});
  return list;
}

}  // namespace stratum::registry_families
