#pragma once
/// The exact variance of jittered sampling on an edge (§4). An n×n jittered
/// grid puts one uniform point in each of its N = n² cells, independently;
/// for f = 1[half-plane], f(X_i) is Bernoulli(a_i) with a_i the fraction of
/// cell i inside the half-plane, so the estimate (1/N) Σ f(X_i) has variance
///   Var = (1/N²) Σ_i a_i (1 − a_i),
/// in which only the cells the edge cuts (0 < a_i < 1) count: O(n) of them,
/// each at most 1/4, hence Var = O(n / n⁴) = O(N^-1.5) (the stratified
/// variance formula of Cochran 1977, "Sampling Techniques", §5.3, with one
/// point per stratum; Mitchell 1996, "Consequences of stratified sampling in
/// graphics"). Exact, for every n and every edge: no asymptotics.
#include <array>
#include <cstdint>

namespace stratum::report {

/// The region (x − point)·normal < 0.
struct HalfPlane {
  std::array<double, 2> point{}, normal{};
};

/// The half-plane of the registry's edge-random integrand for `seed` (its
/// description: a point uniform in the square from uniform01(seed, 0) and
/// (seed, 1), a normal at angle 2π·uniform01(seed, 2)).
HalfPlane random_edge_half_plane(std::uint64_t seed);

/// Area of the box [x0, x1) × [y0, y1) inside the half-plane (the box
/// clipped by the line, Sutherland & Hodgman 1974, then the shoelace formula).
double half_plane_area(const HalfPlane& plane, double x0, double y0, double x1, double y1);

/// Σ a_i(1 − a_i) / N² over the n×n cells of the unit square.
double jittered_edge_variance(const HalfPlane& plane, std::uint64_t n);

/// The number of the n×n cells the edge cuts (0 < a_i < 1).
std::uint64_t cut_cells(const HalfPlane& plane, std::uint64_t n);

}  // namespace stratum::report
