#pragma once
/// Stratification checks of point sets (LECTURE.md §4, §11): the t-value of
/// a (t, m, s)-net in any base and the Latin (N-rooks) property.
///
/// A set of N = b^m points in [0,1)^s is a (t, m, s)-net in base b when every
/// elementary interval Π_j [a_j b^{−d_j}, (a_j + 1) b^{−d_j}) with
/// Σ_j d_j = m − t (volume b^{t−m}) holds exactly b^t points (Niederreiter
/// 1992, "Random number generation and quasi-Monte Carlo methods", Def. 4.1).
/// Every net is also a (t+1, m, s)-net, so the t-value is the smallest such t
/// (at most m: with t = m the only interval is the whole cube).
#include <cstddef>
#include <cstdint>

#include "stratum/analysis/measures.hpp"  // PointView

namespace stratum::analysis {

struct NetQuality {
  unsigned t = 0;  ///< smallest t for which the set is a (t, m, s)-net
  unsigned m = 0;  ///< N = base^m
};

/// The t-value of `points` as a net in `base` (2 ≤ base ≤ 2^16): for t = 0,
/// 1, ... checks every split of m − t digits over the s coordinates, counting
/// the points per elementary interval in one O(N) pass per split. Throws
/// stratum::invalid_argument when base < 2, N is not a power of base, or a
/// coordinate is outside [0, 1] (a coordinate equal to 1 counts in the last
/// interval). For bases that are not powers of 2 the interval of a point is
/// found with a relative nudge of 1e-12 upwards, so that radical-inverse
/// values a/b^k, which binary doubles cannot hold exactly, fall in the
/// interval they belong to.
NetQuality net_t_value(const PointView& points, std::uint64_t base);

/// The same by brute force: for each t and each split, every elementary
/// interval is enumerated and its points counted by comparing coordinates
/// against its bounds, O(#intervals · N) per split. For tests (small m).
NetQuality net_t_value_reference(const PointView& points, std::uint64_t base);

/// The Latin (N-rooks) property: along every axis each of the N strata
/// [i/N, (i+1)/N) holds exactly one point (Shirley 1991, "Discrepancy as a
/// quality measure for sample distributions"; McKay, Beckman, Conover 1979).
struct LatinCheck {
  bool latin = false;
  std::size_t worst_count = 0;   ///< largest number of points in one stratum (1 if Latin)
  std::size_t worst_axis = 0;    ///< the axis where it occurs
  std::size_t empty_strata = 0;  ///< strata with no point, over all axes
};
LatinCheck latin_check(const PointView& points);

}  // namespace stratum::analysis
