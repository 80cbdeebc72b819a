// Exact 2D star discrepancy, time vs N (2^10 … 2^16): the O(N²) vectorized
// sweep (1 and 2 threads) against a peer in the same run — the textbook exact
// method with a Fenwick tree over y-ranks (for each corner abscissa, one
// O(log N) count per candidate y: O(N² log N)), run up to N = 2^13. The peer
// benchmark also times the sweep on the same points and reports
// `speedup` = peer CPU time / sweep CPU time (thread CPU clocks, so the ratio
// holds on a loaded machine), and fails if the two values differ.
// d ≥ 3: the DEM cell decomposition (O(N^{1+d/2})) against the critical-box
// enumeration (O(N^d)) in the same run, d = 3 and 4: `dem_vs_grid` times DEM
// as the benchmark and the enumeration once on the same points (thread CPU
// clocks), reports `speedup` = enumeration / DEM, and fails if the two values
// differ by a bit. Larger N: DEM alone. Also Thiémard bounds in 3D.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <random>
#include <vector>

#include "stratum/analysis/star_discrepancy.hpp"

namespace {

namespace sa = stratum::analysis;

/// CPU seconds of the calling thread: a ratio of two of them does not depend
/// on how loaded the machine is.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::vector<double> uniform_points(std::size_t n, std::size_t d) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x(n * d);
  for (auto& v : x) v = u(rng);
  return x;
}

/// O(N² log N) exact 2D star discrepancy (points in [0,1)²): sweep x, keep a
/// Fenwick tree of the y-ranks to the left, and evaluate both one-sided
/// terms at every (point x or 1, point y or 1) corner with one prefix count each.
double fenwick_star_2d(const std::vector<double>& x, std::size_t n) {
  std::vector<std::size_t> by_x(n), by_y(n);
  for (std::size_t i = 0; i < n; ++i) by_x[i] = by_y[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](auto a, auto b) { return x[2 * a] < x[2 * b]; });
  std::sort(by_y.begin(), by_y.end(), [&](auto a, auto b) { return x[2 * a + 1] < x[2 * b + 1]; });
  std::vector<double> ys(n);
  for (std::size_t r = 0; r < n; ++r) ys[r] = x[2 * by_y[r] + 1];
  std::vector<std::size_t> rank(n);
  for (std::size_t r = 0; r < n; ++r) rank[by_y[r]] = r;
  std::vector<int> tree(n + 1, 0);
  auto add = [&](std::size_t r) {
    for (std::size_t i = r + 1; i <= n; i += i & (~i + 1)) ++tree[i];
  };
  auto prefix = [&](std::size_t r) {  // count of ranks < r
    int s = 0;
    for (std::size_t i = r; i > 0; i -= i & (~i + 1)) s += tree[i];
    return s;
  };
  const double inv_n = 1.0 / static_cast<double>(n);
  double best = 0;
  auto evaluate = [&](double a, bool closed) {
    for (std::size_t r = 0; r <= n; ++r) {
      const double b = r < n ? ys[r] : 1.0;
      if (closed && r < n) {
        const std::size_t last = static_cast<std::size_t>(std::upper_bound(ys.begin(), ys.end(), b) - ys.begin());
        best = std::max(best, prefix(last) * inv_n - a * b);
      } else if (!closed) {
        const std::size_t first =
            r < n ? static_cast<std::size_t>(std::lower_bound(ys.begin(), ys.end(), b) - ys.begin()) : n;
        best = std::max(best, a * b - prefix(first) * inv_n);
      }
    }
  };
  std::size_t i = 0;
  while (i < n) {
    const double a = x[2 * by_x[i]];
    evaluate(a, false);
    std::size_t j = i;
    while (j < n && x[2 * by_x[j]] == a) add(rank[by_x[j++]]);
    evaluate(a, true);
    i = j;
  }
  evaluate(1.0, false);
  return best;
}

void star_exact_2d(benchmark::State& state, unsigned threads) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto x = uniform_points(n, 2);
  for (auto _ : state) benchmark::DoNotOptimize(sa::star_discrepancy_2d(sa::PointView{x.data(), n, 2}, threads));
  state.counters["N"] = static_cast<double>(n);
}

