// ns per coordinate of every registry sampler (bulk, through the registry,
// as the CLI and Python get them), against a memory-write baseline that
// allocates and fills a buffer of the same size, in the same run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>
#include <string>

#include <boost/random/sobol.hpp>

#include "stratum/randomizers/base2.hpp"
#include "stratum/randomizers/owen_base_b.hpp"
#include "stratum/registry.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/error.hpp"
#include "support.hpp"

namespace {

constexpr unsigned kDims = 4;

// The baseline allocates its buffer exactly as the registry does (same
// allocator, same huge-page advice) and writes a constant into it.
void memory_write_baseline(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    stratum::PointSet buffer = stratum::registry_support::allocate_points(n, kDims);
    std::fill_n(buffer.data.get(), n * kDims, 0.5);
    benchmark::DoNotOptimize(buffer.data.get());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_coord"] = benchmark::Counter(
      static_cast<double>(n * kDims), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
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
  state.counters["ns_per_coord"] =
      benchmark::Counter(static_cast<double>(*request.n * request.d),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Random access (seed, index, dim) as a renderer calls it: Sobol' with
// hash-based Owen scrambling, indices below 2^16, 16 dimensions. "bound"
// binds the scrambler to a dimension once per dimension (pbrt-v4 style).
void sobol_random_access(benchmark::State& state, bool bound) {
  const unsigned dims = 16;
  const stratum::Sobol sobol(dims);
  const stratum::HashOwenScrambler owen(7);
  std::uint64_t index = 0;
  double sum = 0;
  for (auto _ : state) {
    // A local per row: `sum` lives in memory (DoNotOptimize takes its
    // address), and a store-to-load round trip per coordinate costs ~3 ns.
    double row = 0;
    for (unsigned j = 0; j < dims; ++j) {
      if (bound) row += sobol.sample(index, j, owen.dimension(j));
      else row += sobol.sample(index, j, owen);
    }
    sum += row;
    index = (index + 1) & 0xffff;
  }
  benchmark::DoNotOptimize(sum);
  state.counters["ns_per_coord"] =
      benchmark::Counter(dims, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Random access to exact base-b Owen scrambling (faure, halton:owen draw
// through it): one coordinate in base b at indices below 2^k in a scrambled
// order (k·odd mod 2^k), as a renderer's per-pixel sets (k = 4) or a long
// sequence (k = 16) read it; random-access/sobol-owen-hash is the peer.
void owen_base_b_random_access(benchmark::State& state) {
  const auto base = static_cast<std::uint32_t>(state.range(0));
  const std::uint64_t mask = (std::uint64_t{1} << state.range(1)) - 1;
  const stratum::BaseBOwenScrambler owen(7, {base});
  std::uint64_t k = 0;
  double sum = 0;
  for (auto _ : state) {
    sum += owen.sample((k * 0x9e3779b97f4a7c15ULL) & mask, 0);
    ++k;
  }
  benchmark::DoNotOptimize(sum);
  state.counters["ns_per_coord"] =
      benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Peer: Boost.Random's Sobol' engine (Gray-code, unscrambled) writing the same
// buffer as the registry does, converted to double.
void boost_sobol_bulk(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    boost::random::sobol engine(kDims);
    stratum::PointSet buffer = stratum::registry_support::allocate_points(n, kDims);
    double* out = buffer.data.get();
    for (std::size_t k = 0; k < n * kDims; ++k) out[k] = static_cast<double>(engine()) * 0x1.0p-32;
    benchmark::DoNotOptimize(out);
  }
  state.counters["ns_per_coord"] = benchmark::Counter(
      static_cast<double>(n * kDims), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// The Poisson-disk target: the maximal set at radius 0.01 in the
// unit square (about 7000 points), through the registry, per set and per
// coordinate. bench/scipy_compare.py --poisson-rounds puts scipy beside it.
void poisson_disk_maximal_2d(benchmark::State& state) {
  stratum::SamplerRequest request;
  request.d = 2;
  request.seed = 1;
  request.radius = 0.01;
  std::size_t coordinates = 0;
  for (auto _ : state) {
    auto points = stratum::generate_points("poisson-disk", request);
    coordinates = points.n * points.d;
    benchmark::DoNotOptimize(points.data.get());
  }
  state.counters["points"] = static_cast<double>(coordinates / 2);
  state.counters["ns_per_coord"] = benchmark::Counter(
      static_cast<double>(coordinates), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Small 2D sets through the registry, a new seed per set (as a renderer's
// pixel sets, §5.5): the patterns made by candidates or dart throwing, whose
// fixed costs matter there, beside `random` (the registry's per-set floor).
void small_set(benchmark::State& state, const std::string& sampler) {
  stratum::SamplerRequest request;
  request.n = static_cast<std::uint64_t>(state.range(0));
  request.d = 2;
  for (auto _ : state) {
    auto points = stratum::generate_points(sampler, request);
    benchmark::DoNotOptimize(points.data.get());
    ++request.seed;
  }
}

// A count every sampler accepts (a perfect square, fourth power and power of
// two), large enough to leave the caches.
constexpr std::int64_t kCount = 1 << 16;

int register_all() {
  benchmark::RegisterBenchmark("baseline/memory-write", memory_write_baseline)->Arg(kCount)->Arg(1 << 20);
  benchmark::RegisterBenchmark("peer/boost-sobol", boost_sobol_bulk)->Arg(kCount)->Arg(1 << 20);
  benchmark::RegisterBenchmark("random-access/sobol-owen-hash/seeded", sobol_random_access, false);
  benchmark::RegisterBenchmark("poisson-disk/maximal-2d/r=0.01", poisson_disk_maximal_2d)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("random-access/sobol-owen-hash/bound", sobol_random_access, true);
  benchmark::RegisterBenchmark("random-access/owen-base-b", owen_base_b_random_access)
      ->ArgsProduct({{2, 3, 29}, {4, 16}})
      ->ArgNames({"base", "log2_indices"});
  for (const char* sampler : {"random", "n-rooks", "best-candidate", "pmj02bn", "poisson-disk"})
    benchmark::RegisterBenchmark((std::string("small-set/") + sampler).c_str(), small_set, sampler)
        ->Arg(4)
        ->Arg(32)  // best-candidate's last grid-free size
        ->Arg(256)
        ->Arg(1024)
        ->Unit(benchmark::kMicrosecond);
  for (unsigned threads : {1u, 2u})
    benchmark::RegisterBenchmark(("registry-threads/sobol/owen-hash/" + std::to_string(threads)).c_str(),
                                 registry_sampler, "sobol", "owen-hash", threads)
        ->Arg(1 << 20)
        ->Unit(benchmark::kMicrosecond);
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
