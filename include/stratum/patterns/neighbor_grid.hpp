#pragma once
/// A uniform background grid over the unit cube [0,1)^d that buckets point
/// indices by cell, for fixed-radius neighbour queries: the nearest-neighbour
/// searches of best-candidate sampling (Mitchell 1991, "Spectrally optimal
/// sampling for distribution ray tracing") and the neighbour lists of sample
/// elimination (Yuksel 2015). Each cell holds a linked list of the points
/// that fall in it, so a cell may hold any number of points and the cell
/// side can be chosen for the query radius. (The Poisson-disk engine uses
/// its own one-sample-per-cell grid, poisson_disk_grid.hpp.)
///
/// Distances are Euclidean, or toroidal (the unit cube with opposite faces
/// identified) when `periodic`. The grid owns only indices: a query's
/// visitor gets each candidate index and looks its coordinates up itself,
/// so the caller may keep them in a growing std::vector.
#include <algorithm>
#include <limits>
#include <cmath>
#include <cstdint>
#include <vector>

#include "stratum/util/error.hpp"

namespace stratum {

class NeighborGrid {
 public:
  static constexpr unsigned max_dimensions = 8;
  static constexpr std::uint32_t empty = ~std::uint32_t{0};

  NeighborGrid() = default;

  /// `cells_per_axis` cells along each of `dimensions` axes (so
  /// cells_per_axis^dimensions cells in all, each allocated).
  NeighborGrid(unsigned dimensions, std::uint64_t cells_per_axis, bool periodic)
      : dimensions_(dimensions), cells_per_axis_(cells_per_axis), periodic_(periodic) {
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions,
            "NeighborGrid supports 1 to 8 dimensions");
    require(cells_per_axis >= 1, "cells_per_axis", cells_per_axis, "must be at least 1");
    std::uint64_t cells = 1;
    for (unsigned j = 0; j < dimensions; ++j) {
      require(cells <= (std::uint64_t{1} << 40) / cells_per_axis, "cells_per_axis", cells_per_axis,
              "the grid would have more than 2^40 cells");
      cells *= cells_per_axis;
    }
    head_.assign(cells, empty);
  }

  /// Cells needed for `cells_per_axis` per axis in `dimensions` (saturates at 2^63).
  static std::uint64_t cell_count(unsigned dimensions, std::uint64_t cells_per_axis) noexcept {
    std::uint64_t cells = 1;
    for (unsigned j = 0; j < dimensions; ++j) {
      if (cells > (std::uint64_t{1} << 63) / cells_per_axis) return std::uint64_t{1} << 63;
      cells *= cells_per_axis;
    }
    return cells;
  }

  unsigned dimensions() const noexcept { return dimensions_; }
  std::uint64_t cells_per_axis() const noexcept { return cells_per_axis_; }
  bool periodic() const noexcept { return periodic_; }
  double cell_side() const noexcept { return 1.0 / static_cast<double>(cells_per_axis_); }

  /// Cell index along one axis of a coordinate in [0, 1].
  std::uint64_t axis_cell(double x) const noexcept {
    const double scaled = x * static_cast<double>(cells_per_axis_);
    if (!(scaled > 0)) return 0;
    return std::min(static_cast<std::uint64_t>(scaled), cells_per_axis_ - 1);
  }

  /// Linear index of the cell that holds point x.
  std::uint64_t cell_of(const double* x) const noexcept {
    std::uint64_t cell = 0;
    for (unsigned j = dimensions_; j-- > 0;) cell = cell * cells_per_axis_ + axis_cell(x[j]);
    return cell;
  }

  /// Adds point `index` (coordinates x) to its cell. Indices need not be dense.
  void insert(std::uint32_t index, const double* x) {
    if (next_.size() <= index) next_.resize(static_cast<std::size_t>(index) + 1, empty);
    const std::uint64_t cell = cell_of(x);
    next_[index] = head_[cell];
    head_[cell] = index;
  }