void star_fenwick_peer(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto x = uniform_points(n, 2);
  double peer = 0, peer_seconds = 0;
  std::size_t runs = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    peer = fenwick_star_2d(x, n);
    peer_seconds += thread_seconds() - t0;
    ++runs;
    benchmark::DoNotOptimize(peer);
  }
  double sweep = 0, sweep_seconds = 1e300;
  for (int rep = 0; rep < 3; ++rep) {
    const double t0 = thread_seconds();
    sweep = sa::star_discrepancy_2d(sa::PointView{x.data(), n, 2}, 1);
    sweep_seconds = std::min(sweep_seconds, thread_seconds() - t0);
  }
  if (std::abs(peer - sweep) > 1e-12) state.SkipWithError("the peer and the sweep disagree");
  state.counters["speedup"] = peer_seconds / static_cast<double>(runs) / sweep_seconds;
}

void star_dem_vs_grid(benchmark::State& state, std::size_t d) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto x = uniform_points(n, d);
  const sa::PointView view{x.data(), n, d};
  double dem = 0, dem_seconds = 0;
  std::size_t runs = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    benchmark::DoNotOptimize(dem = sa::star_discrepancy_dem(view, 1));
    dem_seconds += thread_seconds() - t0;
    ++runs;
  }
  const double t0 = thread_seconds();
  const double grid = sa::star_discrepancy_grid(view, 1);
  const double grid_seconds = thread_seconds() - t0;
  if (grid != dem) state.SkipWithError("DEM and the enumeration disagree");
  state.counters["N"] = static_cast<double>(n);
  state.counters["dem_s"] = dem_seconds / static_cast<double>(runs);
  state.counters["grid_s"] = grid_seconds;
  state.counters["speedup"] = grid_seconds / (dem_seconds / static_cast<double>(runs));
}

/// The first n Halton points (bases 2, 3, 5, …, index 1 first): a small D*,
/// so fewer DEM cells are pruned than for random points — the inputs the
/// size limits (star_dem_max_points) were set on.
std::vector<double> halton_points(std::size_t n, std::size_t d) {
  constexpr unsigned bases[] = {2, 3, 5, 7, 11, 13, 17, 19};
  std::vector<double> x(n * d);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < d; ++j) {
      double r = 0, f = 1.0 / bases[j];
      for (std::size_t k = i + 1; k > 0; k /= bases[j], f /= bases[j]) r += f * static_cast<double>(k % bases[j]);
      x[i * d + j] = r;
    }
  return x;
}

void star_dem(benchmark::State& state, std::size_t d, bool halton) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto x = halton ? halton_points(n, d) : uniform_points(n, d);
  const unsigned threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(sa::star_discrepancy_dem(sa::PointView{x.data(), n, d}, threads));
  state.counters["N"] = static_cast<double>(n);
}

void star_bounds_3d(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto x = uniform_points(n, 3);
  sa::StarDiscrepancyBounds b;
  for (auto _ : state) benchmark::DoNotOptimize(b = sa::star_discrepancy_bounds(sa::PointView{x.data(), n, 3}, 0.05));
  state.counters["boxes"] = static_cast<double>(b.boxes);
  state.counters["gap"] = b.upper - b.lower;
}

}  // namespace

BENCHMARK_CAPTURE(star_exact_2d, threads1, 1u)
    ->RangeMultiplier(2)
    ->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(star_exact_2d, threads2, 2u)
    ->RangeMultiplier(4)
    ->Range(1 << 12, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(star_fenwick_peer)->RangeMultiplier(2)->Range(1 << 10, 1 << 13)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(star_dem_vs_grid, d3, 3)->RangeMultiplier(2)->Range(1 << 6, 1 << 11)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(star_dem_vs_grid, d4, 4)->RangeMultiplier(2)->Range(1 << 4, 1 << 8)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(star_dem, d3_random, 3, false)
    ->RangeMultiplier(2)
    ->Range(1 << 12, 1 << 13)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(star_dem, d4_random, 4, false)
    ->RangeMultiplier(2)
    ->Range(1 << 9, 1 << 10)
    ->Unit(benchmark::kMillisecond);
// At the size limits (star_dem_max_points: 14000 for d = 3, 2200 for d = 4).
BENCHMARK_CAPTURE(star_dem, d3_halton, 3, true)->Arg(4096)->Arg(14000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(star_dem, d4_halton, 4, true)->Arg(1024)->Arg(2200)->Unit(benchmark::kMillisecond);
BENCHMARK(star_bounds_3d)->Arg(1 << 10)->Arg(1 << 12)->Unit(benchmark::kMillisecond);
