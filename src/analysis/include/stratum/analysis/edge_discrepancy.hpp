#pragma once
/// Edge (half-plane) discrepancy of 2D point sets in the unit square.
///
/// For a line ℓ cutting [0,1]² let H be one of its open half-planes, A(H) the
/// area of H ∩ [0,1]², and C_open, C_closed the numbers of points in H and in
/// H ∪ ℓ. The local discrepancy of ℓ counts the points on ℓ both ways:
///   D(ℓ) = max(C_closed/N − A(H), A(H) − C_open/N),
/// which is the same for either half-plane and is the limit of
/// |fraction − area| over lines converging to ℓ from either side.
///
/// * Exact edge discrepancy sup_ℓ D(ℓ) (Dobkin, Eppstein, Mitchell 1996,
///   "Computing the discrepancy with applications to supersampling
///   patterns"): for a fixed direction the supremum over offsets is attained
///   at a line through a point; rotating a line about a point, the counts are
///   constant between the directions of other points and the area is C¹ with
///   derivative (r₁² − r₂²)/2 (r₁, r₂ the distances from the point to the two
///   ends of its chord), so the supremum is attained at a line through two
///   points or at a line through one point that bisects its chord. Both
///   families are enumerated; the lines through pairs by a rotational sweep
///   about every point (O(N² log N)). Orientation tests are exact (Shewchuk
///   1997, "Adaptive precision floating-point arithmetic and fast robust
///   geometric predicates": a floating-point filter, then an exact
///   expansion), so collinear points are found and counted both ways; areas
///   are computed in double precision.
/// * Mitchell's random-edge discrepancy (Mitchell 1992, "Ray tracing and
///   irregularities of distribution"): D(ℓ) over L random lines from the
///   motion-invariant measure of lines hitting the square (Santaló 1976,
///   "Integral geometry and geometric probability": density dp dθ, uniform
///   on the (θ, p) with θ ∈ [0, π) and p in the square's projection onto the
///   normal (cos θ, sin θ); by Crofton the lines hitting a convex set have
///   measure equal to its perimeter). θ is therefore not uniform: its
///   density is proportional to the square's width in that direction.
///   Reported as the RMS, the mean and the maximum. Counter-based random numbers: deterministic for any thread
///   count.
#include <cstddef>
#include <cstdint>

#include "stratum/analysis/measures.hpp"  // PointView

namespace stratum::analysis {

/// A line {x : normal·x = offset} with unit normal (cos angle, sin angle).
struct EdgeLine {
  double angle = 0;   ///< in [0, 2π)
  double offset = 0;  ///< signed distance from the origin
};

struct EdgeDiscrepancy {
  double value = 0;  ///< sup_ℓ D(ℓ) (for the search: the largest value found)
  EdgeLine line;     ///< a line attaining it
};

/// Area of {x ∈ [0,1]² : normal_x·x + normal_y·y < offset} (any normal ≠ 0).
double half_plane_area(double normal_x, double normal_y, double offset);

/// Sign (−1, 0, +1) of the orientation det[q − p, r − p], computed exactly.
int orientation(double px, double py, double qx, double qy, double rx, double ry);

/// Exact edge discrepancy by rotational sweeps about every point:
/// O(N² log N) time, O(N) memory per thread. Points must be 2D, in [0,1]²;
/// throws stratum::invalid_argument otherwise. Deterministic for any
/// `threads` (0: all cores).
EdgeDiscrepancy edge_discrepancy(const PointView& points, unsigned threads = 1);

/// The same supremum by direct enumeration: every line through two points,
/// counted in O(N) each (O(N³)), plus the chord-bisecting lines. The
/// reference the sweep is tested and benchmarked against.
EdgeDiscrepancy edge_discrepancy_naive(const PointView& points, unsigned threads = 1);

/// A lower bound by search: `angles` equally spaced directions, for each the
/// exact best offset (sorting the projections), then three rounds of local
/// refinement (×1000 finer) about every direction within 2·10⁻³ of the best.
/// Independent of the candidate-line argument; used as an oracle in tests.
EdgeDiscrepancy edge_discrepancy_search(const PointView& points, std::size_t angles, unsigned threads = 1);

/// The i-th random line of Mitchell's random-edge estimate for `seed`.
EdgeLine random_isotropic_line(std::uint64_t seed, std::uint64_t index);

/// D(ℓ) of one line for the given points.
double line_discrepancy(const PointView& points, const EdgeLine& line);

struct RandomEdgeDiscrepancy {
  double rms = 0;   ///< sqrt(mean D²): Mitchell's random-edge discrepancy
  double mean = 0;  ///< mean D
  double max = 0;   ///< largest D seen (≤ the exact edge discrepancy)
  std::size_t lines = 0;
};

/// Mitchell's random-edge discrepancy over `lines` ≥ 1 random lines
/// (lines 0 … L−1 of random_isotropic_line(seed, ·)); O(L·N).
RandomEdgeDiscrepancy random_edge_discrepancy(const PointView& points, std::size_t lines, std::uint64_t seed,
                                              unsigned threads = 1);

}  // namespace stratum::analysis
