#pragma once
/// Maximal Poisson-disk patterns: points in [0,1)^d no two closer than r,
/// and so many that no point of the cube is farther than r from all of them
/// (the set is *maximal*: no further point fits). Blue noise with a
/// guaranteed gap, recommended with jittered sampling by Mitchell (1992).
///
/// Two phases, both sequential and driven by counter-based randomness, so a
/// seed gives one result on any thread count:
///  1. Bridson 2007, "Fast Poisson disk sampling in arbitrary dimensions":
///     grow the set from a random seed point; pick a random active point,
///     try k candidates uniform (by volume) in the annulus [r, 2r) around it,
///     keep the first one at distance ≥ r from every sample, retire the
///     active point after k failures. O(N) with Bridson's background grid of
///     cell side ≤ r/√d (poisson_disk_grid.hpp).
///  2. Annulus sampling leaves small gaps, so the set is not yet maximal.
///     Completion after Ebeida et al. 2012, "A simple algorithm for maximal
///     Poisson-disk sampling in high dimensions": a grid cell holding a
///     sample is covered (its diameter is ≤ r); every empty cell is a box to
///     check. A box is *covered* when one disk contains it (its farthest
///     corner is within r of a sample), or two (or, in 2D, three) disks do:
///     exact tests of every candidate for the box's farthest point from the
///     sites (corners, bisector-edge crossings, circumcentre). An uncovered
///     box whose centre is free gets a sample (a uniform dart in the box, or
///     the centre when the dart misses), which covers the whole cell; if
///     instead a corner is free, the gap lies mostly outside the box and
///     gets a sample near that corner; otherwise the box is split into 2^d
///     children, depth first. Every test is exact, so when no box is left
///     every point of the cube lies within r of a sample: the set is
///     maximal, up to boxes still uncovered after 40 halvings (side 2^-40 of
///     a cell: gaps thinner than rounding). Unlike Ebeida et al., cells are
///     refined one at a time, which bounds memory; the completion's darts
///     are then not unbiased in their sense (neither are Bridson's).
///
/// d is limited to 4: proving coverage needs boxes of diameter well below r,
/// whose number per sample grows like 2^(d·levels); Ebeida et al. call their
/// method practical up to 5D, and our 5D/6D trials took seconds to minutes
/// for a thousand points.
///
/// Exactly n points (`subset`, `with_count`): a maximal set is thinned by
/// weighted sample elimination (Yuksel 2015, sample_elimination.hpp), which
/// keeps the minimum distance and removes the most crowded points first.
/// Without a radius, r is chosen from n by the measured packing density of
/// maximal sets, a few percent more points than n are generated, and the
/// surplus is eliminated.
///
/// `periodic`: distances on the torus (opposite faces identified); the
/// pattern then tiles space. The patterns allocate (they are finite
/// generators); construction validates, and generation throws only when a
/// requested n exceeds what the maximal set holds.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "stratum/patterns/poisson_disk_grid.hpp"
#include "stratum/patterns/sample_elimination.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

class PoissonDisk {
 public:
  static constexpr unsigned max_dimensions = 4;
  static constexpr unsigned default_candidates = 30;
  static constexpr unsigned max_candidates = 100000;
  /// Halvings of a grid cell before an uncovered sliver is given up.
  static constexpr unsigned max_refinement = 40;

  PoissonDisk(unsigned dimensions, double radius, std::uint64_t seed, unsigned candidates = default_candidates,
              bool periodic = false)
      : dimensions_(dimensions), radius_(radius), seed_(seed), candidates_(candidates), periodic_(periodic) {
    require(dimensions >= 1 && dimensions <= max_dimensions, "d", dimensions,
            "Poisson-disk sampling supports d = 1 to 4");
    require(radius > 0 && radius <= 1, "radius", radius, "must be in (0, 1]");
    require(candidates >= 1 && candidates <= max_candidates, "candidates", candidates, "must be in [1, 100000]");
    if (grid_bytes(dimensions, radius) > 0x1.0p40)  // the message built only on failure: a set per pixel and dimension
      throw invalid_argument(
          "radius", to_message_string(radius),
          "too small for d = " + std::to_string(dimensions) + ": the background grid would exceed 2^40 bytes");
  }

  unsigned dimensions() const noexcept { return dimensions_; }
  double radius() const noexcept { return radius_; }
  std::uint64_t seed() const noexcept { return seed_; }
  unsigned candidates() const noexcept { return candidates_; }
  bool periodic() const noexcept { return periodic_; }

