#include "stratum/analysis/geometry.hpp"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "stratum/patterns/neighbor_grid.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::analysis {
namespace {

constexpr double pi = std::numbers::pi;

double squared_distance(const PointView& points, std::size_t a, std::size_t b, bool toroidal) {
  double sum = 0;
  for (std::size_t j = 0; j < points.d; ++j) {
    double delta = std::abs(points(a, j) - points(b, j));
    if (toroidal && delta > 0.5) delta = 1.0 - delta;
    sum += delta * delta;
  }
  return sum;
}

/// Volume of the unit ball in d dimensions, π^{d/2} / Γ(d/2 + 1).
double unit_ball_volume(std::size_t d) {
  const double half = 0.5 * static_cast<double>(d);
  return std::pow(pi, half) / std::tgamma(half + 1.0);
}

/// Area of the unit sphere in d dimensions, d · V_d.
double unit_sphere_area(std::size_t d) { return static_cast<double>(d) * unit_ball_volume(d); }

/// What a uniform random (binomial) set adds to the kernel sum at radius r, per
/// ordered pair: ∫ k_σ(r − t) S_{d−1} t^{d−1} dt over the distances t ≥ 0 that
/// the truncated kernel (|r − t| < 4σ) sees. On the torus with r + 4σ ≤ ½ the
/// distance of two independent uniform points has density S_{d−1} t^{d−1}, so
/// dividing by this makes E g(r) = 1 exactly for white noise at every r, where
/// the shell S_{d−1} r^{d−1} alone overcounts when r is a few σ (the kernel's
/// mass below t = 0 is lost and t^{d−1} curves under it). With u = (r − t)/σ:
/// ∫ φ(u) (r − σu)^{d−1} du over [−4, min(4, r/σ)], from the moments
/// M_k = ∫ u^k φ(u) du of the standard normal on that interval
/// (M_k = (k−1) M_{k−2} − [u^{k−1} φ(u)]).
double expected_kernel_shell(double r, double sigma, std::size_t d) {
  const double a = -4, b = std::min(4.0, r / sigma);
  const auto density = [](double u) { return std::exp(-0.5 * u * u) / std::sqrt(2 * pi); };
  const auto power = [](double u, std::size_t k) { return k == 0 ? 1.0 : std::pow(u, static_cast<double>(k)); };
  std::vector<double> moment(d);
  for (std::size_t k = 0; k < d; ++k) {
    if (k == 0) moment[k] = 0.5 * (std::erf(b / std::sqrt(2.0)) - std::erf(a / std::sqrt(2.0)));
    else if (k == 1) moment[k] = density(a) - density(b);
    else
      moment[k] =
          static_cast<double>(k - 1) * moment[k - 2] - (power(b, k - 1) * density(b) - power(a, k - 1) * density(a));
  }
  // (r − σu)^{d−1} = Σ_k C(d−1, k) r^{d−1−k} (−σ)^k u^k
  double sum = 0, binomial = 1;
  for (std::size_t k = 0; k < d; ++k) {
    sum += binomial * power(r, d - 1 - k) * power(-sigma, k) * moment[k];
    binomial = binomial * static_cast<double>(d - 1 - k) / static_cast<double>(k + 1);
  }
  return unit_sphere_area(d) * sum;
}

NeighborGrid grid_for(const PointView& points, std::uint64_t cells_per_axis, bool periodic) {
  NeighborGrid grid(static_cast<unsigned>(points.d), std::max<std::uint64_t>(1, cells_per_axis), periodic);
  for (std::size_t i = 0; i < points.n; ++i) grid.insert(static_cast<std::uint32_t>(i), &points.data[i * points.d]);
  return grid;
}

}  // namespace

MinimumDistance minimum_distance_reference(const PointView& points, bool toroidal) {
  check_unit_cube(points);
  MinimumDistance best{std::numeric_limits<double>::infinity(), 0, 1};
  for (std::size_t a = 0; a < points.n; ++a)
    for (std::size_t b = a + 1; b < points.n; ++b) {
      const double d2 = squared_distance(points, a, b, toroidal);
      if (d2 < best.distance) best = {d2, a, b};
    }
  best.distance = std::sqrt(best.distance);
  return best;
}

MinimumDistance minimum_distance(const PointView& points, bool toroidal) {
  check_unit_cube(points);
  require(points.n < (std::size_t{1} << 32) - 1, "n", points.n, "at most 2^32 − 2 points");
  if (points.d > NeighborGrid::max_dimensions) return minimum_distance_reference(points, toroidal);
  // About one point per cell: N^{1/d} cells per axis.
  const auto per_axis = static_cast<std::uint64_t>(
      std::floor(std::pow(static_cast<double>(points.n), 1.0 / static_cast<double>(points.d)) + 1e-9));
  const NeighborGrid grid = grid_for(points, per_axis, toroidal);
  const double diameter = std::sqrt(static_cast<double>(points.d)) * (toroidal ? 0.5 : 1.0);
  double best2 = diameter * diameter * 1.0001;  // above every pair's distance
  MinimumDistance best{0, 0, 1};
  for (std::size_t i = 0; i < points.n && best2 > 0; ++i) {
    const double* x = &points.data[i * points.d];
    grid.visit_near(x, std::sqrt(best2), [&](std::uint32_t j) {
      if (j != i) {
        const double d2 = squared_distance(points, i, j, toroidal);
        if (d2 < best2) {
          best2 = d2;
          best.first = std::min<std::size_t>(i, j);
          best.second = std::max<std::size_t>(i, j);
        }
      }
      return true;
    });
  }
  best.distance = std::sqrt(best2);
  return best;
}

