#pragma once
/// The completion phase of stratum's maximal Poisson-disk sampler (the
/// engine is poisson_disk_grid.hpp): after Bridson's phase, every empty
/// cell of the grid is proved covered by the samples' disks, or gets a
/// sample (Ebeida et al. 2012, "A simple algorithm for maximal
/// Poisson-disk sampling in high dimensions"), so that the set is maximal.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "stratum/patterns/poisson_disk_coverage.hpp"
#include "stratum/patterns/poisson_disk_grid.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum::poisson_detail {

// Does the disk of the sample q contain the whole cell at lo? covered()'s
// single-disk test, operation for operation.
template <unsigned D>
inline bool CompactPoissonDisk<D>::disk_covers_cell(const double* lo, const double* q) const noexcept {
  const double half = sides_[0] / 2;
  double far2 = 0;
  for (unsigned j = 0; j < D; ++j) {
    const double gap = std::abs((lo[j] + half) - q[j]) + half;
    far2 += gap * gap;
  }
  return far2 <= r2_;
}

// Lists in local_ the samples of the stencil of the empty cell at lo
// (index base) and returns true, unless one sample of the nearest 3^D
// cells contains the whole cell: most empty cells are covered so (no
// farther sample can cover a cell alone), and are settled without the
// list (false). In the plane only the occupied cells are visited
// (occupancy_); the list is then in row-major order, not nearest first,
// which no test depends on (they combine the samples with "or", or rank
// them by distance).
template <unsigned D>
inline bool CompactPoissonDisk<D>::list_stencil_unless_covered(const double* lo, std::int64_t base) {
  const std::size_t capacity = stencil_.size();
  if constexpr (D == 2) {
    const std::uint64_t mask = stencil_pattern_.occupied(occupancy_, base);
    for (std::uint64_t near = mask & neighbour_bits_; near != 0; near &= near - 1)
      if (disk_covers_cell(lo, cell(base + stencil_pattern_.offset(static_cast<unsigned>(std::countr_zero(near))))))
        return false;
    local_size_ = 0;
    for (std::uint64_t bits = mask; bits != 0; bits &= bits - 1) {
      const double* q = cell(base + stencil_pattern_.offset(static_cast<unsigned>(std::countr_zero(bits))));
      local_[local_size_] = q[0];
      local_[capacity + local_size_] = q[1];
      ++local_size_;
    }
    return true;
  } else {
    constexpr std::size_t block = D == 1 ? 3 : D == 3 ? 27 : 81;
    const std::size_t first = std::min(block, stencil_.size());
    bool any = false;
    for (std::size_t k = 0; k < first; ++k) any |= disk_covers_cell(lo, cell(base + stencil_[k]));
    if (any) return false;
    local_size_ = 0;  // branch-free compaction of the stencil's samples
    for (const std::int64_t offset : stencil_) {
      const double* q = cell(base + offset);
      for (unsigned j = 0; j < D; ++j) local_[j * capacity + local_size_] = q[j];
      local_size_ += q[0] != sentinel;
    }
    return true;
  }
}

// Is the box [lo, lo + side] inside the union of the disks of the listed
// samples? Exact tests, so the answer "yes" is always right: one disk
// covers the box when its farthest corner is within r; two disks p, q
// cover it when every corner is within r of p or q and every point where
// their bisector crosses an edge of the box is within r of both (the
// farthest point of the box from {p, q} is a corner or such a crossing,
// since distance to p is convex on the box's half on p's side). "No" may
// be wrong (three or more disks needed); the box is then split.
template <unsigned D>
inline bool CompactPoissonDisk<D>::covered(const double* lo, double side) const noexcept {
  const double half = side / 2;
  const std::size_t n = local_size_, capacity = stencil_.size();
  double* far2 = far2_.data();
  // Farthest-corner distances, coordinate by coordinate (vectorizes).
  for (unsigned j = 0; j < D; ++j) {
    const double centre = lo[j] + half;
    const double* column = local_.data() + j * capacity;
    for (std::size_t k = 0; k < n; ++k) {
      const double gap = std::abs(centre - column[k]) + half;
      far2[k] = (j == 0 ? 0.0 : far2[k]) + gap * gap;
    }
  }
  if (n == 0) return false;
  // The sites are the samples whose disks come closest to containing the
  // box, nearest first (ties: in list order). One disk covers the box if
  // the nearest does; the third site is only needed when the nearest two
  // fail. take_nearest takes the first smallest far2 without branches and
  // rules it out.
  const auto take_nearest = [&](double* site) {
    std::size_t best = 0;
    double best_far2 = far2[0];
    for (std::size_t k = 1; k < n; ++k) {
      const bool nearer = far2[k] < best_far2;
      best = nearer ? k : best;
      best_far2 = nearer ? far2[k] : best_far2;
    }
    far2[best] = std::numeric_limits<double>::infinity();
    for (unsigned j = 0; j < D; ++j) site[j] = local_[j * capacity + best];
    return best_far2;
  };
  // The nearest two: their far2 by a min/max network, then their places
  // by scans from the end (the first place of each value, or the first
  // two places of a tied value): what two passes of take_nearest find.
  double nearest = std::numeric_limits<double>::infinity(), second = nearest;
  for (std::size_t k = 0; k < n; ++k) {
    second = std::min(second, std::max(nearest, far2[k]));
    nearest = std::min(nearest, far2[k]);
  }
  if (nearest <= r2_) return true;
  if (n < 2) return false;
  std::size_t first_place = 0, next_place = 0, second_place = 0;
  for (std::size_t k = n; k-- > 0;) {
    const bool is_nearest = far2[k] == nearest;
    next_place = is_nearest ? first_place : next_place;
    first_place = is_nearest ? k : first_place;
    second_place = far2[k] == second ? k : second_place;
  }
  if (second == nearest) second_place = next_place;
  double site[3][D];
  for (unsigned j = 0; j < D; ++j) {
    site[0][j] = local_[j * capacity + first_place];
    site[1][j] = local_[j * capacity + second_place];
  }
  if (pair_covers<D>(lo, side, site[0], site[1], r2_)) return true;
  if constexpr (D == 2) {
    if (n < 3) return false;
    far2[first_place] = far2[second_place] = std::numeric_limits<double>::infinity();
    take_nearest(site[2]);
    return triple_covers(lo, side, site, r2_);
  }
  return false;
}