  /// Bytes of the background grid for (d, r): cells of side ≤ r/√d, padded.
  static double grid_bytes(unsigned dimensions, double radius) noexcept {
    switch (dimensions) {
      case 1:
        return poisson_detail::CompactPoissonDisk<1>::grid_bytes(radius);
      case 2:
        return poisson_detail::CompactPoissonDisk<2>::grid_bytes(radius);
      case 3:
        return poisson_detail::CompactPoissonDisk<3>::grid_bytes(radius);
      default:
        return poisson_detail::CompactPoissonDisk<4>::grid_bytes(radius);
    }
  }

  /// Bytes a maximal set at radius r needs while it is made (grid, points
  /// with a margin over the estimate, bookkeeping): what a caller checks
  /// against its memory before asking.
  static double working_bytes(unsigned dimensions, double radius, bool periodic) noexcept {
    return grid_bytes(dimensions, radius) +
           1.5 * estimated_count(dimensions, radius, periodic) * (dimensions + 1) * sizeof(double);
  }

  /// Packing density φ of the maximal sets this generator makes on the
  /// torus, measured as n · V_d (r/2)^d over 1..5 seeds of 1300 to 27000
  /// points (d = 1..4; for comparison, random sequential addition jams at
  /// 0.748, 0.547, 0.384, 0.255: Torquato, Uche, Stillinger 2006).
  static double maximal_packing_density(unsigned dimensions) noexcept {
    constexpr double density[5] = {0, 0.667, 0.5405, 0.389, 0.2722};
    return density[std::min(dimensions, 4u)];
  }

  /// Expected number of points of a maximal set: φ / (V_d (r/2)^d) on the
  /// torus; in the cube, points crowd the faces, which adds a layer: a
  /// measured factor (1 + c r)^d, c ≈ 0.6 to 0.7.
  static double estimated_count(unsigned dimensions, double radius, bool periodic) noexcept {
    return estimated_count(dimensions, unit_ball_volume(dimensions), radius, periodic);
  }

  /// Upper bound on the size of any set with minimum distance ≥ r: balls of
  /// radius r/2 around the points are disjoint and lie in the cube grown by
  /// r/2 (or on the torus), so their number is at most the densest packing
  /// density times that volume over one ball's volume.
  static double packing_bound(unsigned dimensions, double radius, bool periodic) noexcept {
    const double volume = periodic ? 1.0 : std::pow(1.0 + radius, dimensions);
    // The densest-packing density is an upper bound only asymptotically; a
    // factor 2 covers finite boxes, where boundary effects allow more.
    return 2.0 * densest_packing_density(dimensions) * volume /
               (unit_ball_volume(dimensions) * std::pow(radius / 2, static_cast<double>(dimensions))) +
           1.0;
  }

  /// The radius whose maximal sets have about `count` points (inverse of
  /// estimated_count), at most 1.
  static double radius_for_count(double count, unsigned dimensions, bool periodic) noexcept {
    // A renderer asks for the same count set after set: each thread keeps its last answer.
    thread_local struct {
      double count = -1, radius = 0;
      unsigned dimensions = 0;
      bool periodic = false;
    } last;
    if (last.count == count && last.dimensions == dimensions && last.periodic == periodic) return last.radius;
    last = {count, search_radius(count, dimensions, periodic), dimensions, periodic};
    return last.radius;
  }

  /// radius_for_count without its cache: a bisection in log scale of estimated_count.
  static double search_radius(double count, unsigned dimensions, bool periodic) noexcept {
    const double ball = unit_ball_volume(dimensions);  // once, not per step (a gamma function)
    double lo = 1e-12, hi = 1.0;
    if (estimated_count(dimensions, ball, hi, periodic) >= count) return hi;
    // Bisection in log scale; lo always has estimate >= count and hi < count, so once the mean rounds to
    // either end every later step leaves both as they are (after about 60 of the 200): stop there.
    for (int iteration = 0; iteration < 200; ++iteration) {
      const double mid = std::sqrt(lo * hi);
      if (mid == lo || mid == hi) break;
      if (estimated_count(dimensions, ball, mid, periodic) >= count) lo = mid;
      else hi = mid;
    }
    return lo;
  }

  /// A maximal set, row-major (d coordinates per point), in generation
  /// order: Bridson's points first, then the completion's.
  template <class Real = double>
  std::vector<Real> maximal_set() const {
    return convert<Real>(generate_maximal());
  }

