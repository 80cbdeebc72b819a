#pragma once
/// The 2D scan shared by the exact star-discrepancy methods (d = 2 directly,
/// d ≥ 3 at the bottom of the nested sweep). Private to src/analysis.
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace stratum::analysis::star_detail {

inline constexpr double kNoValue = -std::numeric_limits<double>::infinity();

/// The two one-sided maxima over the critical corners (a, b) of a 2D sweep:
///   open   = max  weight·a·b − #{x < a, y < b}/N   (a, b from the points' x, y or 1)
///   closed = max  #{x ≤ a, y ≤ b}/N − weight·a·b  (a, b from the points' x, y)
/// `weight` is the volume of the box in the remaining coordinates (1 in 2D).
/// Each value is rounded as fl(fl(fl(weight·a)·b) − K) or fl(K − fl(fl(weight·a)·b))
/// with K = fl(count·inv_n), without fused multiply-adds: the DEM method
/// (star_discrepancy_dem.cpp) rounds the same boxes the same way, so the
/// exact methods agree to the last bit.
struct SweepTerms {
  double open = kNoValue;
  double closed = kNoValue;
};

/// points: (x, y) pairs sorted by x, every coordinate < 1 (points with a
/// coordinate 1 lie in no half-open box and are left out by the caller);
/// inv_n = 1/N with N the size of the whole set. `threads` > 1 splits the
/// sweep into x-slabs of equal work; the result does not depend on it.
SweepTerms sweep_2d(const std::vector<std::pair<double, double>>& points, double weight, double inv_n,
                    unsigned threads);

}  // namespace stratum::analysis::star_detail
