#include "stratum/analysis/measures.hpp"

#include <cmath>
#include <string>

#include "measure_families.hpp"
#include "stratum/memory.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {

const std::vector<MeasureInfo>& measures() {
  static const std::vector<MeasureInfo> all = [] {
    std::vector<MeasureInfo> list;
    namespace f = measure_families;
    for (auto family : {f::l2, f::star, f::local, f::edge, f::geometry}) {
      auto part = family();
      list.insert(list.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
    }
    return list;
  }();
  return all;
}

const MeasureInfo& find_measure(std::string_view name) {
  const auto& all = measures();
  for (const auto& measure : all)
    if (measure.name == name) return measure;
  std::string names;
  for (const auto& measure : all) names += (names.empty() ? "" : ", ") + measure.name;
  throw invalid_argument("measure", std::string(name).empty() ? "''" : std::string(name),
                         "valid measures are " + names);
}

void check_unit_cube(const PointView& points) {
  require(points.d >= 1, "d", points.d, "must be at least 1");
  require(points.n >= 2, "n", points.n, "a measure needs at least 2 points");
  for (std::size_t i = 0; i < points.n; ++i)
    for (std::size_t j = 0; j < points.d; ++j) {
      const double v = points(i, j);
      if (!(std::isfinite(v) && v >= 0.0 && v <= 1.0))
        throw invalid_argument("point[" + std::to_string(i) + "][" + std::to_string(j) + "]", to_message_string(v),
                               "coordinates must be finite and in [0, 1]");
    }
}

void require_measure_memory(std::string_view name, std::size_t n, std::size_t d, const MeasureRequest& request) {
  const MeasureInfo& info = find_measure(name);
  const double points = double(n) * double(d) * sizeof(double);
  MeasureRequest bound = request;
  bound.values = bind_params(info.name, info.params, request.params, "measure-param");
  const double working = info.working_bytes ? info.working_bytes(n, d, bound) : 0.0;
  require_memory(points + working,
                 std::to_string(n) + " x " + std::to_string(d) + " points and their " + info.name + " measure");
}

MeasureResult compute_measure(std::string_view name, const PointView& points, const MeasureRequest& request) {
  const MeasureInfo& info = find_measure(name);
  check_unit_cube(points);
  const bool too_small = points.d < info.min_dim;
  const bool too_large = info.max_dim != 0 && points.d > info.max_dim;
  if (too_small || too_large)
    throw invalid_argument("d", std::to_string(points.d),
                           info.name + " is defined for d in [" + std::to_string(info.min_dim) + ", " +
                               (info.max_dim == 0 ? std::string("any") : std::to_string(info.max_dim)) + "]");
  MeasureRequest bound = request;
  bound.values = bind_params(info.name, info.params, request.params, "measure-param");
  if (info.validate) info.validate(points, bound);
  // Points handed in (a file, a Python array) are already in memory; what
  // the measure allocates for them is checked here, before it starts.
  if (info.working_bytes)
    require_memory(
        info.working_bytes(points.n, points.d, bound),
        "the " + info.name + " measure of " + std::to_string(points.n) + " x " + std::to_string(points.d) + " points");
  MeasureResult result = info.compute(points, bound);
  // A measure whose terms leave double precision (products of d factors
  // that over- or underflow at large d) has no number to report: refused,
  // never printed as inf or nan.
  bool finite = std::isfinite(result.value) && (!result.lower || std::isfinite(*result.lower)) &&
                (!result.upper || std::isfinite(*result.upper));
  for (const auto& [key, value] : result.extras) finite = finite && std::isfinite(value);
  if (!finite)
    throw invalid_argument("d", std::to_string(points.d),
                           info.name + " of these " + std::to_string(points.n) + " points is " +
                               to_message_string(result.value) +
                               ": not representable in double precision at this dimension (its terms over- or "
                               "underflow)");
  return result;
}

}  // namespace stratum::analysis