  /// Exactly n points: the maximal set thinned by sample elimination. Throws
  /// invalid_argument naming n when the maximal set has fewer than n points.
  template <class Real = double>
  std::vector<Real> subset(std::uint64_t n) const {
    std::vector<double> points = generate_maximal();
    const std::uint64_t found = points.size() / dimensions_;
    if (n < 1 || n > found)  // the message built only on failure, as above
      throw invalid_argument("n", to_message_string(n),
                             "a maximal Poisson-disk set with radius " + to_message_string(radius_) + " in d = " +
                                 std::to_string(dimensions_) + " has " + std::to_string(found) + " points for seed " +
                                 std::to_string(seed_) + "; ask for at most that many or give a smaller radius");
    return convert<Real>(thin(points, n, dimensions_, periodic_));
  }

  /// Exactly n points without a radius: r is chosen so that a maximal set
  /// has a few percent more than n points (shrunk and retried with a derived
  /// seed when it falls short), then thinned to n by sample elimination.
  template <class Real = double>
  static std::vector<Real> with_count(std::uint64_t n, unsigned dimensions, std::uint64_t seed,
                                      unsigned candidates = default_candidates, bool periodic = false) {
    require(n >= 1, "n", n, "must be at least 1");
    const double surplus = 1.03 + 2.0 / std::sqrt(static_cast<double>(n));
    double radius = radius_for_count(static_cast<double>(n) * surplus, dimensions, periodic);
    for (std::uint64_t attempt = 0;; ++attempt) {
      const PoissonDisk disk(dimensions, radius, attempt == 0 ? seed : hash64(seed, attempt), candidates, periodic);
      std::vector<double> points = disk.generate_maximal();
      const std::uint64_t found = points.size() / dimensions;
      if (found >= n) return convert<Real>(thin(points, n, dimensions, periodic));
      const double ratio = static_cast<double>(found) / (static_cast<double>(n) * surplus);
      radius *= 0.97 * std::pow(ratio, 1.0 / dimensions);
    }
  }

 private:
  /// estimated_count with the unit ball's volume given.
  static double estimated_count(unsigned dimensions, double ball, double radius, bool periodic) noexcept {
    const double bulk =
        maximal_packing_density(dimensions) / (ball * std::pow(radius / 2, static_cast<double>(dimensions)));
    const double boundary = periodic ? 1.0 : std::pow(1.0 + boundary_layer(dimensions) * radius, dimensions);
    return std::max(1.0, bulk * boundary);
  }

  static double boundary_layer(unsigned dimensions) noexcept {
    constexpr double layer[5] = {0, 0.65, 0.6, 0.69, 0.665};
    return layer[std::min(dimensions, 4u)];
  }

  template <class Real>
  static std::vector<Real> convert(std::vector<double>&& points) {
    if constexpr (sizeof(Real) == sizeof(double)) {
      return std::move(points);
    } else {
      std::vector<Real> out(points.size());
      for (std::size_t i = 0; i < points.size(); ++i) out[i] = to_unit<Real>(points[i]);
      return out;
    }
  }

  static std::vector<double> thin(const std::vector<double>& points, std::uint64_t n, unsigned d, bool periodic) {
    const std::size_t count = points.size() / d;
    const std::vector<std::uint32_t> kept = eliminate_samples(points.data(), count, d, n, periodic);
    std::vector<double> out;
    out.reserve(kept.size() * d);
    for (std::uint32_t i : kept)
      out.insert(out.end(), points.begin() + std::ptrdiff_t(i) * d, points.begin() + std::ptrdiff_t(i + 1) * d);
    return out;
  }

  std::vector<double> generate_maximal() const {
    switch (dimensions_) {
      case 1:
        return poisson_detail::CompactPoissonDisk<1>(radius_, seed_, candidates_, periodic_, max_refinement).generate();
      case 2:
        return poisson_detail::CompactPoissonDisk<2>(radius_, seed_, candidates_, periodic_, max_refinement).generate();
      case 3:
        return poisson_detail::CompactPoissonDisk<3>(radius_, seed_, candidates_, periodic_, max_refinement).generate();
      default:
        return poisson_detail::CompactPoissonDisk<4>(radius_, seed_, candidates_, periodic_, max_refinement).generate();
    }
  }

  unsigned dimensions_;
  double radius_;
  std::uint64_t seed_;
  unsigned candidates_;
  bool periodic_;
};

}  // namespace stratum
