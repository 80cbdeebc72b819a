#pragma once
/// Best-candidate patterns (Mitchell 1991, "Spectrally optimal sampling for
/// distribution ray tracing"): points are added one at a time; point i
/// (i ≥ 1, with i points already placed) is the best of k·i uniform random
/// candidates, "best" meaning farthest from its nearest existing point. The
/// first point is uniform. Distances are toroidal by default, as Mitchell's,
/// so the pattern tiles the plane. The result approximates a Poisson-disk
/// pattern, and every prefix is itself a best-candidate pattern
/// (progressive): the first m of n points are the m-point pattern.
///
/// `candidates` is Mitchell's multiplier k (default 10), not a fixed count:
/// the work is k·n(n−1)/2 candidates, so n is bounded in practice (the
/// registry caps the total).
///
/// Making that affordable without changing the result: a fine grid (about 4
/// cells per final point) keeps for each cell c an upper bound U_c ≥ max over
/// the cell of the distance to the nearest point (each new point p lowers U_c
/// to its farthest-corner distance from p). A candidate can win only if its
/// nearest-point distance exceeds the best so far, b; when U_c ≤ b it is
/// rejected after one table look-up. The few others get an exact
/// nearest-neighbour search in a second grid, stopped as soon as a point
/// closer than b turns up. Since both tests are exact, the chosen point is
/// the same as brute force would choose.
///
/// Candidates use 32-bit coordinates from one counter-based SplitMix64 word
/// per two coordinates; the winner then gets 21 further random low bits, so
/// output coordinates are full doubles. Counter-based throughout: the
/// pattern depends only on (seed, n, d, k, periodic), never on threads.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "stratum/patterns/neighbor_grid.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

class BestCandidate {
 public:
  static constexpr unsigned max_dimensions = 4;
  static constexpr unsigned default_candidates = 10;
  static constexpr unsigned max_candidates = 1000;
  /// Up to this n every candidate is measured against every point (k·n³/6
  /// distances), which costs less than the grids' upkeep (BENCHMARKS §1.5:
  /// 17× faster at 4 points, 2× at 32; the grids win from about 64).
  static constexpr std::uint64_t small_points = 32;
  /// Largest n: indices are 32-bit.
  static constexpr std::uint64_t max_points = std::uint64_t{1} << 31;