  /// Removes every point, keeping the cells.
  void clear() {
    std::fill(head_.begin(), head_.end(), empty);
    next_.clear();
  }

  /// Signed difference b - a along one axis, wrapped to [-1/2, 1/2] when periodic.
  double axis_delta(double a, double b) const noexcept {
    double delta = b - a;
    if (periodic_) {
      if (delta > 0.5) delta -= 1.0;
      else if (delta < -0.5) delta += 1.0;
    }
    return delta;
  }

  /// Squared distance between two points (toroidal when periodic).
  double distance_squared(const double* a, const double* b) const noexcept {
    return distance_squared(a, b, dimensions_, periodic_);
  }
  /// The same for points of [0, 1)^d without a grid. The wrap of axis_delta,
  /// delta ∓ 1 past ±1/2, is exactly ±(1 − |delta|) there (Sterbenz), so its
  /// square is that of the smaller of |delta| and 1 − |delta|: no branch on
  /// the wrap's direction, which is random and mispredicts.
  static double distance_squared(const double* a, const double* b, unsigned d, bool periodic) noexcept {
    double sum = 0;
    for (unsigned j = 0; j < d; ++j) {
      const double delta = b[j] - a[j];
      const double along = periodic ? std::min(std::abs(delta), 1.0 - std::abs(delta)) : delta;
      sum += along * along;
    }
    return sum;
  }
  /// The smallest distance_squared from x to `count` points (row-major, d
  /// coordinates each), measured against every one: small sets' brute force.
  static double nearest_squared(const double* x, const double* points, std::uint64_t count, unsigned d,
                                bool periodic) noexcept {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::uint64_t p = 0; p < count; ++p)
      nearest = std::min(nearest, distance_squared(x, points + p * d, d, periodic));
    return nearest;
  }

  /// Calls visit(index) for every stored point in a cell whose distance to
  /// the box [lo, hi] is below `radius` (a superset of the points within
  /// `radius` of the box; visit tests the exact distance). A point query
  /// passes lo = hi = x. visit returns false to stop early; the function
  /// returns false when it was stopped.
  template <class Visit>
  bool visit_near_box(const double* lo, const double* hi, double radius, Visit&& visit) const {
    AxisCells axes[max_dimensions];
    const double g = static_cast<double>(cells_per_axis_);
    const auto count = static_cast<std::int64_t>(cells_per_axis_);
    // Cells beyond ⌈radius·g⌉ are at least `radius` away; the tiny shrink
    // keeps a radius of exactly k cells from reaching a (k+1)-th cell.
    const auto reach = static_cast<std::int64_t>(std::ceil(radius * g * (1 - 1e-12)));
    const double radius2 = radius * radius;
    bool small = true;
    for (unsigned j = 0; j < dimensions_; ++j) {
      AxisCells& axis = axes[j];
      axis.lo = lo[j];
      axis.hi = hi[j];
      axis.first = static_cast<std::int64_t>(axis_cell(lo[j])) - reach;
      axis.last = static_cast<std::int64_t>(axis_cell(hi[j])) + reach;
      if (periodic_) {
        axis.whole_circle = axis.last - axis.first + 1 >= count;
        if (axis.whole_circle) axis.first = 0, axis.last = count - 1;
      } else {
        axis.first = std::max<std::int64_t>(axis.first, 0);
        axis.last = std::min<std::int64_t>(axis.last, count - 1);
      }
      if (axis.last - axis.first + 1 > AxisCells::capacity) {
        small = false;
        continue;
      }
      // The cells of this axis within reach, with their squared gaps.
      // Cells that overlap the query come first, so that searches stopping
      // at the first hit (coverage, rejection) usually stop early.
      axis.size = 0;
      for (int pass = 0; pass < 2; ++pass)
        for (std::int64_t unwrapped = axis.first; unwrapped <= axis.last; ++unwrapped) {
          const double gap = axis_gap(axis, unwrapped);
          if ((gap == 0) != (pass == 0) || (gap * gap >= radius2 && gap > 0)) continue;
          std::int64_t wrapped = unwrapped;
          if (wrapped < 0) wrapped += count;
          else if (wrapped >= count) wrapped -= count;
          axis.cell[axis.size] = static_cast<std::uint64_t>(wrapped);
          axis.gap2[axis.size] = gap * gap;
          ++axis.size;
        }
    }
    if (small) return visit_listed(axes, dimensions_ - 1, 0, 0.0, radius2, visit);
    return visit_axis(axes, dimensions_ - 1, 0, 0.0, radius2, visit);
  }

  /// Point version of visit_near_box.
  template <class Visit>
  bool visit_near(const double* x, double radius, Visit&& visit) const {
    return visit_near_box(x, x, radius, visit);
  }

 private:
  struct AxisCells {
    static constexpr int capacity = 8;
    double lo, hi;
    std::int64_t first, last;  // unwrapped cell indices
    bool whole_circle = false;
    int size = 0;
    std::uint64_t cell[capacity];
    double gap2[capacity];
  };

  // Distance along one axis between the query interval and cell `cell`
  // (unwrapped index: cell c + k g is the periodic image of c shifted by k).
  double axis_gap(const AxisCells& axis, std::int64_t cell) const noexcept {
    const double g = static_cast<double>(cells_per_axis_);
    auto gap = [&](double cell_lo, double cell_hi) {
      return std::max(0.0, std::max(cell_lo - axis.hi, axis.lo - cell_hi));
    };
    const double cell_lo = static_cast<double>(cell) / g, cell_hi = static_cast<double>(cell + 1) / g;
    if (!axis.whole_circle) return gap(cell_lo, cell_hi);
    return std::min({gap(cell_lo, cell_hi), gap(cell_lo - 1, cell_hi - 1), gap(cell_lo + 1, cell_hi + 1)});
  }

  template <class Visit>
  bool visit_cell(std::uint64_t cell, Visit& visit) const {
    for (std::uint32_t index = head_[cell]; index != empty; index = next_[index])
      if (!visit(index)) return false;
    return true;
  }

  // Fast path: every axis has its cells listed.
  template <class Visit>
  bool visit_listed(const AxisCells* axes, unsigned axis, std::uint64_t prefix, double partial, double radius2,
                    Visit& visit) const {
    const AxisCells& cells = axes[axis];
    for (int k = 0; k < cells.size; ++k) {
      const double sum = partial + cells.gap2[k];
      if (sum >= radius2 && sum > 0) continue;
      const std::uint64_t cell = prefix * cells_per_axis_ + cells.cell[k];
      if (axis == 0 ? !visit_cell(cell, visit) : !visit_listed(axes, axis - 1, cell, sum, radius2, visit)) return false;
    }
    return true;
  }

  // General path (long axis ranges, e.g. a radius of many cells).
  template <class Visit>
  bool visit_axis(const AxisCells* axes, unsigned axis, std::uint64_t prefix, double partial, double radius2,
                  Visit& visit) const {
    const AxisCells& range = axes[axis];
    const auto count = static_cast<std::int64_t>(cells_per_axis_);
    for (std::int64_t unwrapped = range.first; unwrapped <= range.last; ++unwrapped) {
      const double gap = axis_gap(range, unwrapped);
      const double sum = partial + gap * gap;
      if (sum >= radius2 && sum > 0) continue;
      const std::int64_t wrapped = ((unwrapped % count) + count) % count;
      const std::uint64_t cell = prefix * cells_per_axis_ + static_cast<std::uint64_t>(wrapped);
      if (axis == 0 ? !visit_cell(cell, visit) : !visit_axis(axes, axis - 1, cell, sum, radius2, visit)) return false;
    }
    return true;
  }

  unsigned dimensions_ = 1;
  std::uint64_t cells_per_axis_ = 1;
  bool periodic_ = false;
  std::vector<std::uint32_t> head_;
  std::vector<std::uint32_t> next_;
};

}  // namespace stratum
