// The registry entry of the star discrepancy: exact where the exact methods
// reach (d = 1 closed form, d = 2 sweep, d ≥ 3 Dobkin-Eppstein-Mitchell),
// otherwise Thiémard's bounds, reported as kind "bounds" with lower and upper.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "measure_families.hpp"
#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis::measure_families {
namespace {

constexpr const char* kDefaultMaxBoxes = "1000000";

const std::string& method_of(const MeasureRequest& request) { return request.values.text("method"); }

/// The default δ: 0.05 up to d = 3, doubled every two dimensions above (the
/// partition's size grows roughly like δ^-d), at most 0.4.
double default_delta(std::size_t d) {
  const std::size_t doublings = d <= 3 ? 0 : std::min<std::size_t>(3, (d - 2) / 2);
  return 0.05 * static_cast<double>(std::size_t{1} << doublings);
}

double delta_of(const MeasureRequest& request, std::size_t d) {
  return request.values.has("delta") ? request.values.real("delta") : default_delta(d);
}

std::uint64_t max_boxes_of(const MeasureRequest& request) { return request.values.unsigned_integer("max_boxes"); }

bool use_exact(const PointView& points, const std::string& method) {
  return method == "exact" || (method == "auto" && star_exact_feasible(points.n, points.d));
}

}  // namespace

std::vector<MeasureInfo> star() {
  MeasureInfo info;
  info.name = "star";
  info.description =
      "star discrepancy D* = sup over anchored boxes [0,x) of |A/N - volume| (Niederreiter 1992): exact in 1D "
      "(closed form), 2D (O(N^2) sweep, N <= 2^18) and d >= 3 (Dobkin-Eppstein-Mitchell 1996, O(N^(1+d/2)); N <= "
      "14000, 2200, 650, 260, 140, 80 for d = 3..8); otherwise Thiemard (2001) bounds";
  info.min_dim = 1;
  info.max_dim = 0;
  info.params = {
      params::choice("method", "auto (exact where feasible, else bounds), exact, or bounds", "auto",
                     {"auto", "exact", "bounds"}),
      params::real("delta",
                   "bounds: width of the delta-partition, upper - lower <= delta; default 0.05 for d <= 3, 0.1 for "
                   "d = 4, 5, 0.2 for d = 6, 7, 0.4 above, doubled until the partition fits in max_boxes",
                   "", open(0, 1)),
      params::integer("max_boxes", "bounds: the most boxes the delta-partition may use", kDefaultMaxBoxes, at_least(1)),
  };
  info.validate = [](const PointView& points, const MeasureRequest& request) {
    const std::string& method = method_of(request);
    if (method == "exact" && !star_exact_feasible(points.n, points.d))
      star_discrepancy_exact(points, request.threads);  // throws the message naming d (or n) and method=bounds
  };
  info.compute = [](const PointView& points, const MeasureRequest& request) {
    MeasureResult result;
    if (use_exact(points, method_of(request))) {
      result.value = star_discrepancy_exact(points, request.threads);
      result.kind = "exact";
      return result;
    }
    // Without an explicit delta, start at the default and double it until the
    // partition fits in max_boxes (an attempt that overflows stops early).
    double delta = delta_of(request, points.d);
    const bool adapt = !request.values.has("delta");
    StarDiscrepancyBounds bounds;
    for (;;) {
      try {
        bounds = star_discrepancy_bounds(points, delta, max_boxes_of(request), request.threads);
        break;
      } catch (const invalid_argument&) {
        if (!adapt || 2 * delta >= 1) throw;
        delta *= 2;
      }
    }
    result.kind = "bounds";
    result.value = bounds.upper;
    result.lower = bounds.lower;
    result.upper = bounds.upper;
    result.extras["delta"] = delta;
    result.extras["boxes"] = static_cast<double>(bounds.boxes);
    return result;
  };
  // What each method allocates besides the points (the memory guard): the
  // 1D copy; the 2D sweep's pairs, counts, group starts and per-worker y
  // lists; Dobkin-Eppstein-Mitchell's index lists and cuts (N is small where
  // it is feasible); the bounds' sorted axes, point lists of the first
  // boxes and per-worker depth-first stacks (the children of a box hold
  // disjoint subsets of its points, so each stack holds at most N indices).
  info.working_bytes = [](std::size_t n, std::size_t d, const MeasureRequest& request) {
    const double points = double(n), workers = concurrent_workers(request.threads);
    if (method_of(request) == "exact" || (method_of(request) == "auto" && star_exact_feasible(n, d))) {
      if (d == 1) return 8 * points;
      if (d == 2) return (56 + 8 * workers) * points;
      return (32 * double(d) + 8 * workers) * points;
    }
    return 8 * points * double(d) + 4 * points * (2 + workers);
  };
  return {info};
}

}  // namespace stratum::analysis::measure_families