// Is x, a point of the closed current cell, at distance ≥ r from every
// listed sample? (The list holds every sample within r of the cell.)
template <unsigned D>
inline bool CompactPoissonDisk<D>::locally_free(const double* x) const noexcept {
  const std::size_t capacity = stencil_.size();
  bool conflict = false;
  for (std::size_t k = 0; k < local_size_; ++k) {
    double sum = 0;
    for (unsigned j = 0; j < D; ++j) {
      const double delta = x[j] - local_[j * capacity + k];
      sum += delta * delta;
    }
    conflict |= sum < r2_;
  }
  return !conflict;
}

// Places a sample at x (free, inside the cube); returns whether it lies in
// the current cell `c` (which it then covers). Otherwise it lies in a
// neighbour cell and joins the local list.
template <unsigned D>
inline bool CompactPoissonDisk<D>::place(const double* x, const std::int64_t* c) {
  std::int64_t cx[D];
  bool here = true;
  double stored[D];
  for (unsigned j = 0; j < D; ++j) {
    stored[j] = x[j];
    if (periodic_) stored[j] -= std::floor(stored[j]);
    if (stored[j] >= 1.0) stored[j] = 0.0;
    cx[j] = axis_cell(stored[j]);
    here = here && cx[j] == c[j];
  }
  add(stored, cx);
  if (!here) {
    const std::size_t capacity = stencil_.size();
    for (unsigned j = 0; j < D; ++j) local_[j * capacity + local_size_] = x[j];  // unwrapped
    ++local_size_;
  }
  return here;
}

// Phase 2: every empty cell is refined until each box is inside one disk
// (or two), or a sample lands in the cell (which then covers all of it).
// An uncovered box gets a sample when its centre is free (a dart uniform
// in the box, or the centre itself when the dart misses), else when one of
// its corners is free: the gap then lies mostly outside the box, maybe in
// a neighbour cell, and a dart near the corner (or the corner itself)
// fills it. Without the corner rule, a gap that enters the cell only as a
// thin wedge along a face would be refined to the last level along a
// whole (d−2)-dimensional edge. Otherwise the box is split in 2^D.
template <unsigned D>
inline void CompactPoissonDisk<D>::complete() {
  struct Box {
    double lo[D];
    unsigned level;
  };
  // Depth-first: at most (2^D - 1) boxes wait per level, plus the current.
  std::vector<Box> stack((max_refinement_ + 1) * (1u << D) + 2);
  std::size_t top = 0;
  std::int64_t c[D] = {};
  double x[D], y[D];
  std::uint64_t dart = 0;
  for (;;) {
    const std::int64_t base = cell_index(c);
    Box box{};
    for (unsigned j = 0; j < D; ++j) box.lo[j] = static_cast<double>(c[j]) * a_;
    if (!occupied(base) && list_stencil_unless_covered(box.lo, base)) {
      stack[0] = box;
      top = 1;
      while (top > 0) {
        const Box current = stack[--top];
        const double side = sides_[current.level];
        if (covered(current.lo, side)) continue;
        for (unsigned j = 0; j < D; ++j) x[j] = current.lo[j] + side / 2;
        if (locally_free(x)) {
          for (unsigned j = 0; j < D; ++j)
            y[j] = std::min(current.lo[j] + side * uniform01(seed_, tag_dart, dart, j), one_minus_epsilon_double);
          ++dart;
          place(locally_free(y) ? y : x, c);  // in this cell: it is now covered
          top = 0;
          break;
        }
        bool placed_nearby = false;
        for (unsigned corner = 0; corner < (1u << D) && !placed_nearby; ++corner) {
          for (unsigned j = 0; j < D; ++j)
            x[j] = std::min(current.lo[j] + ((corner >> j) & 1u ? side : 0.0), one_minus_epsilon_double);
          if (!locally_free(x)) continue;
          // A dart in the cube of half-width `side` around the corner.
          bool inside = true;
          double wrapped[D];
          std::int64_t cy[D] = {};
          for (unsigned j = 0; j < D; ++j) {
            y[j] = x[j] + side * (2 * uniform01(seed_, tag_dart, dart, j) - 1);
            wrapped[j] = periodic_ ? y[j] - std::floor(y[j]) : y[j];
            if (!(wrapped[j] >= 0.0 && wrapped[j] < 1.0)) inside = false;
            else cy[j] = axis_cell(wrapped[j]);
          }
          ++dart;
          const bool here = place(inside && is_free(wrapped, cell_index(cy)) ? y : x, c);
          if (here) top = 0;
          else stack[top++] = current;  // test the box again with the new sample
          placed_nearby = true;
        }
        if (placed_nearby || current.level >= max_refinement_) continue;
        for (unsigned child = 0; child < (1u << D); ++child) {
          Box next{};
          next.level = current.level + 1;
          for (unsigned j = 0; j < D; ++j) next.lo[j] = current.lo[j] + ((child >> j) & 1u ? side / 2 : 0.0);
          stack[top++] = next;
        }
      }
    }
    unsigned j = 0;
    while (j < D && ++c[j] == g_) c[j++] = 0;
    if (j == D) break;
  }
}

}  // namespace stratum::poisson_detail
