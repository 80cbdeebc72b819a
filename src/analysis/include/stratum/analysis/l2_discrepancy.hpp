#pragma once
/// L2 discrepancies of a point set in [0,1]^d, with exactly the definitions
/// of scipy.stats.qmc.discrepancy (Hickernell 1998, "A generalized
/// discrepancy and quadrature error bound"; Zhou, Fang, Ning 2013, "Mixture
/// discrepancy for quasi-random point sets"):
///
///   L2-star (Warnock 1972, "Computational investigations of low-discrepancy
///   point sets"): the L2 norm over anchored boxes [0,x) of the local
///   discrepancy,
///     D² = 3^-d − 2^(1−d)/n Σ_i Π_k (1 − x_ik²) + 1/n² Σ_{i,j} Π_k (1 − max(x_ik, x_jk));
///   centered (CD):
///     D² = (13/12)^d − 2/n Σ_i Π_k (1 + ½|x_ik − ½| − ½|x_ik − ½|²)
///          + 1/n² Σ_{i,j} Π_k (1 + ½|x_ik − ½| + ½|x_jk − ½| − ½|x_ik − x_jk|);
///   wrap-around (WD):
///     D² = −(4/3)^d + 1/n² Σ_{i,j} Π_k (3/2 − |x_ik − x_jk| + |x_ik − x_jk|²);
///   mixture (MD):
///     D² = (19/12)^d − 2/n Σ_i Π_k (5/3 − ¼|x_ik − ½| − ¼|x_ik − ½|²)
///          + 1/n² Σ_{i,j} Π_k (15/8 − ¼|x_ik − ½| − ¼|x_jk − ½| − ¾|x_ik − x_jk| + ½|x_ik − x_jk|²).
///
/// Every function here returns the SQUARED discrepancy D². (scipy returns
/// D² for CD, WD and MD but √D² for L2-star; the scipy-compatible Python
/// function stratum.qmc.discrepancy reproduces that; the measure registry
/// reports √D² for all four with D² in its extras. See docs/discrepancy.md.)
///
/// The pair sums are computed over i < j only (the summand is symmetric),
/// tiled so a block of points stays in cache, vectorized over j and split
/// over oneTBB threads in fixed row blocks whose partial sums are added in
/// order: the result does not depend on the thread count.
#include <cstddef>

#include "stratum/analysis/measures.hpp"  // PointView

namespace stratum::analysis {

enum class L2Kind { star, centered, wrap_around, mixture };

enum class L2Algorithm {
  automatic,  ///< fast where available (L2-star, d ≤ 3), else pairwise
  pairwise,   ///< the O(d N²) formula above (Warnock's for L2-star)
  fast,       ///< L2-star only, d ≤ 3: sorting + Fenwick trees, O(N log^(d−1) N) (Heinrich 1996)
};

struct L2Options {
  unsigned threads = 1;
  L2Algorithm algorithm = L2Algorithm::automatic;
  /// scipy's `iterative=True`: normalize by n + 1 instead of n, so that
  /// l2_centered_update can add one more point (scipy's update_discrepancy).
  bool iterative = false;
};

/// D² of `points` (n ≥ 1, d ≥ 1; coordinates are assumed finite and in
/// [0,1]: callers check). Throws invalid_argument when `algorithm` is fast
/// and the kind is not L2-star or d > 3.
double l2_discrepancy_squared(L2Kind kind, const PointView& points, const L2Options& options = {});

/// Bytes l2_discrepancy_squared allocates besides the points (the pairwise
/// formula's two column copies; the fast one's sort keys, sorted columns and
/// merge buffers or Fenwick trees); it refuses (stratum::memory_error)
/// when they are not available (stratum/memory.hpp).
double l2_working_bytes(L2Kind kind, std::size_t n, std::size_t d, const L2Options& options = {});

/// The L2-star pair sum Σ_{i,j} Π_k (1 − max(x_ik, x_jk)) in O(N log^(d−1) N)
/// for d ≤ 3 (d = 1: sort; d = 2: sort by x, Fenwick tree over y ranks;
/// d = 3: divide and conquer over x, sweep over y, Fenwick tree over z;
/// Heinrich 1996, "Efficient algorithms for computing the L2-discrepancy").
/// Accumulates in long double. Throws invalid_argument for d > 3.
long double l2_star_pair_sum_fast(const PointView& points);

/// The centered discrepancy D² after appending `x_new` (d coordinates) to
/// `sample`, given `initial` = D² of `sample` computed with iterative = true,
/// in O(n d): scipy.stats.qmc.update_discrepancy's recurrence.
double l2_centered_update(const double* x_new, const PointView& sample, double initial);

}  // namespace stratum::analysis
