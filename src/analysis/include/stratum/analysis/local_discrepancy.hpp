#pragma once
/// The local discrepancy of a 2D point set, as a picture (LECTURE.md §10):
///
///   Δ(x, y) = n(x, y)/N − x·y,   n(x, y) = #{i : p_i ∈ [0,x) × [0,y)},
///
/// on a grid of corners, and the box where |Δ| reaches its supremum D*_N
/// (Niederreiter 1992, "Random Number Generation and Quasi-Monte Carlo
/// Methods", Def. 2.1). star_discrepancy.hpp computes the value D*_N fast;
/// this file says *where* it is attained, which the value alone does not.
///
/// The supremum is approached at the critical corners whose coordinates are
/// point coordinates or 1 (Gnewuch, Srivastav, Winzen 2009, Lemma 1.1): either
/// from below, x·y − n_open(x, y)/N with the half-open count, or as the limit
/// from above of the closed count, n_closed(x, y)/N − x·y, where a point on
/// the box's upper edges counts. Both kinds are reported, since the second is
/// attained only in the limit.
#include <cstddef>
#include <vector>

#include "stratum/analysis/measures.hpp"  // PointView

namespace stratum::analysis {

/// Δ at the corners (i/R, j/R), i, j = 0 … R: values[j·(R+1) + i].
struct LocalDiscrepancyGrid {
  std::size_t resolution = 0;  ///< R
  std::vector<double> values;
  double max_abs = 0;  ///< the largest |Δ| on the grid (a lower bound on D*_N)
};

/// Δ on an (R+1)×(R+1) grid of corners by binning the points into R×R cells
/// and summing prefix counts: O(N + R²). Needs d == 2, N ≥ 1 and
/// 1 ≤ R ≤ 4096; throws stratum::invalid_argument naming `d`, `n` or
/// `resolution` otherwise.
LocalDiscrepancyGrid local_discrepancy_grid(const PointView& points, std::size_t resolution);

/// The box [0,x) × [0,y) of the supremum of |Δ|.
struct StarDiscrepancyBox {
  double value = 0;     ///< D*_N
  double x = 0, y = 0;  ///< the box's upper corner
  /// true: the supremum is n_closed/N − x·y (too many points; the box's upper
  /// edges included, approached from above); false: x·y − n_open/N (too few).
  bool closed = false;
  std::size_t count = 0;  ///< points counted in that box (closed or open as said)
};

/// The critical box of largest local discrepancy by a sweep over the x
/// corners with the y's to the left kept sorted: O(N²) time, O(N) memory.
/// On ties the first in (x, y) order wins. Needs d == 2 and N ≥ 1.
StarDiscrepancyBox star_discrepancy_box(const PointView& points);

}  // namespace stratum::analysis
