#pragma once
/// PMJ02BN: the progressive multi-jittered (0,2) sequence with blue-noise
/// properties of Christensen, Kensler and Kilpatrick (2018, "Progressive
/// multi-jittered sample sequences", Sec. 6): each new point goes into the
/// square stratum the (0,2) construction assigns it, and within it the best
/// of k random candidates is kept, "best" meaning farthest (toroidally) from
/// the points already placed, as in Mitchell's best-candidate sampling.
///
/// Construction, on the stateless PMJ02 of sequences/pmj.hpp (Helmer,
/// Christensen, Kensler 2021): point p ≥ 1 with m = msb(p) copies, in each
/// coordinate, the first m binary digits of the earlier point j = (p − 2^m) ⊕
/// x_m (x_m: Pmj02::xor_value) and flips its digit m + 1; its digits m + 2 …
/// are free. Every choice of free digits keeps every 2^k prefix a
/// (0,k,2)-net (the elementary intervals of a 2^(m+1) prefix are fixed by the
/// first m + 1 digits, and later points copy whatever digits their earlier
/// points have), so the free digits are where the candidates differ: the
/// candidate region is the 2^-(m+1) × 2^-(m+1) square of p's strata. With k =
/// 1 the point is a plain stochastic PMJ02 point. Point 0 is uniform.
///
/// Blue noise in a different space from sobol-bn's: PMJ02BN spreads the
/// points of one sample set (within a pixel, say) apart from each other,
/// so its own periodogram is low at low frequencies; sobol-bn, pmj02-bn and
/// zsobol leave each pixel's set an ordinary randomized net and arrange the
/// pixels' sets so that the *error* across pixels is blue.
///
/// Not index-addressable: point p needs the points before it (n points cost
/// about k·n nearest-neighbour searches in a grid). Deterministic from (seed,
/// n, k): candidates are counter-based hashes of (seed, p, candidate).
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "stratum/patterns/neighbor_grid.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/util/bits.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

class Pmj02Bn {
 public:
  static constexpr unsigned default_candidates = 10;
  static constexpr unsigned max_candidates = 1000;
  /// Largest n: indices are 32-bit in the neighbour grid.
  static constexpr std::uint64_t max_points = std::uint64_t{1} << 31;

  explicit Pmj02Bn(std::uint64_t seed = 0, unsigned candidates = default_candidates)
      : seed_(seed), candidates_(candidates) {
    require(candidates >= 1 && candidates <= max_candidates, "candidates", candidates, "must be in [1, 1000]");
  }

  unsigned candidates() const noexcept { return candidates_; }

  /// Replay hook (for tests): the random bits of coordinate c of candidate k
  /// for point p; the candidate keeps its fixed digits and takes these in the free ones.
  static std::uint64_t candidate_bits(std::uint64_t seed, std::uint64_t p, unsigned k, unsigned c) noexcept {
    return hash64(hash64(seed, tag_candidate, p, k), c);
  }

  /// The first n points as 64-bit binary fractions, (x, y) per point.
  std::vector<std::uint64_t> generate_bits(std::uint64_t n) const {
    require(n >= 1 && n <= max_points, "n", n, "pmj02bn takes 1 to 2^31 points");
    std::vector<std::uint64_t> bits(2 * n);
    std::vector<double> xy(2 * n);
    // About one point per cell at the end: a query near radius 1/√p visits few cells.
    const auto cells = static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    NeighborGrid grid(2, cells, true);
    for (std::uint64_t p = 0; p < n; ++p) {
      std::uint64_t top[2] = {0, 0}, free = ~std::uint64_t{0};
      if (p != 0) {
        const unsigned m = 63u - static_cast<unsigned>(std::countl_zero(p));
        const std::uint64_t kept = ~std::uint64_t{0} << (63 - m);  // digits 1 … m + 1
        for (unsigned c = 0; c < 2; ++c) {
          const std::uint64_t j = (p ^ (std::uint64_t{1} << m)) ^ Pmj02::xor_value(c, m);
          top[c] = (bits[2 * j + c] & kept) ^ (std::uint64_t{1} << (63 - m));
        }
        free = ~kept;
      }
      std::uint64_t best[2] = {0, 0};
      double best_distance = -1;
      for (unsigned k = 0; k < (p == 0 ? 1u : candidates_); ++k) {
        const std::uint64_t key = hash64(seed_, tag_candidate, p, k);  // candidate_bits' first link, shared
        const std::uint64_t candidate[2] = {top[0] | (hash64(key, 0) & free), top[1] | (hash64(key, 1) & free)};
        const double x[2] = {bits_to_double(candidate[0]), bits_to_double(candidate[1])};
        const double distance = p == 0 ? 0 : nearest_squared(grid, xy, x, p, best_distance);
        if (distance > best_distance) best_distance = distance, best[0] = candidate[0], best[1] = candidate[1];
      }
      bits[2 * p] = best[0], bits[2 * p + 1] = best[1];
      xy[2 * p] = bits_to_double(best[0]), xy[2 * p + 1] = bits_to_double(best[1]);
      grid.insert(static_cast<std::uint32_t>(p), &xy[2 * p]);
    }
    return bits;
  }

  /// The first n points, row-major (x, y).
  void generate(std::uint64_t n, double* out) const {
    const std::vector<std::uint64_t> bits = generate_bits(n);
    for (std::size_t i = 0; i < bits.size(); ++i) out[i] = bits_to_double(bits[i]);
  }

 private:
  static constexpr std::uint64_t tag_candidate = 0x706d'6a62'6e63ULL;  // "pmjbnc"
  /// Up to this many placed points a candidate's nearest is found without the grid.
  static constexpr std::uint64_t brute_points = 256;

  /// The squared toroidal distance from x to its nearest of the `placed`
  /// points, or any value ≤ `beat` once it is known not to exceed it (the
  /// candidate cannot win then).
  static double nearest_squared(const NeighborGrid& grid, const std::vector<double>& xy, const double* x,
                                std::uint64_t placed, double beat) {
    // Every point: fewer distances than the grid's cells a query visits.
    if (placed <= brute_points) return NeighborGrid::nearest_squared(x, xy.data(), placed, 2, true);
    double radius = 1.5 / std::sqrt(static_cast<double>(placed));
    for (;;) {
      double nearest = std::numeric_limits<double>::infinity();
      const double radius2 = radius * radius;
      grid.visit_near(x, radius, [&](std::uint32_t i) {
        nearest = std::min(nearest, grid.distance_squared(x, &xy[2 * std::size_t{i}]));
        return !(nearest <= beat);  // stop: this candidate loses
      });
      if (nearest <= radius2 || nearest <= beat) return nearest;
      if (radius >= 1) return nearest;  // every point was visited (the torus' diameter is √2/2)
      radius *= 2;
    }
  }

  std::uint64_t seed_;
  unsigned candidates_;
};

}  // namespace stratum
