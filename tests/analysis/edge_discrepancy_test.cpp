// Tests of the exact and random-edge discrepancies (edge_discrepancy.hpp)
// against independent oracles: closed-form areas, an exact integer
// orientation, the O(N³) enumeration, a search over directions that never
// relies on the candidate-line argument, and the exact mean over the
// motion-invariant measure of lines by numerical integration.
#include "stratum/analysis/edge_discrepancy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "stratum/analysis/measures.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::analysis {
namespace {

constexpr double pi = 3.14159265358979323846;

std::vector<double> random_points(std::size_t n, std::uint64_t seed) {
  std::vector<double> xs(2 * n);
  for (std::size_t i = 0; i < 2 * n; ++i) xs[i] = uniform01(seed, i);
  return xs;
}
PointView view(const std::vector<double>& xs) { return {xs.data(), xs.size() / 2, 2}; }

TEST(EdgeDiscrepancyArea, ClosedForms) {
  for (double c : {0.0, 0.1, 0.5, 0.93, 1.0}) {
    EXPECT_NEAR(half_plane_area(1, 0, c), c, 1e-15);
    EXPECT_NEAR(half_plane_area(0, 1, c), c, 1e-15);
    EXPECT_NEAR(half_plane_area(-1, 0, -c), 1 - c, 1e-15);
    // {x + y < c} is a right triangle of legs c for c ≤ 1, its complement one of legs 2 − c beyond.
    EXPECT_NEAR(half_plane_area(1, 1, c), c * c / 2, 1e-15);
    EXPECT_NEAR(half_plane_area(1, 1, 2 - c), 1 - c * c / 2, 1e-15);
  }
  EXPECT_EQ(half_plane_area(1, 0, -0.5), 0.0);
  EXPECT_EQ(half_plane_area(1, 0, 1.5), 1.0);
  EXPECT_NEAR(half_plane_area(3, 3, 3), 0.5, 1e-15);  // scaling the normal changes nothing
}

TEST(EdgeDiscrepancyArea, MatchesCellCounting) {
  // Midpoint counting on a 1000² grid: at most the ~2·1000·√2 cells a line crosses are wrong.
  constexpr int m = 1000;
  for (std::uint64_t trial = 0; trial < 6; ++trial) {
    const double angle = 2 * pi * uniform01(7, trial, 0), nx = std::cos(angle), ny = std::sin(angle);
    const double lo = std::min(0.0, nx) + std::min(0.0, ny), hi = std::max(0.0, nx) + std::max(0.0, ny);
    const double c = lo + (hi - lo) * uniform01(7, trial, 1);
    std::int64_t inside = 0;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) inside += nx * (i + 0.5) / m + ny * (j + 0.5) / m < c;
    EXPECT_NEAR(half_plane_area(nx, ny, c), static_cast<double>(inside) / (m * m), 3.0 / m) << "trial " << trial;
  }
}

TEST(EdgeDiscrepancyOrientation, ExactWhereFloatingPointFails) {
  // Points near the line y = x: the naive double determinant gets many signs
  // wrong (Kettner et al. 2008, "Classroom examples of robustness problems in
  // geometric computations"). Oracle: the determinant in exact 128-bit
  // integers, all coordinates being multiples of 2^-53 below 32.
  const double ulp = 0x1.0p-53;
  int disagreements_of_naive = 0;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const double px = 0.5 + i * ulp, py = 0.5 + j * ulp, qx = 12, qy = 12, rx = 24, ry = 24;
      auto scaled = [](double v) { return static_cast<__int128>(std::ldexp(v, 53)); };
      const __int128 det =
          (scaled(qx) - scaled(px)) * (scaled(ry) - scaled(py)) - (scaled(qy) - scaled(py)) * (scaled(rx) - scaled(px));
      const int expected = det > 0 ? 1 : det < 0 ? -1 : 0;
      ASSERT_EQ(orientation(px, py, qx, qy, rx, ry), expected) << i << " " << j;
      const double naive = (qx - px) * (ry - py) - (qy - py) * (rx - px);
      disagreements_of_naive += (naive > 0 ? 1 : naive < 0 ? -1 : 0) != expected;
    }
  EXPECT_GT(disagreements_of_naive, 0);  // the inputs do exercise the exact path
  EXPECT_EQ(orientation(0.1, 0.2, 0.1, 0.2, 0.7, 0.3), 0);
  EXPECT_EQ(orientation(0, 0, 1, 0, 0, 1), 1);
  EXPECT_EQ(orientation(0, 0, 0, 1, 1, 0), -1);
}

