#pragma once
/// The engine of stratum's maximal Poisson-disk sampler for d = 1..4 (see
/// poisson_disk.hpp for the method and its sources).
///
/// Bridson's background grid (Bridson 2007, "Fast Poisson disk sampling in
/// arbitrary dimensions"): cells of side a = 1/⌈√d/r⌉ ≤ r/√d, so a cell
/// holds at most one sample, stored inline (its coordinates, or a far-away
/// sentinel). The grid is padded by the reach of a query; on the torus the
/// padding holds the periodic images of the samples near a face, so no
/// query ever wraps. A Bridson step first lists the samples in the block of
/// cells around the active point p (its neighbours, which shadow most of
/// its annulus) and tests each candidate against them, two at a time in a
/// vector register; only candidates that pass meet the full test, a stencil
/// of the cells that can hold a sample closer than r (nearest first, the
/// nearest 3^d without branches), and a sample found there joins the list.
/// In the plane (the common case) candidates go eight at a time through a
/// float screen before the exact tests (grow_plane, poisson_disk_plane.hpp);
/// the set is the same. The plane also keeps one byte per cell saying
/// whether it holds a sample (poisson_disk_occupancy.hpp), so that a block
/// of cells is read a row at a time and only its occupied cells are visited.
///
/// The same grid is Ebeida et al.'s (2012, "A simple algorithm for maximal
/// Poisson-disk sampling in high dimensions"): a cell with a sample is
/// covered (its diameter is ≤ r), so completion only visits empty cells, and
/// only the samples of the stencil can touch one; they are gathered once per
/// empty cell, coordinate by coordinate, so that the tests of the cell's
/// boxes vectorize. A box is covered when one disk contains it, or two, or
/// (in 2D) three: exact tests on the candidates for the farthest point
/// (poisson_disk_completion.hpp).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "stratum/patterns/poisson_disk_candidates.hpp"
#include "stratum/patterns/poisson_disk_coverage.hpp"
#include "stratum/patterns/poisson_disk_occupancy.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum::poisson_detail {

/// Which implementation of Bridson's phase runs. All give the same set,
/// bit for bit (tested): `sequential` tries one candidate at a time (any
/// d); in the plane, `batched` screens eight at a time in float vectors
/// (grow_plane), and `fastest` is `batched` compiled for AVX2 when the CPU
/// has it (x86-64 with GCC or Clang), else `batched`.
enum class BridsonKernel { fastest, batched, sequential };

/// Bridson + Ebeida on a one-sample-per-cell grid, for dimension D ≤ 4.
template <unsigned D>
class CompactPoissonDisk {
 public:
  static_assert(D >= 1 && D <= 4);