  explicit BestCandidate(unsigned dimensions, std::uint64_t seed = 0, unsigned candidates = default_candidates,
                         bool periodic = true)
      : dimensions_(dimensions), seed_(seed), candidates_(candidates), periodic_(periodic) {
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions, "best-candidate supports d = 1 to 4");
    require(candidates >= 1 && candidates <= max_candidates, "candidates", candidates, "must be in [1, 1000]");
  }

  unsigned dimensions() const noexcept { return dimensions_; }
  unsigned candidates() const noexcept { return candidates_; }
  bool periodic() const noexcept { return periodic_; }

  /// Candidates evaluated for n points: k·n(n−1)/2 (saturating).
  static std::uint64_t candidate_count(std::uint64_t n, unsigned candidates) noexcept {
    if (n < 2) return 0;
    const long double total = static_cast<long double>(candidates) * n * (n - 1) / 2;
    return total >= 0x1.0p63L ? std::uint64_t{1} << 63 : static_cast<std::uint64_t>(total);
  }

  /// n points, row-major, in the order they were chosen.
  template <class Real = double>
  std::vector<Real> generate(std::uint64_t n) const {
    std::vector<Real> out(static_cast<std::size_t>(n) * dimensions_);
    generate(n, out.data());
    return out;
  }

  /// Writes n points (row-major, d per point) to `out`.
  template <class Real = double>
  void generate(std::uint64_t n, Real* out) const {
    require(n >= 1 && n <= max_points, "n", n, "best-candidate takes 1 to 2^31 points");
    switch (dimensions_) {
      case 1:
        run<1>(n, out);
        break;
      case 2:
        run<2>(n, out);
        break;
      case 3:
        run<3>(n, out);
        break;
      default:
        run<4>(n, out);
        break;
    }
  }

  /// Replay hooks (for tests and tools): the first point; the 32-bit
  /// coordinates of candidate `index` of round `round` (round i chooses
  /// point i from k·i candidates); the random low bits (below 2^-32) added
  /// to each coordinate j of round `round`'s winner.
  static void first_point(std::uint64_t seed, unsigned d, double* x) noexcept {
    for (unsigned j = 0; j < d; ++j) x[j] = uniform01(seed, tag_first, j);
  }
  static void candidate(std::uint64_t seed, unsigned d, std::uint64_t round, std::uint64_t index, double* x) noexcept {
    const std::uint64_t key = round_key(seed, round);
    switch (d) {
      case 1:
        coordinates<1>(key, index, x);
        break;
      case 2:
        coordinates<2>(key, index, x);
        break;
      case 3:
        coordinates<3>(key, index, x);
        break;
      default:
        coordinates<4>(key, index, x);
        break;
    }
  }
  static double low_bits(std::uint64_t seed, std::uint64_t round, unsigned j) noexcept {
    return static_cast<double>(hash64(seed, tag_low_bits, round, j) >> 43) * 0x1.0p-53;
  }

 private:
  static std::uint64_t round_key(std::uint64_t seed, std::uint64_t round) noexcept {
    return hash64(seed, tag_round, round);
  }

  // A candidate's coordinates: 32 bits each, two per word of its stream.
  template <unsigned D>
  static void coordinates(std::uint64_t key, std::uint64_t candidate, double* x) noexcept {
    constexpr unsigned words = (D + 1) / 2;
    for (unsigned w = 0; w < words; ++w) {
      const std::uint64_t bits = mix64(key + (candidate * words + w + 1) * golden);
      x[2 * w] = static_cast<double>(bits >> 32) * 0x1.0p-32;
      if (2 * w + 1 < D) x[2 * w + 1] = static_cast<double>(bits & 0xffffffffu) * 0x1.0p-32;
    }
  }

  static constexpr std::uint64_t tag_first = 0x4243'4649'5253'54ULL;
  static constexpr std::uint64_t tag_round = 0x4243'524f'554eULL;
  static constexpr std::uint64_t tag_low_bits = 0x4243'4c4f'5742ULL;
  static constexpr std::uint64_t golden = 0x9e3779b97f4a7c15ULL;

  // Small sets without grids (small_points), larger ones through the engine's.
  template <unsigned D, class Real>
  void run(std::uint64_t n, Real* out) const {
    if (n <= small_points) run_small<D>(n, out);
    else Engine<D>(*this, n).run(out);
  }

  // Mitchell's rounds without grids: the engine's choices (it prunes only
  // candidates that cannot win), for n ≤ small_points.
  template <unsigned D, class Real>
  void run_small(std::uint64_t n, Real* out) const {
    double points[small_points * D], x[D];
    first_point(seed_, D, points);
    for (std::uint64_t i = 1; i < n; ++i) {
      const std::uint64_t key = round_key(seed_, i);
      const std::uint64_t count = static_cast<std::uint64_t>(candidates_) * i;
      double best2 = -1;
      std::uint64_t best_index = 0;
      for (std::uint64_t candidate = 0; candidate < count; ++candidate) {
        coordinates<D>(key, candidate, x);
        const double nearest2 = NeighborGrid::nearest_squared(x, points, i, D, periodic_);
        if (nearest2 > best2) best2 = nearest2, best_index = candidate;
      }
      coordinates<D>(key, best_index, x);
      for (unsigned j = 0; j < D; ++j)
        points[i * D + j] = std::min(x[j] + low_bits(seed_, i, j), one_minus_epsilon_double);
    }
    for (std::uint64_t k = 0; k < n * D; ++k) out[k] = to_unit<Real>(points[k]);
  }

  template <unsigned D>
  class Engine {
   public:
    Engine(const BestCandidate& owner, std::uint64_t n)
        : owner_(owner),
          n_(n),
          periodic_(owner.periodic_),
          bound_cells_(
              static_cast<std::int64_t>(std::ceil(std::pow(cells_per_point * static_cast<double>(n), 1.0 / D)))),
          search_(D,
                  static_cast<std::uint64_t>(std::max(1.0, std::floor(std::pow(static_cast<double>(n) / 2, 1.0 / D)))),
                  owner.periodic_) {
      std::int64_t total = 1;
      for (unsigned j = 0; j < D; ++j) total *= bound_cells_;
      bound_.assign(static_cast<std::size_t>(total), std::numeric_limits<float>::infinity());
      points_.reserve(static_cast<std::size_t>(n) * D);
    }

    template <class Real>
    void run(Real* out) {
      double x[D];
      first_point(owner_.seed_, D, x);
      insert(x);
      for (std::uint64_t i = 1; i < n_; ++i) {
        choose(i, x);
        insert(x);
      }
      for (std::size_t k = 0; k < points_.size(); ++k) out[k] = to_unit<Real>(points_[k]);
    }

   private:
    // Farthest distance along one axis from p to a point of [lo, hi].
    double far_gap(double lo, double hi, double p) const noexcept {
      if (!periodic_) return std::max(p - lo, hi - p);
      double antipode = p + 0.5;
      if (antipode >= 1.0) antipode -= 1.0;
      if (antipode >= lo && antipode <= hi) return 0.5;
      return std::max(std::abs(search_.axis_delta(p, lo)), std::abs(search_.axis_delta(p, hi)));
    }

    std::int64_t bound_axis(double x) const noexcept {
      return std::min(static_cast<std::int64_t>(x * static_cast<double>(bound_cells_)), bound_cells_ - 1);
    }

    // Lowers the cell bounds near the new point p: U_c = min(U_c, far(p, c)).
    // Only cells within `reach_` (≥ every U_c) of p can change.
    void lower_bounds(const double* p) {
      const double side = 1.0 / static_cast<double>(bound_cells_);
      const std::int64_t cells = bound_cells_;
      const double scaled = reach_ * static_cast<double>(cells);
      const std::int64_t reach =
          scaled < static_cast<double>(cells) ? static_cast<std::int64_t>(std::ceil(scaled)) + 1 : cells;
      std::int64_t first[D], last[D], c[D];
      for (unsigned j = 0; j < D; ++j) {
        const std::int64_t centre = bound_axis(p[j]);
        first[j] = centre - reach;
        last[j] = centre + reach;
        if (last[j] - first[j] + 1 >= cells) first[j] = 0, last[j] = cells - 1;
        else if (!periodic_) first[j] = std::max<std::int64_t>(first[j], 0), last[j] = std::min(last[j], cells - 1);
        c[j] = first[j];
      }
      for (;;) {
        std::int64_t index = 0;
        double far2 = 0;
        for (unsigned j = D; j-- > 0;) {
          const std::int64_t wrapped = ((c[j] % cells) + cells) % cells;
          index = index * cells + wrapped;
          const double lo = static_cast<double>(wrapped) * side;
          const double gap = far_gap(lo, lo + side, p[j]);
          far2 += gap * gap;
        }
        // Stored as a float rounded up, so it stays an upper bound.
        const double far = std::sqrt(far2);
        float& bound = bound_[static_cast<std::size_t>(index)];
        if (far < bound) {
          float rounded = static_cast<float>(far);
          if (static_cast<double>(rounded) < far)
            rounded = std::nextafter(rounded, std::numeric_limits<float>::infinity());
          bound = std::min(bound, rounded);
        }
        unsigned j = 0;
        while (j < D && ++c[j] > last[j]) c[j] = first[j], ++j;
        if (j == D) break;
      }
    }

    void insert(const double* x) {
      const auto index = static_cast<std::uint32_t>(points_.size() / D);
      points_.insert(points_.end(), x, x + D);
      search_.insert(index, x);
      lower_bounds(x);
      // Every time the count doubles, tighten reach_ to the largest bound.
      if ((index & (index + 1)) == 0) reach_ = *std::max_element(bound_.begin(), bound_.end());
    }

    // Round i: the best of k·i candidates.
    void choose(std::uint64_t i, double* winner) {
      const std::uint64_t key = round_key(owner_.seed_, i);
      const std::uint64_t count = static_cast<std::uint64_t>(owner_.candidates_) * i;
      double best = -1, best2 = -1;
      std::uint64_t best_index = 0;
      double x[D];
      for (std::uint64_t candidate = 0; candidate < count; ++candidate) {
        coordinates<D>(key, candidate, x);
        std::int64_t index = 0;
        for (unsigned j = D; j-- > 0;) index = index * bound_cells_ + bound_axis(x[j]);
        if (bound_[static_cast<std::size_t>(index)] <= best) continue;
        // Exact nearest distance, unless some point is within `best`.
        double nearest2 = std::numeric_limits<double>::infinity();
        const double radius = bound_[static_cast<std::size_t>(index)];
        search_.visit_near(x, std::isinf(radius) ? 2.0 : radius * (1 + 1e-12), [&](std::uint32_t k) {
          nearest2 = std::min(nearest2, search_.distance_squared(x, points_.data() + std::size_t(k) * D));
          return nearest2 > best2;
        });
        if (nearest2 > best2) {
          best2 = nearest2;
          best = std::sqrt(nearest2);
          best_index = candidate;
        }
      }
      // The winner's 32-bit coordinates, completed with 21 random low bits
      // (never changing its 32-bit cell, so it stays in [0, 1)).
      coordinates<D>(key, best_index, x);
      for (unsigned j = 0; j < D; ++j)
        winner[j] = std::min(x[j] + low_bits(owner_.seed_, i, j), one_minus_epsilon_double);
    }

    // Cells of the bound grid per final point: finer cells make tighter
    // bounds (more rejections by look-up) at the cost of memory and updates.
    static constexpr double cells_per_point = D == 1 ? 64.0 : D == 2 ? 32.0 : D == 3 ? 64.0 : 16.0;

    const BestCandidate& owner_;
    std::uint64_t n_;
    bool periodic_;
    std::int64_t bound_cells_;
    std::vector<float> bound_;  // U_c per cell of the fine grid
    double reach_ = std::numeric_limits<double>::infinity();
    NeighborGrid search_;
    std::vector<double> points_;
  };

  unsigned dimensions_;
  std::uint64_t seed_;
  unsigned candidates_;
  bool periodic_;
};

}  // namespace stratum