TEST(EdgeDiscrepancyExact, SweepMatchesEnumerationOnRandomSets) {
  for (std::size_t n : {2u, 3u, 5u, 17u, 64u})
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
      const auto xs = random_points(n, 100 + seed);
      EXPECT_NEAR(edge_discrepancy(view(xs)).value, edge_discrepancy_naive(view(xs)).value, 1e-12) << n << " " << seed;
    }
}

TEST(EdgeDiscrepancyExact, SweepMatchesEnumerationWithCollinearPoints) {
  // A 5×5 grid of dyadic points (many collinear triples, exact in doubles),
  // the same with repeated points, and points on the square's edges.
  std::vector<double> grid;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) grid.insert(grid.end(), {i / 4.0, j / 8.0 + 0.25});
  EXPECT_NEAR(edge_discrepancy(view(grid)).value, edge_discrepancy_naive(view(grid)).value, 1e-12);
  auto repeated = grid;
  repeated.insert(repeated.end(), grid.begin(), grid.begin() + 10);
  EXPECT_NEAR(edge_discrepancy(view(repeated)).value, edge_discrepancy_naive(view(repeated)).value, 1e-12);
  const std::vector<double> edges{0, 0.5, 0.5, 0, 1, 0.25, 0.75, 1, 0, 0, 1, 1};
  EXPECT_NEAR(edge_discrepancy(view(edges)).value, edge_discrepancy_naive(view(edges)).value, 1e-12);
}

TEST(EdgeDiscrepancyExact, SearchNeverExceedsAndComesClose) {
  // The search evaluates real lines only, so it is a lower bound; with
  // refinement to 10⁻⁹·π/angles rad it must find the supremum to ~1e-9
  // (the area is 1-Lipschitz in the direction), allowing 1e-7.
  for (std::size_t n : {4u, 8u, 16u})
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
      const auto xs = random_points(n, 200 + seed);
      const double exact = edge_discrepancy(view(xs)).value;
      const double search = edge_discrepancy_search(view(xs), 2048).value;
      EXPECT_LE(search, exact + 1e-12) << n << " " << seed;
      EXPECT_GE(search, exact - 1e-7) << n << " " << seed;
    }
}

TEST(EdgeDiscrepancyExact, KnownConfigurations) {
  // Every line through the centre halves the square: with all points there, D = 1 − 1/2.
  EXPECT_NEAR(edge_discrepancy(view({0.5, 0.5, 0.5, 0.5, 0.5, 0.5})).value, 0.5, 1e-15);
  // All points at a corner, or on an edge: a sliver containing them has area → 0.
  EXPECT_NEAR(edge_discrepancy(view({0, 0, 0, 0})).value, 1.0, 1e-15);
  EXPECT_NEAR(edge_discrepancy(view({0.5, 0, 0.5, 0})).value, 1.0, 1e-15);
  // Two points (1/4, 1/2), (3/4, 1/2): the vertical line x = 1/4 gives max(1/2 − 1/4, 1/4 − 0) = 1/4 and
  // the horizontal line y = 1/2 gives 1 − 1/2; nothing beats a half-plane of area 1/2 holding both.
  EXPECT_NEAR(edge_discrepancy(view({0.25, 0.5, 0.75, 0.5})).value, 0.5, 1e-15);
}

