// Star discrepancy: every exact method against an independent brute force
// that evaluates the definition sup_x |A([0,x))/N − V(x)| on the grid of
// point coordinates (and 1), at each corner and just above it (the closed
// limit); closed forms (1D, one point); fast vs slow; thread-count invariance;
// the DEM cell decomposition against the critical-box enumeration, to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "stratum/analysis/star_discrepancy.hpp"

namespace {

using stratum::analysis::PointView;
namespace sa = stratum::analysis;

std::vector<double> random_points(std::size_t n, std::size_t d, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x(n * d);
  for (auto& v : x) v = u(rng);
  return x;
}

/// Points on the grid k/8 (k = 0..8): many ties, zeros and ones.
std::vector<double> grid_points(std::size_t n, std::size_t d, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> k(0, 8);
  std::vector<double> x(n * d);
  for (auto& v : x) v = k(rng) / 8.0;
  return x;
}

/// The definition, evaluated at every corner z of the critical grid and at
/// z + ε (each coordinate capped at 1), which approaches the closed box
/// [0, z] from above. Error ≤ d·ε from the nudge.
double brute_force(const std::vector<double>& x, std::size_t n, std::size_t d) {
  constexpr double eps = 1e-11;
  std::vector<std::vector<double>> values(d);
  for (std::size_t j = 0; j < d; ++j) {
    for (std::size_t i = 0; i < n; ++i) values[j].push_back(x[i * d + j]);
    values[j].push_back(1.0);
    std::sort(values[j].begin(), values[j].end());
    values[j].erase(std::unique(values[j].begin(), values[j].end()), values[j].end());
  }
  auto local = [&](const std::vector<double>& z) {
    std::size_t inside = 0;
    for (std::size_t i = 0; i < n; ++i) {
      bool in = true;
      for (std::size_t j = 0; j < d; ++j) in = in && x[i * d + j] < z[j];
      inside += in;
    }
    double volume = 1;
    for (double c : z) volume *= c;
    return std::abs(static_cast<double>(inside) / static_cast<double>(n) - volume);
  };
  std::vector<std::size_t> index(d, 0);
  std::vector<double> z(d), up(d);
  double best = 0;
  while (true) {
    for (std::size_t j = 0; j < d; ++j) {
      z[j] = values[j][index[j]];
      up[j] = std::min(1.0, z[j] + eps);
    }
    best = std::max({best, local(z), local(up)});
    std::size_t j = 0;
    while (j < d && ++index[j] == values[j].size()) index[j++] = 0;
    if (j == d) break;
  }
  return best;
}

constexpr double kBruteTolerance = 1e-9;  // covers the d·ε nudge of the brute force

TEST(StarDiscrepancy, OneDimensionClosedFormMatchesBruteForce) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const std::size_t n = 1 + seed % 17;
    for (const auto& x : {random_points(n, 1, seed), grid_points(n, 1, seed)}) {
      const double got = sa::star_discrepancy_1d(PointView{x.data(), n, 1});
      EXPECT_NEAR(got, brute_force(x, n, 1), kBruteTolerance) << "n = " << n << " seed = " << seed;
      EXPECT_GE(got, 0.5 / static_cast<double>(n) - 1e-15);  // D* ≥ 1/(2N) for any 1D set
    }
  }
}

TEST(StarDiscrepancy, OneDimensionEvenGridIsOptimal) {
  // x_i = (2i−1)/(2N) attains the minimum 1/(2N) (Niederreiter 1992, Cor. 2.7).
  for (std::size_t n : {1u, 2u, 7u, 64u}) {
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = (2.0 * i + 1.0) / (2.0 * n);
    EXPECT_NEAR(sa::star_discrepancy_1d(PointView{x.data(), n, 1}), 0.5 / n, 1e-15);
  }
}

TEST(StarDiscrepancy, SweepMatchesBruteForceOnRandomPoints) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const std::size_t n = 1 + (seed * 7) % 45;
    const auto x = random_points(n, 2, seed);
    EXPECT_NEAR(sa::star_discrepancy_2d(PointView{x.data(), n, 2}), brute_force(x, n, 2), kBruteTolerance)
        << "n = " << n << " seed = " << seed;
  }
}

TEST(StarDiscrepancy, SweepMatchesBruteForceWithTiesZerosAndOnes) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const std::size_t n = 1 + (seed * 5) % 30;
    const auto x = grid_points(n, 2, seed);
    EXPECT_NEAR(sa::star_discrepancy_2d(PointView{x.data(), n, 2}), brute_force(x, n, 2), kBruteTolerance)
        << "n = " << n << " seed = " << seed;
  }
}