  /// Cells per axis of the unpadded grid: ⌈√D / r⌉.
  static std::uint64_t cells_per_axis(double radius) noexcept {
    return static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(D)) / radius));
  }
  /// Chebyshev radius of the block of cells whose samples grow_plane lists
  /// around a parent p. Candidates lie within 2r of p, so the samples that
  /// reject them lie within 3r ≈ 4.2 cells; radius 3 holds most of them. At
  /// r = 0.01 (6,200 placements), radius 2 let 11,500 candidates through
  /// the float screen only to be rejected by the exact test, radius 3 lets
  /// 1,400 through, which saves more than screening twice the samples costs.
  static constexpr std::int64_t plane_reach = 3;
  /// Cells beyond the unit cube on each side: ⌈r / a⌉, the reach of a
  /// query, and in the plane at least plane_reach.
  static std::int64_t padding(double radius) noexcept {
    const double g = static_cast<double>(cells_per_axis(radius));
    const auto reach = static_cast<std::int64_t>(std::ceil(radius * g * (1 - 1e-12)));
    return D == 2 ? std::max(reach, plane_reach) : reach;
  }
  /// Bytes of the padded grid.
  static double grid_bytes(double radius) noexcept {
    const double side = static_cast<double>(cells_per_axis(radius)) + 2.0 * static_cast<double>(padding(radius));
    return std::pow(side, D) * D * sizeof(double);
  }

  CompactPoissonDisk(double radius, std::uint64_t seed, unsigned candidates, bool periodic, unsigned max_refinement,
                     BridsonKernel kernel = BridsonKernel::fastest)
      : r_(radius),
        r2_(radius * radius),
        seed_(seed),
        candidates_(candidates),
        periodic_(periodic),
        max_refinement_(max_refinement),
        kernel_(kernel),
        g_(static_cast<std::int64_t>(cells_per_axis(radius))),
        pad_(padding(radius)),
        side_(g_ + 2 * pad_),
        a_(1.0 / static_cast<double>(g_)) {
    std::int64_t stride = 1;
    for (unsigned j = 0; j < D; ++j, stride *= side_) stride_[j] = stride;
    cells_.assign(static_cast<std::size_t>(stride) * D, sentinel);
    if constexpr (D == 2) occupancy_.reset(static_cast<std::size_t>(stride));
    build_stencil();
    // The block of cells around a Bridson parent whose samples are tried
    // first: Chebyshev radius 2 in 1D and 2D, 1 from 3D (within the
    // padding); in the plane, grow_plane's block of radius plane_reach.
    // p's own cell holds only p, which blocks nothing.
    {
      const std::int64_t reach = std::min<std::int64_t>(D <= 2 ? 2 : 1, pad_);
      std::int64_t o[D];
      std::fill(o, o + D, -reach);
      for (;;) {
        std::int64_t linear = 0;
        for (unsigned j = 0; j < D; ++j) linear += o[j] * stride_[j];
        if (linear != 0) block_.push_back(linear);
        unsigned j = 0;
        while (j < D && ++o[j] > reach) o[j++] = -reach;
        if (j == D) break;
      }
      // Rows: the block, `recent` rejecters, a NaN slot; even length.
      blocker_capacity_ = (block_.size() + recent + 2) / 2 * 2;
      blockers_.resize(blocker_capacity_ * D);
    }
    if constexpr (D == 2) {
      std::vector<std::pair<std::int64_t, std::int64_t>> block_cells;
      for (std::int64_t y = -plane_reach; y <= plane_reach; ++y)
        for (std::int64_t x = -plane_reach; x <= plane_reach; ++x)
          if (x != 0 || y != 0) block_cells.emplace_back(x, y);
      block_pattern_ = CellPattern(block_cells, stride_[1]);
      // Rows: the block, then rejecters.
      shadow_capacity_ = block_pattern_.size() + recent;
      shadows_.resize(shadow_capacity_ * D);
    }
    local_.resize(stencil_.size() * D);
    far2_.resize(stencil_.size());
    sides_.resize(max_refinement + 1);
    for (unsigned level = 0; level <= max_refinement; ++level) sides_[level] = std::ldexp(a_, -static_cast<int>(level));
  }

  /// The maximal set, row-major, Bridson's samples first.
  std::vector<double> generate() {
    grow();
    complete();
    return std::move(points_);
  }

 private:
  static constexpr double sentinel = 1e30;  // "no sample": far from everything
  /// grow_plane's safety margin, relative to r², for float distances.
  static constexpr double shadow_margin = 4e-4;

  std::int64_t cell_index(const std::int64_t* c) const noexcept {
    std::int64_t index = 0;
    for (unsigned j = 0; j < D; ++j) index += (c[j] + pad_) * stride_[j];
    return index;
  }
  std::int64_t axis_cell(double x) const noexcept {
    return std::min(static_cast<std::int64_t>(x * static_cast<double>(g_)), g_ - 1);
  }
  const double* cell(std::int64_t index) const noexcept { return cells_.data() + index * D; }
  bool occupied(std::int64_t index) const noexcept {
    if constexpr (D == 2) return occupancy_.occupied(index);  // a byte, not the cell's 16
    return cells_[static_cast<std::size_t>(index) * D] != sentinel;
  }

  // Stencil: every offset o whose cell can hold a point closer than r to a
  // point of cell 0, i.e. a²·Σ max(|o_j| - 1, 0)² < r², nearest first.
  // In the plane, the same cells as a CellPattern, and the bits of its
  // nearest 3×3 cells.
  void build_stencil() {
    std::vector<std::pair<double, std::int64_t>> entries;
    std::vector<std::pair<std::int64_t, std::int64_t>> plane_cells;
    std::int64_t o[D];
    std::fill(o, o + D, -pad_);
    for (;;) {
      double gap2 = 0;
      std::int64_t linear = 0;
      for (unsigned j = 0; j < D; ++j) {
        const double gap = static_cast<double>(std::max<std::int64_t>(std::abs(o[j]) - 1, 0)) * a_;
        gap2 += gap * gap;
        linear += o[j] * stride_[j];
      }
      double centre2 = 0;  // ties: nearer centres first
      for (unsigned j = 0; j < D; ++j) centre2 += static_cast<double>(o[j] * o[j]);
      if (gap2 < r2_) entries.emplace_back(gap2 * 1e6 + centre2 * a_ * a_, linear);
      if (D == 2 && gap2 < r2_) plane_cells.emplace_back(o[0], o[D - 1]);
      unsigned j = 0;
      while (j < D && ++o[j] > pad_) o[j++] = -pad_;
      if (j == D) break;
    }
    std::sort(entries.begin(), entries.end());
    for (const auto& entry : entries) stencil_.push_back(entry.second);
    if constexpr (D == 2) {
      stencil_pattern_ = CellPattern(plane_cells, stride_[1]);
      neighbour_bits_ = stencil_pattern_.bits_where(
          stride_[1], [](std::int64_t x, std::int64_t y) { return std::abs(x) <= 1 && std::abs(y) <= 1; });
    }
  }

  // Is x (inside the cube, cell `base`) at distance ≥ r from every sample?
  // The nearest 3^D cells are tested without branches (most conflicts are
  // there), the rest one by one. On a conflict, `blocker` (when given) gets
  // the conflicting sample's coordinates.
  bool is_free(const double* x, std::int64_t base, double* blocker = nullptr) const noexcept {
    constexpr std::size_t block = D == 1 ? 3 : D == 2 ? 9 : D == 3 ? 27 : 81;
    const std::size_t first = std::min(block, stencil_.size());
    const double* hit = nullptr;
    for (std::size_t k = 0; k < first; ++k) {
      const double* q = cell(base + stencil_[k]);
      double sum = 0;
      for (unsigned j = 0; j < D; ++j) sum += (q[j] - x[j]) * (q[j] - x[j]);
      hit = sum < r2_ ? q : hit;
    }
    for (std::size_t k = first; hit == nullptr && k < stencil_.size(); ++k) {
      const double* q = cell(base + stencil_[k]);
      double sum = 0;
      for (unsigned j = 0; j < D; ++j) sum += (q[j] - x[j]) * (q[j] - x[j]);
      if (sum < r2_) hit = q;
    }
    if (hit != nullptr && blocker != nullptr) std::copy(hit, hit + D, blocker);
    return hit == nullptr;
  }

  // is_free in the plane, visiting only the occupied cells of the stencil,
  // with the same test for each sample. It may name another conflicting
  // sample than is_free does; grow_plane only uses it as a shadow.
  bool is_free_plane(const double* x, std::int64_t base, double* blocker) const noexcept {
    for (std::uint64_t bits = stencil_pattern_.occupied(occupancy_, base); bits != 0; bits &= bits - 1) {
      const double* q = cell(base + stencil_pattern_.offset(static_cast<unsigned>(std::countr_zero(bits))));
      double sum = 0;
      for (unsigned j = 0; j < D; ++j) sum += (q[j] - x[j]) * (q[j] - x[j]);
      if (sum < r2_) {
        std::copy(q, q + D, blocker);
        return false;
      }
    }
    return true;
  }

  void add(const double* x, const std::int64_t* c) {
    for (unsigned j = 0; j < D; ++j) points_.push_back(x[j]);
    auto store = [&](std::int64_t index, const double* value) {
      std::copy(value, value + D, cells_.begin() + index * D);
      if constexpr (D == 2) occupancy_.mark(index);
    };
    store(cell_index(c), x);
    if (!periodic_) return;
    // Periodic images that land in the padding.
    int shift[D] = {};
    std::fill(shift, shift + D, -1);
    for (;;) {
      bool inside = true, identity = true;
      std::int64_t shifted[D];
      double image[D];
      for (unsigned j = 0; j < D; ++j) {
        shifted[j] = c[j] + shift[j] * g_;
        image[j] = x[j] + shift[j];
        inside = inside && shifted[j] >= -pad_ && shifted[j] < g_ + pad_;
        identity = identity && shift[j] == 0;
      }
      if (inside && !identity) store(cell_index(shifted), image);
      unsigned j = 0;
      while (j < D && ++shift[j] > 1) shift[j++] = -1;
      if (j == D) break;
    }
  }

  // Is x closer than r to one of the first `count` blockers (rows of
  // `capacity`)? Two blockers at a time in a vector register (GCC/Clang
  // vector extensions); rows have an even length and the slot after the
  // last blocker holds NaN, which compares false.
  bool blocked(const double* x, std::size_t count, std::size_t capacity) const noexcept {
    using pair = double __attribute__((vector_size(16)));
    using mask = long long __attribute__((vector_size(16)));
    const double* rows = blockers_.data();
    mask any = {0, 0};
    for (std::size_t b = 0; b < count; b += 2) {
      pair sum = {0, 0};
      for (unsigned j = 0; j < D; ++j) {
        pair row;
        std::memcpy(&row, rows + j * capacity + b, sizeof(pair));
        const pair delta = row - x[j];
        sum += delta * delta;
      }
      any |= sum < r2_;
    }
    return (any[0] | any[1]) != 0;
  }

  // Bridson's first sample, uniform in the cube; returns the active list.
  std::vector<std::uint32_t> start() {
    double x[D];
    std::int64_t c[D];
    for (unsigned j = 0; j < D; ++j) {
      x[j] = uniform01(seed_, tag_first, j);
      c[j] = axis_cell(x[j]);
    }
    add(x, c);
    return {0};
  }

  // A candidate x moved into the cube (on the torus), and its cell.
  void wrap(const double* x, double* wrapped, std::int64_t* c) const noexcept {
    for (unsigned j = 0; j < D; ++j) {
      wrapped[j] = x[j];
      if (periodic_) {
        wrapped[j] -= std::floor(wrapped[j]);
        if (wrapped[j] >= 1.0) wrapped[j] = 0.0;  // -tiny wraps to 1 after rounding
      }
      c[j] = axis_cell(wrapped[j]);
    }
  }

  // Coordinate of the image of a sample `hit` (found near the wrapped
  // candidate) nearest to the unwrapped candidate x.
  double nearest_image(double hit, double x, double wrapped) const noexcept {
    double image = hit + (x - wrapped);
    if (periodic_) image -= std::nearbyint(image - x);
    return image;
  }

  // Phase 1, Bridson's annulus dart throwing, with the kernel asked for.
  void grow() {
    if constexpr (D == 2) {
      if (kernel_ != BridsonKernel::sequential) {
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
        if (kernel_ == BridsonKernel::fastest && __builtin_cpu_supports("avx2")) return grow_plane_avx2();
#endif
        return grow_plane();
      }
    }
    grow_sequential();
  }