TEST(EdgeDiscrepancyExact, DeterministicAcrossThreads) {
  const auto xs = random_points(300, 5);
  const auto one = edge_discrepancy(view(xs), 1), four = edge_discrepancy(view(xs), 4);
  EXPECT_EQ(one.value, four.value);
  EXPECT_EQ(one.line.angle, four.line.angle);
  // The reported line attains the value (up to the area's rounding).
  EXPECT_NEAR(line_discrepancy(view(xs), one.line), one.value, 1.0 / 300 + 1e-9);
}

/// E[D] over the motion-invariant measure of lines hitting the square,
/// ∫∫ D dp dθ / ∫∫ dp dθ, by the midpoint rule in θ and, for each θ,
/// 5-point Gauss–Legendre on the pieces where the count is fixed and the
/// area is one quadratic (split again where the difference changes sign),
/// which is exact on each piece.
double exact_mean_line_discrepancy(const PointView& points, int directions, double* measure) {
  static const double node[5] = {0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const double weight[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                   0.2369268850561891};
  double total = 0, lines = 0;
  const double n = static_cast<double>(points.n);
  for (int k = 0; k < directions; ++k) {
    const double angle = pi * (k + 0.5) / directions, nx = std::cos(angle), ny = std::sin(angle);
    std::vector<double> breaks{0, nx, ny, nx + ny};
    std::vector<double> projections;
    for (std::size_t i = 0; i < points.n; ++i) projections.push_back(nx * points(i, 0) + ny * points(i, 1));
    breaks.insert(breaks.end(), projections.begin(), projections.end());
    std::sort(breaks.begin(), breaks.end());
    double integral = 0;
    for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
      const double lo = breaks[b], hi = breaks[b + 1];
      if (hi <= lo) continue;
      const double mid = 0.5 * (lo + hi);
      const double fraction = static_cast<double>(std::count_if(projections.begin(), projections.end(),
                                                                [&](double t) { return t < mid; })) /
                              n;
      auto difference = [&](double p) { return fraction - half_plane_area(nx, ny, p); };
      std::vector<double> cuts{lo, hi};
      if ((difference(lo) > 0) != (difference(hi) > 0)) {  // the area is increasing: one root
        double a = lo, c = hi;
        for (int iteration = 0; iteration < 200 && c - a > 1e-17; ++iteration) {
          const double m = 0.5 * (a + c);
          ((difference(m) > 0) == (difference(lo) > 0) ? a : c) = m;
        }
        cuts = {lo, 0.5 * (a + c), hi};
      }
      for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
        const double half = 0.5 * (cuts[c + 1] - cuts[c]), centre = 0.5 * (cuts[c + 1] + cuts[c]);
        for (int g = 0; g < 5; ++g) integral += half * weight[g] * std::abs(difference(centre + half * node[g]));
      }
    }
    total += integral;
    lines += breaks.back() - breaks.front();
  }
  *measure = lines * pi / directions;
  return total / lines;
}

TEST(RandomEdgeDiscrepancy, MeanConvergesToTheExactMean) {
  const auto xs = random_points(7, 31);
  double measure = 0;
  const double exact_mean = exact_mean_line_discrepancy(view(xs), 5000, &measure);
  EXPECT_NEAR(measure, 4.0, 1e-6);  // Crofton: the lines hitting a convex set have measure = its perimeter
  double previous_error = 1;
  for (std::size_t lines : {1000u, 400000u}) {
    const auto estimate = random_edge_discrepancy(view(xs), lines, 11);
    // The mean of L i.i.d. values: |error| ≤ z·sd/√L, z = 3.89 (two-sided α = 1e-4 per check, 2 checks).
    const double sd = std::sqrt(std::max(0.0, estimate.rms * estimate.rms - estimate.mean * estimate.mean));
    EXPECT_NEAR(estimate.mean, exact_mean, 3.89 * sd / std::sqrt(static_cast<double>(lines))) << lines;
    EXPECT_LE(estimate.max, edge_discrepancy(view(xs)).value + 1e-12);
    previous_error = std::abs(estimate.mean - exact_mean);
  }
  EXPECT_LT(previous_error, 2e-3);
}