double densest_packing_distance(std::size_t n, std::size_t d) {
  require(d >= 1 && d <= 8, "d", d, "densest packings are tabulated for d = 1..8");
  require(n >= 1, "n", n, "must be at least 1");
  const double density[9] = {0,
                             1.0,
                             pi / std::sqrt(12.0),
                             pi / std::sqrt(18.0),
                             pi * pi / 16.0,
                             pi * pi / (15.0 * std::sqrt(2.0)),
                             pi * pi * pi / (48.0 * std::sqrt(3.0)),
                             pi * pi * pi / 105.0,
                             pi * pi * pi * pi / 384.0};
  return 2.0 * std::pow(density[d] / (static_cast<double>(n) * unit_ball_volume(d)), 1.0 / static_cast<double>(d));
}

double poisson_radius(const PointView& points, bool toroidal) {
  require(points.d >= 1 && points.d <= 8, "d", points.d, "the Poisson radius is defined here for d = 1..8");
  return minimum_distance(points, toroidal).distance / densest_packing_distance(points.n, points.d);
}

PairCorrelation default_pair_correlation_grid(std::size_t n, std::size_t d, std::size_t count) {
  require(count >= 1, "radii", count, "at least 1");
  const double spacing = densest_packing_distance(n, d);
  PairCorrelation grid;
  grid.sigma = 0.1 * spacing;
  double largest = 2.5 * spacing;
  if (largest + 4 * grid.sigma > 0.5) {  // few points: keep within half the torus
    largest = 0.5 / (2.5 + 0.4) * 2.5;
    grid.sigma = 0.1 * largest / 2.5;
  }
  for (std::size_t k = 1; k <= count; ++k)
    grid.radius.push_back(largest * static_cast<double>(k) / static_cast<double>(count));
  return grid;
}

PairCorrelation pair_correlation(const PointView& points, const std::vector<double>& radii, double sigma,
                                 unsigned threads) {
  check_unit_cube(points);
  require(points.d <= NeighborGrid::max_dimensions, "d", points.d, "the pair correlation is computed for d = 1..8");
  require(std::isfinite(sigma) && sigma > 0, "sigma", sigma, "must be positive and finite");
  require(!radii.empty(), "radii", "[]", "at least one radius");
  double largest = 0;
  for (double r : radii) {
    require(std::isfinite(r) && r > 0, "radius", r, "radii must be positive and finite");
    largest = std::max(largest, r);
  }
  const double cutoff = largest + 4 * sigma;
  require(cutoff <= 0.5, "radius", largest,
          "r + 4 sigma must be at most 1/2 (toroidal distances); sigma = " + to_message_string(sigma));
  // Cells at least `cutoff` wide, and not many more cells than points.
  std::uint64_t per_axis = static_cast<std::uint64_t>(std::floor(1.0 / cutoff));
  const double limit = std::pow(4.0 * static_cast<double>(points.n), 1.0 / static_cast<double>(points.d));
  per_axis = std::max<std::uint64_t>(1, std::min<std::uint64_t>(per_axis, static_cast<std::uint64_t>(limit)));
  const NeighborGrid grid = grid_for(points, per_axis, true);

  const std::size_t block = 256;
  const std::size_t blocks = (points.n + block - 1) / block;
  std::vector<std::vector<double>> partial(blocks, std::vector<double>(radii.size(), 0.0));
  const double normal = 1.0 / (std::sqrt(2 * pi) * sigma);
  auto run_block = [&](std::size_t b) {
    check_interrupt();
    std::vector<double>& sums = partial[b];
    for (std::size_t i = b * block; i < std::min(points.n, (b + 1) * block); ++i)
      grid.visit_near(&points.data[i * points.d], cutoff, [&](std::uint32_t j) {
        if (j == i) return true;
        const double distance = std::sqrt(squared_distance(points, i, j, true));
        if (distance >= cutoff) return true;
        for (std::size_t k = 0; k < radii.size(); ++k) {
          const double u = (radii[k] - distance) / sigma;
          if (std::abs(u) < 4) sums[k] += normal * std::exp(-0.5 * u * u);
        }
        return true;
      });
  };
  oneapi::tbb::task_arena arena(threads == 0 ? oneapi::tbb::task_arena::automatic
                                             : static_cast<int>(std::max(1u, threads)));
  arena.execute([&] { oneapi::tbb::parallel_for(std::size_t{0}, blocks, run_block); });

  PairCorrelation result;
  result.sigma = sigma;
  result.radius = radii;
  const double n = static_cast<double>(points.n);
  for (std::size_t k = 0; k < radii.size(); ++k) {
    double sum = 0;
    for (const auto& block_sums : partial) sum += block_sums[k];  // fixed order: deterministic
    result.g.push_back(sum / (n * (n - 1) * expected_kernel_shell(radii[k], sigma, points.d)));
  }
  return result;
}

}  // namespace stratum::analysis
