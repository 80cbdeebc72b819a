#pragma once
/// Spatial statistics of point sets: the minimum distance, the normalized
/// Poisson-disk radius and the pair correlation function (LECTURE.md §8:
/// a blue-noise pattern keeps its points apart; Lagae & Dutré 2008, "A
/// comparison of methods for generating Poisson disk distributions";
/// Öztireli & Gross 2012, "Analysis and synthesis of point distributions
/// based on pair correlation").
#include <cstddef>
#include <vector>

#include "stratum/analysis/measures.hpp"  // PointView

namespace stratum::analysis {

struct MinimumDistance {
  double distance = 0;                ///< smallest distance between two distinct points (indices)
  std::size_t first = 0, second = 0;  ///< a closest pair, first < second
};

/// Smallest pairwise distance, Euclidean or toroidal (the unit cube with
/// opposite faces identified, each axis difference wrapped to [−½, ½]).
/// d ≤ 8: a uniform grid of about N cells (NeighborGrid); each point searches
/// only the cells within the best distance found so far, so the cost is
/// O(N) for sets without huge empty regions. d > 8: all pairs, O(N² d).
/// Throws invalid_argument for n < 2 or coordinates outside [0, 1].
MinimumDistance minimum_distance(const PointView& points, bool toroidal);

/// All-pairs reference, O(N² d): for tests.
MinimumDistance minimum_distance_reference(const PointView& points, bool toroidal);

/// Largest possible minimum distance of N points in the unit d-cube, taken
/// from the densest lattice sphere packing: N balls of radius a/2 fill the
/// volume fraction Δ_d, so a = 2 (Δ_d / (N V_d))^{1/d}, V_d the unit-ball
/// volume. Δ_1 = 1, Δ_2 = π/√12 (hexagonal; then a = sqrt(2/(√3 N)) as in
/// Lagae & Dutré 2008), Δ_3 = π/√18 (fcc, optimal by Hales 2005), Δ_4 =
/// π²/16 (D4), Δ_5 = π²/(15√2) (D5), Δ_6 = π³/(48√3) (E6), Δ_7 = π³/105
/// (E7), Δ_8 = π⁴/384 (E8, optimal by Viazovska 2017); Conway & Sloane,
/// "Sphere packings, lattices and groups", Table 1.2. For d = 4..7 these are
/// the densest lattice packings (the densest known). d > 8 throws.
double densest_packing_distance(std::size_t n, std::size_t d);

/// Normalized Poisson-disk radius ρ = d_min / densest_packing_distance(N, d)
/// (Lagae & Dutré 2008 recommend ρ ∈ [0.65, 0.85] for good blue noise).
double poisson_radius(const PointView& points, bool toroidal);

/// The pair correlation function g(r) at `radii`, estimated as in Öztireli &
/// Gross (2012, Eq. 4) with a Gaussian kernel k_σ of standard deviation σ,
/// cut at 4σ, and distances toroidal so that no edge correction is needed
/// (valid for r + 4σ ≤ ½):
///   g(r) = Σ_{i≠j} k_σ(r − |x_i − x_j|) / (N (N−1) · ∫_{t≥0} k_σ(r − t) S_{d−1} t^{d−1} dt).
/// The denominator is what a uniform random (binomial) set gives, so
/// E g(r) = 1 for white noise at every radius; it tends to the sphere's area
/// S_{d−1} r^{d−1} (2πr in 2D) of Eq. 4 for r ≫ σ, whose use at r of a few σ
/// overestimates g (2.15 for white noise at r = σ/4 in 2D). Blue noise has
/// g ≈ 0 below its Poisson radius. Pairs farther than max(radii) + 4σ are
/// skipped (a neighbour grid finds the others).
struct PairCorrelation {
  std::vector<double> radius, g;
  double sigma = 0;
};
PairCorrelation pair_correlation(const PointView& points, const std::vector<double>& radii, double sigma,
                                 unsigned threads);

/// Default radii and σ for N points in d dimensions: `count` radii evenly
/// spaced in (0, 2.5 · densest_packing_distance], σ = 0.1 of that distance
/// (capped so that r + 4σ ≤ ½).
PairCorrelation default_pair_correlation_grid(std::size_t n, std::size_t d, std::size_t count);

}  // namespace stratum::analysis
