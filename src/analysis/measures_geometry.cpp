// The registry entries of stratification and geometry: t-value, latin,
// min-distance, poisson-radius (algorithms in stratification.cpp and
// geometry.cpp).
#include <cerrno>
#include <cstdlib>
#include <string>

#include "measure_families.hpp"
#include "stratum/analysis/geometry.hpp"
#include "stratum/analysis/stratification.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis::measure_families {
namespace {

std::uint64_t base_of(const MeasureRequest& request) { return request.values.unsigned_integer("base"); }

bool toroidal_of(const MeasureRequest& request) { return request.values.flag("toroidal"); }

/// The neighbour grid's cell heads and per-point links (about one cell per
/// point, 4-byte indices each).
double neighbour_grid_bytes(std::size_t n, std::size_t, const MeasureRequest&) { return 8 * double(n); }

MeasureInfo t_value_measure() {
  MeasureInfo info;
  info.name = "t-value";
  info.description =
      "t-value of a (t,m,s)-net in base b: the smallest t such that every elementary interval of volume b^(t-m) holds "
      "b^t points, N = b^m (Niederreiter 1992, Def. 4.1); extras m, base";
  info.params = {params::integer("base", "the net's base b; N must be a power of b", "2", closed(2, 65536))};
  info.compute = [](const PointView& points, const MeasureRequest& request) {
    const std::uint64_t base = base_of(request);
    const NetQuality quality = net_t_value(points, base);
    MeasureResult result;
    result.value = quality.t;
    result.extras["m"] = quality.m;
    result.extras["base"] = static_cast<double>(base);
    return result;
  };
  // Every coordinate's finest interval index, and the counts of one level's
  // elementary intervals (at most N).
  info.working_bytes = [](std::size_t n, std::size_t d, const MeasureRequest&) {
    return 8 * double(n) * double(d) + 4 * double(n);
  };
  return info;
}

MeasureInfo latin_measure() {
  MeasureInfo info;
  info.name = "latin";
  info.description =
      "Latin (N-rooks) property: 1 if each of the N equal strata of every axis holds exactly one point, else 0 "
      "(Shirley 1991); extras worst_count (most points in one stratum), worst_axis, empty_strata";
  info.compute = [](const PointView& points, const MeasureRequest&) {
    const LatinCheck check = latin_check(points);
    MeasureResult result;
    result.value = check.latin ? 1 : 0;
    result.extras["worst_count"] = static_cast<double>(check.worst_count);
    result.extras["worst_axis"] = static_cast<double>(check.worst_axis);
    result.extras["empty_strata"] = static_cast<double>(check.empty_strata);
    return result;
  };
  info.working_bytes = [](std::size_t n, std::size_t, const MeasureRequest&) { return 8 * double(n); };  // counts
  return info;
}

MeasureInfo min_distance_measure() {
  MeasureInfo info;
  info.name = "min-distance";
  info.description =
      "smallest distance between two points (Euclidean, or toroidal with toroidal=1), by a neighbour grid for d <= 8; "
      "extras first, second (a closest pair's rows)";
  info.params = {
      params::flag("toroidal", "1: distances on the unit torus (axis differences wrapped to [-1/2, 1/2])", "0")};
  info.compute = [](const PointView& points, const MeasureRequest& request) {
    const MinimumDistance closest = minimum_distance(points, toroidal_of(request));
    MeasureResult result;
    result.value = closest.distance;
    result.extras["first"] = static_cast<double>(closest.first);
    result.extras["second"] = static_cast<double>(closest.second);
    return result;
  };
  info.working_bytes = neighbour_grid_bytes;
  return info;
}

MeasureInfo poisson_radius_measure() {
  MeasureInfo info;
  info.name = "poisson-radius";
  info.description =
      "normalized Poisson-disk radius rho = d_min / d_max, d_max the minimum distance of the densest lattice packing "
      "of "
      "N points (2D: sqrt(2/(sqrt(3) N)); Lagae & Dutre 2008); toroidal by default as in their comparison; extras "
      "min_distance, packing_distance";
  info.min_dim = 1;
  info.max_dim = 8;
  info.params = {params::flag("toroidal", "1: distances on the unit torus (Lagae & Dutre 2008), 0: Euclidean", "1")};
  info.compute = [](const PointView& points, const MeasureRequest& request) {
    const double distance = minimum_distance(points, toroidal_of(request)).distance;
    const double packing = densest_packing_distance(points.n, points.d);
    MeasureResult result;
    result.value = distance / packing;
    result.extras["min_distance"] = distance;
    result.extras["packing_distance"] = packing;
    return result;
  };
  info.working_bytes = neighbour_grid_bytes;
  return info;
}

}  // namespace

std::vector<MeasureInfo> geometry() {
  return {t_value_measure(), latin_measure(), min_distance_measure(), poisson_radius_measure()};
}

}  // namespace stratum::analysis::measure_families
