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
/// float screen before the exact tests (grow_plane); the set is the same.
///
/// The same grid is Ebeida et al.'s (2012, "A simple algorithm for maximal
/// Poisson-disk sampling in high dimensions"): a cell with a sample is
/// covered (its diameter is ≤ r), so completion only visits empty cells, and
/// only the samples of the stencil can touch one; they are gathered once per
/// empty cell, coordinate by coordinate, so that the tests of the cell's
/// boxes vectorize. A box is covered when one disk contains it, or two, or
/// (in 2D) three: exact tests on the candidates for the farthest point.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "stratum/patterns/poisson_disk_candidates.hpp"
#include "stratum/patterns/poisson_disk_coverage.hpp"
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

/// Bridson + Ebeida on a one-sample-per-cell grid, for dimension D ≤ 3.
template <unsigned D>
class CompactPoissonDisk {
 public:
  static_assert(D >= 1 && D <= 4);

  /// Cells per axis of the unpadded grid: ⌈√D / r⌉.
  static std::uint64_t cells_per_axis(double radius) noexcept {
    return static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(D)) / radius));
  }
  /// Cells beyond the unit cube on each side: ⌈r / a⌉.
  static std::int64_t padding(double radius) noexcept {
    const double g = static_cast<double>(cells_per_axis(radius));
    return static_cast<std::int64_t>(std::ceil(radius * g * (1 - 1e-12)));
  }
  /// Bytes of the padded grid.
  static double grid_bytes(double radius) noexcept {
    const double side = static_cast<double>(cells_per_axis(radius)) + 2.0 * static_cast<double>(padding(radius));
    return std::pow(side, D) * D * sizeof(double);
  }

  CompactPoissonDisk(double radius, std::uint64_t seed, unsigned candidates, bool periodic, unsigned max_refinement,
                     BridsonKernel kernel = BridsonKernel::fastest)
      : r_(radius), r2_(radius * radius), seed_(seed), candidates_(candidates), periodic_(periodic),
        max_refinement_(max_refinement), kernel_(kernel), g_(static_cast<std::int64_t>(cells_per_axis(radius))),
        pad_(padding(radius)), side_(g_ + 2 * pad_), a_(1.0 / static_cast<double>(g_)) {
    std::int64_t stride = 1;
    for (unsigned j = 0; j < D; ++j, stride *= side_) stride_[j] = stride;
    cells_.assign(static_cast<std::size_t>(stride) * D, sentinel);
    build_stencil();
    // The block of cells around a Bridson parent whose samples are tried
    // first: Chebyshev radius 2 in 1D and 2D, 1 from 3D (within the padding).
    {
      const std::int64_t reach = std::min<std::int64_t>(D <= 2 ? 2 : 1, pad_);
      std::int64_t o[D];
      std::fill(o, o + D, -reach);
      for (;;) {
        std::int64_t linear = 0;
        for (unsigned j = 0; j < D; ++j) linear += o[j] * stride_[j];
        if (linear != 0) block_.push_back(linear);  // p's own cell holds only p, which blocks nothing
        unsigned j = 0;
        while (j < D && ++o[j] > reach) o[j++] = -reach;
        if (j == D) break;
      }
      // Rows: the block, `recent` rejecters, a NaN slot; even length.
      blocker_capacity_ = (block_.size() + recent + 2) / 2 * 2;
      blockers_.resize(blocker_capacity_ * D);
      shadows_.resize(blocker_capacity_ * D);
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
  bool occupied(std::int64_t index) const noexcept { return cells_[static_cast<std::size_t>(index) * D] != sentinel; }

  // Stencil: every offset o whose cell can hold a point closer than r to a
  // point of cell 0, i.e. a²·Σ max(|o_j| - 1, 0)² < r², nearest first.
  void build_stencil() {
    std::vector<std::pair<double, std::int64_t>> entries;
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
      unsigned j = 0;
      while (j < D && ++o[j] > pad_) o[j++] = -pad_;
      if (j == D) break;
    }
    std::sort(entries.begin(), entries.end());
    for (const auto& entry : entries) stencil_.push_back(entry.second);
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

  void add(const double* x, const std::int64_t* c) {
    points_.insert(points_.end(), x, x + D);
    auto store = [&](std::int64_t index, const double* value) {
      std::copy(value, value + D, cells_.begin() + index * D);
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

  // Phase 1 in the plane, eight candidates at a time. A step lists the
  // samples of the cells around p (which shadow most of its annulus) as
  // float offsets from p, draws eight candidates in float
  // (annulus_offsets_2d_float) and tests them against every listed sample
  // at once, one vector operation per sample for the eight. A candidate
  // whose squared distance to a listed sample is below r²·(1 - 4·10^-4) in
  // float is surely closer than r: offsets err by less than 10^-5·2r
  // (annulus_offsets_2d_float), so squared distances below r² err by less
  // than 5·10^-5·r² (offsets from p keep errors relative to r, whatever r
  // is). Every other candidate, in order, is drawn again in double exactly
  // as grow_sequential draws it and meets the exact tests (the cube, then
  // is_free); if a sample rejects it, that sample joins the list and
  // shadows the batch's later candidates too. A candidate is thus placed
  // iff grow_sequential would place it, and the first one placed is the
  // same: the sets are equal bit for bit. Most steps retire their point
  // after k failures, and then every batch is usually shut by the screen
  // alone: no double arithmetic, no grid look-up.
  [[gnu::always_inline]] inline void grow_plane() {
    static_assert(D == 2);
    using floats8 = float __attribute__((vector_size(32)));
    using mask8 = int __attribute__((vector_size(32)));
    const std::array<double, 512>& circle = unit_circle_256();
    const std::array<float, 512>& circle_float = unit_circle_256_float();
    std::int64_t c[2];
    std::vector<std::uint32_t> active = start();
    const std::uint64_t step_key = hash64(seed_, tag_candidate);
    const std::size_t capacity = blocker_capacity_;
    float* const wx = shadows_.data();
    float* const wy = wx + capacity;
    const float surely2 = static_cast<float>(r2_ * (1 - shadow_margin));
    const float r_float = static_cast<float>(r_);
    const mask8 lane_index = {0, 1, 2, 3, 4, 5, 6, 7};
    const auto open_lanes = [](const mask8& shut) {
      unsigned open = 0;
      for (unsigned lane = 0; lane < 8; ++lane) open |= unsigned(shut[lane] == 0) << lane;
      return open;
    };
    for (std::uint64_t step = 0; !active.empty(); ++step) {
      const std::uint64_t key = hash64(step_key, step);
      const std::size_t pick = uniform_below(active.size(), key, tag_pick);
      const double* p_row = points_.data() + std::size_t(active[pick]) * 2;
      const double p[2] = {p_row[0], p_row[1]};
      for (unsigned j = 0; j < 2; ++j) c[j] = axis_cell(p[j]);
      const std::int64_t centre = cell_index(c);
      std::size_t count = 0;
      for (const std::int64_t offset_index : block_) {
        const double* q = cell(centre + offset_index);
        wx[count] = static_cast<float>(q[0] - p[0]);
        wy[count] = static_cast<float>(q[1] - p[1]);
        count += q[0] != sentinel;
      }
      bool placed = false;
      for (unsigned first = 0; first < candidates_ && !placed; first += 8) {
        floats8 ox, oy;
        annulus_offsets_2d_float(r_float, key, first, ox, oy, circle_float);
        // Lanes that cannot take a sample: past the last candidate, or
        // surely closer than r to a listed sample.
        mask8 shut = lane_index >= static_cast<int>(candidates_ - first);
        for (std::size_t b = 0; b < count; ++b) {
          const floats8 dx = wx[b] - ox, dy = wy[b] - oy;
          shut |= dx * dx + dy * dy < surely2;
        }
        std::uint64_t words[4];  // all shut (lanes are 0 or -1): the usual case
        std::memcpy(words, &shut, sizeof words);
        if ((words[0] & words[1] & words[2] & words[3]) == ~std::uint64_t{0}) continue;
        for (unsigned open = open_lanes(shut); open != 0; open &= open_lanes(shut)) {
          const unsigned lane = static_cast<unsigned>(__builtin_ctz(open));
          shut[lane] = -1;
          double offset[2], unwrapped[2], wrapped[2];
          annulus_offset_2d(r_, key, first + lane, offset, circle);
          bool inside = true;
          for (unsigned j = 0; j < 2; ++j) {
            unwrapped[j] = p[j] + offset[j];
            if (!periodic_) inside &= (unwrapped[j] >= 0.0) & (unwrapped[j] < 1.0);
          }
          if (!inside) continue;
          wrap(unwrapped, wrapped, c);
          double hit[2];
          if (is_free(wrapped, cell_index(c), hit)) {
            active.push_back(static_cast<std::uint32_t>(points_.size() / 2));
            add(wrapped, c);
            placed = true;
            break;
          }
          // The rejecter, as its image nearest to this candidate, shadows
          // the later candidates too.
          float image[2];
          for (unsigned j = 0; j < 2; ++j)
            image[j] = static_cast<float>(nearest_image(hit[j], unwrapped[j], wrapped[j]) - p[j]);
          if (count < capacity) {
            wx[count] = image[0];
            wy[count] = image[1];
            ++count;
          }
          const floats8 dx = image[0] - ox, dy = image[1] - oy;
          shut |= dx * dx + dy * dy < surely2;
        }
      }
      if (!placed) {
        active[pick] = active.back();
        active.pop_back();
      }
    }
  }

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
          for (unsigned j = 0; j < D; ++j) blockers_[j * capacity + next_recent] = nearest_image(hit[j], x[j], wrapped[j]);
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

  // Does one sample of the nearest 3^D cells contain the whole cell at lo?
  // Most empty cells are covered so (no farther sample can cover a cell
  // alone), and this settles them without listing the stencil. The test is
  // covered()'s single-disk test, operation for operation, so it answers
  // as covered() would for these samples.
  bool covered_by_neighbour(const double* lo, std::int64_t base) const noexcept {
    constexpr std::size_t block = D == 1 ? 3 : D == 2 ? 9 : D == 3 ? 27 : 81;
    const std::size_t first = std::min(block, stencil_.size());
    const double half = sides_[0] / 2;
    bool any = false;
    for (std::size_t k = 0; k < first; ++k) {
      const double* q = cell(base + stencil_[k]);
      double far2 = 0;
      for (unsigned j = 0; j < D; ++j) {
        const double gap = std::abs((lo[j] + half) - q[j]) + half;
        far2 += gap * gap;
      }
      any |= far2 <= r2_;
    }
    return any;
  }

  // Is the box [lo, lo + side] inside the union of the disks of the listed
  // samples? Exact tests, so the answer "yes" is always right: one disk
  // covers the box when its farthest corner is within r; two disks p, q
  // cover it when every corner is within r of p or q and every point where
  // their bisector crosses an edge of the box is within r of both (the
  // farthest point of the box from {p, q} is a corner or such a crossing,
  // since distance to p is convex on the box's half on p's side). "No" may
  // be wrong (three or more disks needed); the box is then split.
  bool covered(const double* lo, double side) const noexcept {
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
    bool any = false;
    for (std::size_t k = 0; k < n; ++k) any |= far2[k] <= r2_;
    if (any) return true;
    if (n < 2) return false;
    // The three samples whose disks come closest to containing the box.
    std::size_t rank[3] = {0, 1, 2};
    if (far2[1] < far2[0]) std::swap(rank[0], rank[1]);
    if (n == 2) rank[2] = rank[1];
    for (std::size_t k = 2; k < n; ++k) {
      if (k > 2 && far2[k] >= far2[rank[2]]) continue;
      rank[2] = k;
      if (far2[rank[2]] < far2[rank[1]]) std::swap(rank[1], rank[2]);
      if (far2[rank[1]] < far2[rank[0]]) std::swap(rank[0], rank[1]);
    }
    double site[3][D];
    for (unsigned i = 0; i < 3; ++i)
      for (unsigned j = 0; j < D; ++j) site[i][j] = local_[j * capacity + rank[i]];
    if (pair_covers<D>(lo, side, site[0], site[1], r2_)) return true;
    if constexpr (D == 2) return n >= 3 && triple_covers(lo, side, site, r2_);
    return false;
  }

  // Is x, a point of the closed current cell, at distance ≥ r from every
  // listed sample? (The list holds every sample within r of the cell.)
  bool locally_free(const double* x) const noexcept {
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
  bool place(const double* x, const std::int64_t* c) {
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
  void complete() {
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
    const std::size_t capacity = stencil_.size();
    for (;;) {
      const std::int64_t base = cell_index(c);
      Box box{};
      for (unsigned j = 0; j < D; ++j) box.lo[j] = static_cast<double>(c[j]) * a_;
      if (!occupied(base) && !covered_by_neighbour(box.lo, base)) {
        local_size_ = 0;  // branch-free compaction of the stencil's samples
        for (const std::int64_t offset : stencil_) {
          const double* q = cell(base + offset);
          for (unsigned j = 0; j < D; ++j) local_[j * capacity + local_size_] = q[j];
          local_size_ += q[0] != sentinel;
        }
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
  std::vector<std::int64_t> block_;        // offsets of the cells around a parent
  std::vector<double> blockers_;           // a step's blockers, one row per axis
  std::vector<float> shadows_;             // grow_plane's blockers, offsets from p, one row per axis
  std::size_t blocker_capacity_ = 0;
  std::vector<double> local_;  // samples of the current cell's stencil, one row per axis
  std::size_t local_size_ = 0;
  mutable std::vector<double> far2_;  // scratch: farthest-corner distances
  std::vector<double> sides_;  // box side at each refinement level
};

}  // namespace stratum::poisson_detail