TEST(StarDiscrepancy, SinglePointClosedForm) {
  // One point (a, b): the empty boxes [0,a)×[0,1) and [0,1)×[0,b) give a and b,
  // the box [0,a]×[0,b] gives 1 − ab; nothing does worse.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double smallest = 1;
  for (int trial = 0; trial < 200; ++trial) {
    const double p[2] = {u(rng), u(rng)};
    const double got = sa::star_discrepancy_2d(PointView{p, 1, 2});
    EXPECT_NEAR(got, std::max({p[0], p[1], 1 - p[0] * p[1]}), 1e-15);
    smallest = std::min(smallest, got);
  }
  // The optimum over one point is (√5 − 1)/2 at a = b = (√5 − 1)/2 (White 1977).
  const double golden = (std::sqrt(5.0) - 1) / 2;
  EXPECT_GE(smallest, golden - 1e-15);
  const double best[2] = {golden, golden};
  EXPECT_NEAR(sa::star_discrepancy_2d(PointView{best, 1, 2}), golden, 1e-15);
}

TEST(StarDiscrepancy, NestedSweepMatchesBruteForceInThreeAndFourDimensions) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    for (std::size_t d : {3u, 4u}) {
      const std::size_t n = d == 3 ? 2 + seed % 13 : 2 + seed % 7;
      for (const auto& x : {random_points(n, d, seed), grid_points(n, d, seed + 100)}) {
        EXPECT_NEAR(sa::star_discrepancy_grid(PointView{x.data(), n, d}, 1), brute_force(x, n, d), kBruteTolerance)
            << "n = " << n << " d = " << d << " seed = " << seed;
      }
    }
  }
}

TEST(StarDiscrepancy, ExactDispatchAgreesWithEachMethod) {
  const auto x1 = random_points(50, 1, 3);
  EXPECT_EQ(sa::star_discrepancy_exact(PointView{x1.data(), 50, 1}),
            sa::star_discrepancy_1d(PointView{x1.data(), 50, 1}));
  const auto x2 = random_points(50, 2, 3);
  EXPECT_EQ(sa::star_discrepancy_exact(PointView{x2.data(), 50, 2}),
            sa::star_discrepancy_2d(PointView{x2.data(), 50, 2}));
  EXPECT_EQ(sa::star_discrepancy_grid(PointView{x2.data(), 50, 2}),
            sa::star_discrepancy_2d(PointView{x2.data(), 50, 2}));
  const auto x3 = random_points(20, 3, 3);
  EXPECT_EQ(sa::star_discrepancy_exact(PointView{x3.data(), 20, 3}),
            sa::star_discrepancy_grid(PointView{x3.data(), 20, 3}));
}

TEST(StarDiscrepancy, OneDimensionClosedFormAgreesWithTheSweep) {
  // Lift 1D points x to (x, 1/2): boxes [0,a)×[0,1) reproduce every 1D box,
  // so D*_2 ≥ D*_1.
  const std::size_t n = 50;
  const auto x1 = random_points(n, 1, 3);
  std::vector<double> half, zero;
  for (double v : x1) {
    half.insert(half.end(), {v, 0.5});
    zero.insert(zero.end(), {v, 0.0});
  }
  const double d1 = sa::star_discrepancy_1d(PointView{x1.data(), n, 1});
  EXPECT_GE(sa::star_discrepancy_2d(PointView{half.data(), n, 2}), d1 - 1e-15);
  // On (x, 0) the thin box [0,1)×[0,ε) holds every point: D*_2 = 1.
  EXPECT_NEAR(sa::star_discrepancy_2d(PointView{zero.data(), n, 2}), 1.0, 1e-15);
}

TEST(StarDiscrepancy, SweepMatchesBruteForceAtHundredsOfPoints) {
  for (std::size_t n : {120u, 257u}) {
    const auto x = random_points(n, 2, 11 + n);
    EXPECT_NEAR(sa::star_discrepancy_2d(PointView{x.data(), n, 2}), brute_force(x, n, 2), kBruteTolerance);
  }
}

TEST(StarDiscrepancy, ThreadCountDoesNotChangeTheResult) {
  const std::size_t n = 20000;
  const auto x = random_points(n, 2, 5);
  const double one = sa::star_discrepancy_2d(PointView{x.data(), n, 2}, 1);
  EXPECT_EQ(one, sa::star_discrepancy_2d(PointView{x.data(), n, 2}, 2));
  EXPECT_EQ(one, sa::star_discrepancy_2d(PointView{x.data(), n, 2}, 7));
  const auto y = random_points(300, 3, 6);
  const double three = sa::star_discrepancy_grid(PointView{y.data(), 300, 3}, 1);
  EXPECT_EQ(three, sa::star_discrepancy_grid(PointView{y.data(), 300, 3}, 3));
}

TEST(StarDiscrepancy, RandomSetsAreAtLeastHalfOverN) {
  // D*_d ≥ D*_1 of the first coordinates (boxes with the other sides 1, no
  // coordinate equal to 1) ≥ 1/(2N).
  for (std::size_t d : {2u, 3u}) {
    const std::size_t n = 64;
    const auto x = random_points(n, d, 40 + d);
    std::vector<double> first;
    for (std::size_t i = 0; i < n; ++i) first.push_back(x[i * d]);
    const double full = sa::star_discrepancy_exact(PointView{x.data(), n, d});
    EXPECT_GE(full, sa::star_discrepancy_1d(PointView{first.data(), n, 1}) - 1e-15);
    EXPECT_GE(full, 0.5 / n);
  }
}

