// ns per coordinate of every registry sampler (bulk, through the registry,
// as the CLI and Python get them), against a memory-write baseline that
// allocates and fills a buffer of the same size, in the same run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>

#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace {

constexpr unsigned kDims = 4;

void memory_write_baseline(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    std::unique_ptr<double[]> buffer(new double[n * kDims]);
    std::fill_n(buffer.get(), n * kDims, 0.5);
    benchmark::DoNotOptimize(buffer.get());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_coord"] =
      benchmark::Counter(static_cast<double>(n * kDims), benchmark::Counter::kIsIterationInvariantRate |
                                                             benchmark::Counter::kInvert);
}

void registry_sampler(benchmark::State& state, std::string name, std::string randomize, unsigned threads) {
  stratum::SamplerRequest request;
  request.n = static_cast<std::uint64_t>(state.range(0));
  const auto& info = stratum::find_sampler(name);
  request.d = std::clamp(kDims, info.min_dim, info.max_dim);
  request.randomize = randomize;
  request.threads = threads;
  request.seed = 1;
  for (auto _ : state) {
    auto points = stratum::generate_points(name, request);
    benchmark::DoNotOptimize(points.data.get());
  }
  state.counters["ns_per_coord"] = benchmark::Counter(
      static_cast<double>(*request.n * request.d),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// A count every sampler accepts (a perfect square, fourth power and power of
// two), large enough to leave the caches.
constexpr std::int64_t kCount = 1 << 16;

int register_all() {
  benchmark::RegisterBenchmark("baseline/memory-write", memory_write_baseline)->Arg(kCount)->Arg(1 << 20);
  for (const auto& sampler : stratum::samplers()) {
    for (const auto& randomize : sampler.randomizers) {
      stratum::SamplerRequest probe;
      probe.n = kCount;
      probe.d = std::clamp(kDims, sampler.min_dim, sampler.max_dim);
      probe.randomize = randomize;
      try {
        stratum::validate_request(sampler, probe);
      } catch (const stratum::invalid_argument&) {
        continue;
      }
      benchmark::RegisterBenchmark(("registry/" + sampler.name + "/" + randomize).c_str(), registry_sampler,
                                   sampler.name, randomize, 1u)
          ->Arg(kCount)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  return 0;
}
const int registered = register_all();

}  // namespace

BENCHMARK_MAIN();
