#pragma once
/// Weighted sample elimination (Yuksel 2015, "Sample elimination for
/// generating Poisson disk sample sets"): thin a set of M points to exactly
/// n ≤ M by repeatedly removing the point with the largest crowding weight
/// w_i = Σ_j (1 − d̂_ij / D)^8 over neighbours closer than D, where D is the
/// largest minimum distance n points could have (the densest known packing)
/// and d̂_ij = max(d_ij, D_min) limits the weight of very close pairs
/// (D_min = 0.65 D (1 − (n/M)^1.5), Yuksel's weight limiting). The kept
/// points are a subset, so any minimum distance of the input survives, and
/// they are spread evenly: the most crowded points go first.
///
/// stratum uses it to turn a maximal Poisson-disk set into exactly n points.
/// Allocates (neighbour lists and a heap); not for a per-sample path.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <queue>
#include <utility>
#include <vector>

#include "stratum/patterns/neighbor_grid.hpp"
#include "stratum/util/error.hpp"

namespace stratum {

/// Densest known sphere-packing density in dimension d = 1..8 (Conway, Sloane
/// 1999, "Sphere packings, lattices and groups", table 1.2; lattice packings
/// A1, A2, A3, D4, D5, E6, E7, E8).
inline double densest_packing_density(unsigned d) noexcept {
  constexpr double density[9] = {1.0,
                                 1.0,
                                 0.90689968211710892,
                                 0.74048048969306104,
                                 0.61685027506808491,
                                 0.46525761330925834,
                                 0.37294751488092800,
                                 0.29529789472373224,
                                 0.25366950790104802};
  return d <= 8 ? density[d] : 0.25;
}

/// Volume of the unit ball in dimension d: π^(d/2) / Γ(d/2 + 1).
inline double unit_ball_volume(unsigned d) noexcept {
  return std::pow(std::numbers::pi, d / 2.0) / std::tgamma(d / 2.0 + 1.0);
}

/// The largest minimum distance n points in the unit cube can have, from the
/// densest packing: n balls of radius D/2 fill at most that density.
inline double largest_minimum_distance(std::uint64_t n, unsigned d) noexcept {
  return 2.0 * std::pow(densest_packing_density(d) / (unit_ball_volume(d) * static_cast<double>(n)), 1.0 / d);
}

/// Indices (ascending) of the `keep` points kept out of `count` points
/// (row-major coordinates, `d` per point) by weighted sample elimination.
/// Deterministic: ties go to the larger index.
inline std::vector<std::uint32_t> eliminate_samples(const double* coords, std::size_t count, unsigned d,
                                                    std::size_t keep, bool periodic) {
  require(keep >= 1 && keep <= count, "n", keep, "sample elimination keeps between 1 and the number of input points");
  require(count < NeighborGrid::empty, "count", count, "sample elimination takes fewer than 2^32 points");
  std::vector<std::uint32_t> kept;
  kept.reserve(keep);
  if (keep == count) {
    for (std::size_t i = 0; i < count; ++i) kept.push_back(static_cast<std::uint32_t>(i));
    return kept;
  }
  const double reach = std::min(largest_minimum_distance(keep, d), std::sqrt(static_cast<double>(d)));
  const double closest = reach * 0.65 * (1.0 - std::pow(static_cast<double>(keep) / static_cast<double>(count), 1.5));
  const auto cells_per_axis = static_cast<std::uint64_t>(std::max(1.0, std::floor(1.0 / reach)));
  NeighborGrid grid(d, cells_per_axis, periodic);  // about one cell per kept point
  for (std::size_t i = 0; i < count; ++i) grid.insert(static_cast<std::uint32_t>(i), coords + i * d);

  // Neighbour lists (compressed rows) with the pair weights.
  std::vector<std::size_t> offset(count + 1, 0);
  std::vector<std::uint32_t> neighbor;
  std::vector<double> pair_weight;
  std::vector<double> weight(count, 0.0);
  const double reach2 = reach * reach;
  for (std::size_t i = 0; i < count; ++i) {
    const double* x = coords + i * d;
    grid.visit_near(x, reach, [&](std::uint32_t j) {
      if (j == i) return true;
      const double dist2 = grid.distance_squared(x, coords + static_cast<std::size_t>(j) * d);
      if (dist2 >= reach2) return true;
      const double limited = std::max(std::sqrt(dist2), closest);
      const double w = std::pow(1.0 - limited / reach, 8);
      neighbor.push_back(j);
      pair_weight.push_back(w);
      weight[i] += w;
      return true;
    });
    offset[i + 1] = neighbor.size();
  }

  std::vector<bool> removed(count, false);
  std::priority_queue<std::pair<double, std::uint32_t>> heap;
  for (std::size_t i = 0; i < count; ++i) heap.emplace(weight[i], static_cast<std::uint32_t>(i));
  std::size_t remaining = count;
  while (remaining > keep) {
    const auto [w, i] = heap.top();
    heap.pop();
    if (removed[i] || w != weight[i]) continue;  // stale entry
    removed[i] = true;
    --remaining;
    for (std::size_t e = offset[i]; e < offset[i + 1]; ++e) {
      const std::uint32_t j = neighbor[e];
      if (removed[j]) continue;
      weight[j] -= pair_weight[e];
      heap.emplace(weight[j], j);
    }
  }
  for (std::size_t i = 0; i < count; ++i)
    if (!removed[i]) kept.push_back(static_cast<std::uint32_t>(i));
  return kept;
}

}  // namespace stratum