/// Structured sets with ties: repeated rows, coordinates exactly 0 and 1, a
/// lattice-like set (every point on a shared grid line in some coordinate).
std::vector<double> tied_points(std::size_t n, std::size_t d, std::uint64_t seed, int kind) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x = random_points(n, d, seed);
  switch (kind) {
    case 0:  // duplicated rows
      for (std::size_t i = 1; i < n; i += 2)
        for (std::size_t j = 0; j < d; ++j) x[i * d + j] = x[(i - 1) * d + j];
      break;
    case 1:  // about a third of the coordinates at 0, a tenth at 1
      for (auto& v : x) {
        const double r = u(rng);
        v = r < 0.33 ? 0.0 : r > 0.9 ? 1.0 : v;
      }
      break;
    case 2:  // a rank-1 lattice: (i/n, {i·g_j/n}), ties only through the grid
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < d; ++j)
          x[i * d + j] = static_cast<double>((i * (1 + 2 * j + seed % 5)) % n) / static_cast<double>(n);
      break;
    default:  // one coordinate shared by everyone
      for (std::size_t i = 0; i < n; ++i) x[i * d + seed % d] = 0.5;
  }
  return x;
}

TEST(StarDiscrepancyDem, SameDoubleAsTheEnumeration) {
  std::size_t checked = 0;
  for (std::size_t d : {3u, 4u, 5u}) {
    const std::size_t max_n = d == 3 ? 40 : d == 4 ? 18 : 10;
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
      const std::size_t n = 1 + (seed * 7) % max_n;
      std::vector<std::vector<double>> sets{random_points(n, d, seed), grid_points(n, d, seed + 500)};
      for (int kind = 0; kind < 4; ++kind) sets.push_back(tied_points(n, d, seed + 900, kind));
      for (const auto& x : sets) {
        const PointView view{x.data(), n, d};
        const double oracle = sa::star_discrepancy_grid(view, 1);
        ASSERT_EQ(sa::star_discrepancy_dem(view, 1), oracle) << "n = " << n << " d = " << d << " seed = " << seed;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 3u * 30u * 6u);
}

TEST(StarDiscrepancyDem, MatchesTheDefinitionByBruteForce) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    for (std::size_t d : {3u, 4u}) {
      const std::size_t n = d == 3 ? 3 + seed % 12 : 2 + seed % 7;
      for (const auto& x : {random_points(n, d, seed + 40), grid_points(n, d, seed + 140)}) {
        EXPECT_NEAR(sa::star_discrepancy_dem(PointView{x.data(), n, d}), brute_force(x, n, d), kBruteTolerance)
            << "n = " << n << " d = " << d << " seed = " << seed;
      }
    }
  }
}

TEST(StarDiscrepancyDem, BlockSizeAndThreadsDoNotChangeTheValue) {
  // block_scale sets how many counted points fall between cuts (so the number
  // and shape of the cells), never the value.
  for (std::size_t d : {3u, 4u}) {
    const std::size_t n = d == 3 ? 300 : 60;
    const auto x = random_points(n, d, 77 + d);
    const PointView view{x.data(), n, d};
    const double oracle = sa::star_discrepancy_grid(view, 2);
    for (double scale : {0.05, 0.5, 1.0, 4.0, 100.0}) EXPECT_EQ(sa::star_discrepancy_dem(view, 1, scale), oracle);
    EXPECT_EQ(sa::star_discrepancy_dem(view, 2), oracle);
    EXPECT_EQ(sa::star_discrepancy_dem(view, 5), oracle);
  }
}

TEST(StarDiscrepancyDem, TwoDimensionsAgreeWithTheSweep) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const std::size_t n = 1 + seed * 13;
    for (const auto& x : {random_points(n, 2, seed), grid_points(n, 2, seed)}) {
      EXPECT_EQ(sa::star_discrepancy_dem(PointView{x.data(), n, 2}),
                sa::star_discrepancy_2d(PointView{x.data(), n, 2}));
    }
  }
}

TEST(StarDiscrepancyDem, PointsAtOneCountOnlyInN) {
  // Every point has a coordinate 1: no box holds any, so D* = 1 (the box [0,1)^d).
  std::vector<double> x{1.0, 0.2, 0.3, 0.5, 1.0, 0.1, 0.7, 0.7, 1.0};
  EXPECT_EQ(sa::star_discrepancy_dem(PointView{x.data(), 3, 3}), 1.0);
  EXPECT_EQ(sa::star_discrepancy_grid(PointView{x.data(), 3, 3}), 1.0);
}

}  // namespace