TEST(RandomEdgeDiscrepancy, DeterministicAndBounded) {
  const auto xs = random_points(256, 9);
  const auto one = random_edge_discrepancy(view(xs), 5000, 3, 1), four = random_edge_discrepancy(view(xs), 5000, 3, 4);
  EXPECT_EQ(one.rms, four.rms);
  EXPECT_EQ(one.mean, four.mean);
  EXPECT_EQ(one.max, four.max);
  EXPECT_GE(one.rms, one.mean);
  EXPECT_LE(one.max, edge_discrepancy(view(xs)).value + 1e-12);
  EXPECT_NE(random_edge_discrepancy(view(xs), 5000, 4).rms, one.rms);  // the seed matters
  // The lines' directions are uniform and their offsets fall inside the square's projection.
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const EdgeLine line = random_isotropic_line(3, i);
    ASSERT_GE(line.angle, 0);
    ASSERT_LT(line.angle, pi);
    ASSERT_GT(half_plane_area(std::cos(line.angle), std::sin(line.angle), line.offset + 1e-12), 0);
    ASSERT_LT(half_plane_area(std::cos(line.angle), std::sin(line.angle), line.offset - 1e-12), 1);
  }
}

std::string error_of(const std::string& name, const std::vector<double>& xs, std::size_t d,
                     std::map<std::string, std::string> params = {}) {
  try {
    compute_measure(name, {xs.data(), xs.size() / d, d}, {std::move(params), 1});
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(EdgeDiscrepancyMeasures, RegistryFacesAndBadInput) {
  const auto xs = random_points(50, 4);
  const auto exact = compute_measure("edge", view(xs), {});
  EXPECT_EQ(exact.kind, "exact");
  EXPECT_EQ(exact.value, edge_discrepancy(view(xs)).value);
  const auto random = compute_measure("edge-random", view(xs), {{{"lines", "2000"}, {"seed", "5"}}, 2});
  EXPECT_EQ(random.kind, "estimate");
  const auto direct = random_edge_discrepancy(view(xs), 2000, 5);
  EXPECT_EQ(random.value, direct.rms);
  EXPECT_EQ(random.extras.at("mean"), direct.mean);
  EXPECT_EQ(random.extras.at("max"), direct.max);
  EXPECT_EQ(compute_measure("edge-random", view(xs), {}).extras.at("lines"), 10000);
  EXPECT_NE(error_of("edge", random_points(30, 1), 3).find("invalid d = 3"), std::string::npos);
  EXPECT_NE(error_of("edge-random", xs, 2, {{"lines", "0"}}).find("invalid lines = 0"), std::string::npos);
  EXPECT_NE(error_of("edge-random", xs, 2, {{"lines", "-3"}}).find("invalid lines = -3"), std::string::npos);
  EXPECT_NE(error_of("edge-random", xs, 2, {{"lines", "1e3"}}).find("invalid lines = 1e3"), std::string::npos);
  EXPECT_NE(error_of("edge-random", xs, 2, {{"seed", "x"}}).find("invalid seed = x"), std::string::npos);
  EXPECT_NE(
      error_of("edge", xs, 2, {{"lines", "10"}}).find("invalid measure-param = lines=10: edge takes no parameters"),
      std::string::npos);
  EXPECT_NE(error_of("edge", {0.5, 0.5}, 2).find("invalid n = 1"), std::string::npos);
  EXPECT_THROW(random_edge_discrepancy(view(xs), 0, 0), invalid_argument);
  EXPECT_THROW(edge_discrepancy({xs.data(), 25, 4}), invalid_argument);
}

}  // namespace
}  // namespace stratum::analysis
