// Pixel-sampler draws, stratum against OpenQMC (the sampler library of a
// production renderer, Academy Software Foundation), in the same run: for a
// 64×64 image at 16 samples per pixel, the cost of one sample's first four
// dimensions (film position and lens), the draws a camera ray needs.
// stratum: render::PixelSampler (start_pixel_sample, get_pixel_2d, get_2d);
// OpenQMC: a domain per (pixel, index) and drawSample<4>.
//
// OpenQMC is not part of stratum: the bench is built only when the
// environment variable OPENQMC_INCLUDE names a folder holding oqmc/oqmc.h
// (its header-only include tree) at configure time; see BENCHMARKS.md.
//   OPENQMC_INCLUDE=/path/to/openqmc/include cmake -S . -B build/bench -DSTRATUM_BUILD_BENCH=ON ...
//   build/bench/bin/stratum_openqmc_bench
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>
#include <string>

#include <oqmc/oqmc.h>

#include "stratum/render/pixel_sampler.hpp"

namespace {

constexpr int kSize = 64;
constexpr int kSpp = 16;

void report(benchmark::State& state) {
  state.SetItemsProcessed(state.iterations() * kSize * kSize * kSpp);
  state.counters["ns_per_sample"] = benchmark::Counter(
      double(kSize) * kSize * kSpp, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_Stratum(benchmark::State& state, std::string name, std::string randomize) {
  stratum::render::PixelSamplerSettings settings;
  settings.sampler = std::move(name);
  settings.randomize = std::move(randomize);
  settings.spp = kSpp;
  settings.resolution = kSize;
  const stratum::render::PixelSampler prototype(settings);
  for (auto _ : state) {
    stratum::render::PixelSampler sampler(prototype);
    double sum = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int index = 0; index < kSpp; ++index) {
          sampler.start_pixel_sample(std::uint32_t(x), std::uint32_t(y), std::uint32_t(index));
          const auto film = sampler.get_pixel_2d();
          const auto lens = sampler.get_2d();
          sum += film[0] + film[1] + lens[0] + lens[1];
        }
    benchmark::DoNotOptimize(sum);
  }
  report(state);
}

template <class Sampler>
void BM_OpenQmc(benchmark::State& state) {
  const auto cache = std::make_unique<char[]>(Sampler::cacheSize);
  Sampler::initialiseCache(cache.get());
  for (auto _ : state) {
    double sum = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int index = 0; index < kSpp; ++index) {
          const Sampler domain(x, y, 0, index, cache.get());
          float sample[4];
          domain.template drawSample<4>(sample);
          sum += double(sample[0]) + sample[1] + sample[2] + sample[3];
        }
    benchmark::DoNotOptimize(sum);
  }
  report(state);
}

}  // namespace

BENCHMARK_CAPTURE(BM_Stratum, random, std::string("random"), std::string(""));
BENCHMARK_CAPTURE(BM_Stratum, sobol_owen_hash, std::string("sobol"), std::string("owen-hash"));
BENCHMARK_CAPTURE(BM_Stratum, pmj02, std::string("pmj02"), std::string(""));
BENCHMARK_CAPTURE(BM_Stratum, zsobol, std::string("zsobol"), std::string(""));
BENCHMARK_CAPTURE(BM_Stratum, halton, std::string("halton"), std::string(""));
BENCHMARK_CAPTURE(BM_Stratum, sobol_bn, std::string("sobol-bn"), std::string(""));
BENCHMARK_CAPTURE(BM_Stratum, pmj02_bn, std::string("pmj02-bn"), std::string(""));
BENCHMARK_CAPTURE(BM_Stratum, lattice_bn, std::string("lattice-bn"), std::string(""));
BENCHMARK_CAPTURE(BM_Stratum, lattice, std::string("lattice-sequence"), std::string(""));
BENCHMARK(BM_OpenQmc<oqmc::SobolSampler>)->Name("BM_OpenQmc/sobol");
BENCHMARK(BM_OpenQmc<oqmc::PmjSampler>)->Name("BM_OpenQmc/pmj");
BENCHMARK(BM_OpenQmc<oqmc::LatticeSampler>)->Name("BM_OpenQmc/lattice");
BENCHMARK(BM_OpenQmc<oqmc::SobolBnSampler>)->Name("BM_OpenQmc/sobol_bn");
BENCHMARK(BM_OpenQmc<oqmc::PmjBnSampler>)->Name("BM_OpenQmc/pmj_bn");
BENCHMARK(BM_OpenQmc<oqmc::LatticeBnSampler>)->Name("BM_OpenQmc/lattice_bn");
BENCHMARK_MAIN();