#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
  // AVX2 without FMA: the exact tests and the double candidates inlined
  // here must round as grow_sequential's do, which contraction into fused
  // multiply-adds would change.
  [[gnu::target("avx2")]] void grow_plane_avx2() { grow_plane(); }
#endif

  // Phase 1 in the plane, eight candidates at a time (poisson_disk_plane.hpp).
  [[gnu::always_inline]] inline void grow_plane();

  // Phase 1, one candidate at a time (any d).
  void grow_sequential() {
    const std::array<double, 512>& circle = unit_circle_256();
    double x[D], offset[D];
    std::int64_t c[D];
    std::vector<std::uint32_t> active = start();
    const std::uint64_t step_key = hash64(seed_, tag_candidate);
    for (std::uint64_t step = 0; !active.empty(); ++step) {
      // One hash per step keys both the pick and the candidates.
      const std::uint64_t key = hash64(step_key, step);
      const std::size_t pick = uniform_below(active.size(), key, tag_pick);
      const double* p_row = points_.data() + std::size_t(active[pick]) * D;
      double p[D];
      std::copy(p_row, p_row + D, p);
      // Blockers: the samples in the block of cells around p (its nearest
      // neighbours, which shadow most of its annulus), then those that
      // rejected this step's earlier candidates. All are unwrapped images
      // near p (the padding holds images), so a candidate p + offset is
      // tested against them without wrapping, and most rejections never
      // touch the grid.
      const std::size_t capacity = blocker_capacity_;
      std::size_t count = 0;  // blockers listed, one row per axis
      for (unsigned j = 0; j < D; ++j) c[j] = axis_cell(p[j]);
      const std::int64_t centre = cell_index(c);
      for (const std::int64_t offset_index : block_) {
        const double* q = cell(centre + offset_index);
        for (unsigned j = 0; j < D; ++j) blockers_[j * capacity + count] = q[j];
        count += q[0] != sentinel;
      }
      const std::size_t neighbours = count;
      std::size_t next_recent = neighbours;
      for (unsigned j = 0; j < D; ++j) blockers_[j * capacity + count] = std::numeric_limits<double>::quiet_NaN();
      bool placed = false;
      for (unsigned k = 0; k < candidates_ && !placed; ++k) {
        if constexpr (D == 2) annulus_offset_2d(r_, key, k, offset, circle);
        else annulus_offset(D, r_, key, k, offset);
        bool inside = true;
        for (unsigned j = 0; j < D; ++j) {
          x[j] = p[j] + offset[j];
          if (!periodic_) inside &= (x[j] >= 0.0) & (x[j] < 1.0);
        }
        if (!inside || blocked(x, count, capacity)) continue;
        double wrapped[D];
        wrap(x, wrapped, c);
        double hit[D];
        if (!is_free(wrapped, cell_index(c), hit)) {
          // Remember the rejecter, as its image nearest to the unwrapped x.
          for (unsigned j = 0; j < D; ++j)
            blockers_[j * capacity + next_recent] = nearest_image(hit[j], x[j], wrapped[j]);
          if (next_recent == count) {
            ++count;
            for (unsigned j = 0; j < D; ++j) blockers_[j * capacity + count] = std::numeric_limits<double>::quiet_NaN();
          }
          next_recent = next_recent + 1 < neighbours + recent ? next_recent + 1 : neighbours;
          continue;
        }
        active.push_back(static_cast<std::uint32_t>(points_.size() / D));
        add(wrapped, c);
        placed = true;
      }
      if (!placed) {
        active[pick] = active.back();
        active.pop_back();
      }
    }
  }

  // Phase 2, completion (poisson_disk_completion.hpp).
  void complete();
  bool disk_covers_cell(const double* lo, const double* q) const noexcept;
  bool list_stencil_unless_covered(const double* lo, std::int64_t base);
  bool covered(const double* lo, double side) const noexcept;
  bool locally_free(const double* x) const noexcept;
  bool place(const double* x, const std::int64_t* c);

  double r_, r2_;
  std::uint64_t seed_;
  unsigned candidates_;
  bool periodic_;
  unsigned max_refinement_;
  BridsonKernel kernel_;
  std::int64_t g_, pad_, side_;
  double a_;
  std::int64_t stride_[D];
  std::vector<double> cells_;
  std::vector<std::int64_t> stencil_;
  std::vector<double> points_;
  static constexpr std::size_t recent = 8;  // blockers remembered from rejections
  std::vector<std::int64_t> block_;         // offsets of the cells around a parent
  std::vector<double> blockers_;            // a step's blockers, one row per axis
  std::vector<float> shadows_;              // grow_plane's blockers, offsets from p, one row per axis
  CellOccupancy occupancy_;                 // in the plane: which cells hold a sample
  std::size_t shadow_capacity_ = 0;
  CellPattern block_pattern_;         // in the plane: grow_plane's block
  CellPattern stencil_pattern_;       // in the plane: stencil_ as a pattern
  std::uint64_t neighbour_bits_ = 0;  // its nearest 3×3 cells
  std::size_t blocker_capacity_ = 0;
  std::vector<double> local_;  // samples of the current cell's stencil, one row per axis
  std::size_t local_size_ = 0;
  mutable std::vector<double> far2_;  // scratch: farthest-corner distances
  std::vector<double> sides_;         // box side at each refinement level
};

}  // namespace stratum::poisson_detail

#include "stratum/patterns/poisson_disk_completion.hpp"  // CompactPoissonDisk<D>::complete
#include "stratum/patterns/poisson_disk_plane.hpp"       // CompactPoissonDisk<2>::grow_plane
