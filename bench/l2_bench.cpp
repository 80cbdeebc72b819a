// The L2 discrepancies (l2_discrepancy.hpp): the O(d N²) pair kernels
// (ns per pair i < j, single thread and all threads) and the O(N log N)
// L2-star algorithms for d = 2 and 3 against Warnock's formula on the same
// points, so the ratio is read off one run.
#include <benchmark/benchmark.h>

#include <random>
#include <thread>
#include <vector>

#include "stratum/analysis/l2_discrepancy.hpp"

namespace {

using stratum::analysis::L2Algorithm;
using stratum::analysis::L2Kind;

std::vector<double> uniform(std::size_t n, std::size_t d) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x(n * d);
  for (auto& v : x) v = u(rng);
  return x;
}

void l2(benchmark::State& state, L2Kind kind, L2Algorithm algorithm, std::size_t d, unsigned threads) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<double> x = uniform(n, d);
  stratum::analysis::L2Options options;
  options.algorithm = algorithm;
  options.threads = threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : threads;
  for (auto _ : state)
    benchmark::DoNotOptimize(stratum::analysis::l2_discrepancy_squared(kind, {x.data(), n, d}, options));
  const double pairs = 0.5 * static_cast<double>(n) * static_cast<double>(n);
  state.counters["ns_per_pair"] =
      benchmark::Counter(pairs, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK_CAPTURE(l2, star_warnock_d2, L2Kind::star, L2Algorithm::pairwise, 2, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, star_fast_d2, L2Kind::star, L2Algorithm::fast, 2, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, star_warnock_d3, L2Kind::star, L2Algorithm::pairwise, 3, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, star_fast_d3, L2Kind::star, L2Algorithm::fast, 3, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, star_warnock_d5, L2Kind::star, L2Algorithm::pairwise, 5, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, centered_d2, L2Kind::centered, L2Algorithm::pairwise, 2, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, centered_d5, L2Kind::centered, L2Algorithm::pairwise, 5, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, wrap_around_d5, L2Kind::wrap_around, L2Algorithm::pairwise, 5, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, mixture_d5, L2Kind::mixture, L2Algorithm::pairwise, 5, 1)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(l2, centered_d5_all_threads, L2Kind::centered, L2Algorithm::pairwise, 5, 0)
    ->RangeMultiplier(4)
    ->Range(1 << 12, 1 << 16)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
