#pragma once
/// The star discrepancy D*_N of n points in [0,1]^d:
///
///   D*_N = sup_{x ∈ [0,1]^d} | #{i : p_i ∈ [0,x)} / N − x_1 ⋯ x_d |,
///
/// over half-open boxes anchored at the origin (Niederreiter 1992, "Random
/// Number Generation and Quasi-Monte Carlo Methods", Def. 2.1; LECTURE.md §10).
/// Because the boxes are half-open and x ≤ 1, a point with a coordinate equal
/// to 1 lies in no box: it counts in N only. For points in [0,1)^d this equals
/// the closed-box definition.
///
/// The supremum is attained, or approached, at the critical boxes whose upper
/// corners take each coordinate from the points' coordinates or 1: the largest
/// of V(y) − A([0,y))/N and of A([0,y])/N − V(y) over those corners
/// (Niederreiter 1972; Gnewuch, Srivastav, Winzen 2009, "Finding optimal
/// volume subintervals with k points and calculating the star discrepancy are
/// NP-hard problems", Lemma 1.1). Every exact method below enumerates them.
///
/// Methods:
///  - d = 1: the closed form D* = 1/(2N) + max_i |x_(i) − (2i−1)/(2N)|
///    (Niederreiter 1992, Theorem 2.6); O(N log N).
///  - d = 2: a sweep in x over the sorted points with the sorted list of y's
///    to the left; at each corner x every candidate y is scanned once, with
///    the count given by its rank: O(N²) time with a vectorized scan, O(N)
///    memory, parallel over x-slabs (oneTBB; the result is a maximum, so it is
///    the same for every thread count). N = 2^16 takes about a second.
///  - d ≥ 3: the cell decomposition of Dobkin, Eppstein, Mitchell 1996
///    ("Computing the discrepancy with applications to supersampling
///    patterns", ACM TOG 15(4)): the space of upper corners is cut into
///    O(N^{d/2}) cells, one coordinate at a time, so that in each cell every
///    point is inside all boxes, outside all, or between the cell's faces in
///    exactly one coordinate (O(d√N) such points); there the count is a sum
///    over coordinates and a knapsack over them gives the best box of every
///    count in O(N): O(N^{1+d/2}) time in all (star_discrepancy_dem.cpp).
///    Limited to N ≤ star_dem_max_points(d) (about 10 s on one core).
///  - the direct enumeration of the critical boxes, O(N^d) (the 2D scan nested
///    in a sweep over each further coordinate), is kept as the slow oracle of
///    the tests (star_discrepancy_grid); DEM returns the same double.
///  - bounds for anything larger: Thiémard 2001 ("An algorithm to compute
///    bounds for the star discrepancy", J. Complexity 17) — a δ-partition of
///    the cube into boxes [α,β] with V(β) − V(α) ≤ δ; on each box the local
///    discrepancy is bounded above by max(V(β) − A([0,α))/N, A([0,β))/N − V(α))
///    and attained at its corners, so lower ≤ D* ≤ upper ≤ lower + δ.
#include <cstddef>
#include <cstdint>

#include "stratum/analysis/measures.hpp"

namespace stratum::analysis {

/// The largest N the exact method for d ≥ 3 (DEM) accepts in d dimensions:
/// for d = 3 … 8, 14000, 2200, 650, 260, 140, 80 — about 7 s of CPU time
/// on one core on the slowest inputs we timed (Halton points, whose small D*
/// lets fewer cells be pruned than uniform random points; measured on a
/// loaded 2-core machine; bench/star_bench.cpp times d = 3, 4). Above d = 8 the
/// largest N with N^{1+d/2} ≤ 80^5, the d = 8 budget (d = 9: 53, timed at
/// N = 50: 2.8 s; d = 10: 38). Needs d ≥ 3.
std::size_t star_dem_max_points(std::size_t d);
/// The largest N the exact 2D sweep accepts (O(N²): about a minute at this N on one core).
inline constexpr std::size_t kStarExact2dMaxPoints = std::size_t{1} << 18;

/// Can star_discrepancy_exact handle n points in d dimensions within its limits?
bool star_exact_feasible(std::size_t n, std::size_t d);

/// The d = 1 closed form (Niederreiter 1992, Thm 2.6). Needs d == 1.
double star_discrepancy_1d(const PointView& points);

/// The exact 2D sweep, O(N²) (see above). Needs d == 2.
double star_discrepancy_2d(const PointView& points, unsigned threads = 1);

/// The exact enumeration of critical boxes for any d ≥ 2, O(N^d): the nested
/// sweep (d ≥ 3) ending in the 2D scan. No size limit is applied here.
double star_discrepancy_grid(const PointView& points, unsigned threads = 1);

/// The exact value by the cell decomposition of Dobkin, Eppstein, Mitchell
/// 1996 (O(N^{1+d/2}) time, O(dN) memory per thread; see above), for any d ≥ 2.
/// No size limit is applied here. `block_scale` sets the counted points per cut
/// (block_scale·√N): it changes the running time, never the value. Returns
/// the same double as star_discrepancy_grid (both round every box alike).
double star_discrepancy_dem(const PointView& points, unsigned threads = 1, double block_scale = 1.0);

/// The exact value by the fastest method for this d (1D closed form, 2D sweep,
/// or DEM for d ≥ 3). Throws invalid_argument naming d (or n) when the input
/// is beyond star_exact_feasible, saying that star_discrepancy_bounds can.
double star_discrepancy_exact(const PointView& points, unsigned threads = 1);

struct StarDiscrepancyBounds {
  double lower = 0;         ///< a value of the local discrepancy at a box corner: D* ≥ lower
  double upper = 0;         ///< D* ≤ upper; upper − lower ≤ delta
  std::uint64_t boxes = 0;  ///< boxes in the δ-partition
};

/// Thiémard's (2001) bounds from a δ-partition, delta in (0, 1). Throws
/// invalid_argument naming delta when the partition would need more than
/// max_boxes boxes. Deterministic for any thread count.
StarDiscrepancyBounds star_discrepancy_bounds(const PointView& points, double delta,
                                              std::uint64_t max_boxes = std::uint64_t{1} << 26, unsigned threads = 1);

}  // namespace stratum::analysis
