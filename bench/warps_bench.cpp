// ns per warped sample of every registry warp, through the registry's array
// call (warp.sample over n rows, no input checks) and, for the basic warps,
// through the core headers directly; against a copy of the input array of the
// same size (a memory-bandwidth baseline) in the same run. The ratio to the
// baseline is computed from the JSON output (the command is in BENCHMARKS.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "stratum/util/hash.hpp"
#include "stratum/warp_registry.hpp"
#include "stratum/warps/densities_1d.hpp"
#include "stratum/warps/disk.hpp"
#include "stratum/warps/sphere.hpp"
#include "stratum/warps/triangle.hpp"

namespace {

constexpr std::size_t kSamples = 1 << 16;

std::vector<double> uniforms(unsigned dim) {
  std::vector<double> u(kSamples * dim);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = stratum::uniform01(1, i);
  return u;
}

void set_counters(benchmark::State& state) {
  state.counters["ns_per_sample"] = benchmark::Counter(
      static_cast<double>(kSamples), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Baseline: copy a 2-coordinate input array into a 3-coordinate-wide output (as a warp to directions writes).
void copy_baseline(benchmark::State& state) {
  const auto u = uniforms(2);
  std::vector<double> out(kSamples * 3);
  for (auto _ : state) {
    for (std::size_t i = 0; i < kSamples; ++i) std::memcpy(&out[3 * i], &u[2 * i], 2 * sizeof(double));
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state);
}

stratum::WarpParams example(const std::string& name) {
  if (name == "piecewise-1d") return {{"values", std::vector<double>(256, 1.0)}, {"width", {256}}};
  if (name == "piecewise-2d")
    return {{"values", std::vector<double>(256 * 128, 1.0)}, {"width", {256}}, {"height", {128}}};
  if (name == "alias") return {{"values", std::vector<double>(256, 1.0)}};
  return {};
}

void registry_warp(benchmark::State& state, const std::string& name) {
  const auto warp = stratum::make_warp(name, example(name));
  auto u = uniforms(warp->input_dim());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = stratum::uniform01(2, i);
  std::vector<double> out(kSamples * warp->output_dim());
  for (auto _ : state) {
    warp->sample(u.data(), kSamples, out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state);
}

template <class Map>
void core_warp(benchmark::State& state, Map map) {
  const auto u = uniforms(2);
  using Point = decltype(map(std::array<double, 2>{}));
  std::vector<Point> out(kSamples);
  for (auto _ : state) {
    for (std::size_t i = 0; i < kSamples; ++i) out[i] = map(std::array<double, 2>{u[2 * i], u[2 * i + 1]});
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state);
}

const bool registered = [] {
  benchmark::RegisterBenchmark("warp/copy_baseline", copy_baseline);
  for (const auto& info : stratum::warps())
    benchmark::RegisterBenchmark(("warp/registry/" + info.name).c_str(),
                                 [name = info.name](benchmark::State& s) { registry_warp(s, name); });
  const stratum::UniformCone<double> cone(0.5);
  const stratum::UniformTriangle<double, 3> triangle({1, 0, 0.5}, {0, 2, -1}, {-1, -0.5, 2});
  const stratum::NormalDensity<double> normal(0, 1);
  const stratum::BilinearDensity<double> bilinear(std::array<double, 4>{1, 2, 3, 4});
  using A2 = std::array<double, 2>;
  benchmark::RegisterBenchmark("warp/core/disk-polar",
                               [](benchmark::State& s) { core_warp(s, stratum::sample_polar_disk<double>); });
  benchmark::RegisterBenchmark("warp/core/disk-concentric",
                               [](benchmark::State& s) { core_warp(s, stratum::sample_concentric_disk<double>); });
  benchmark::RegisterBenchmark("warp/core/hemisphere-uniform",
                               [](benchmark::State& s) { core_warp(s, stratum::sample_uniform_hemisphere<double>); });
  benchmark::RegisterBenchmark("warp/core/hemisphere-cosine",
                               [](benchmark::State& s) { core_warp(s, stratum::sample_cosine_hemisphere<double>); });
  benchmark::RegisterBenchmark("warp/core/sphere-uniform",
                               [](benchmark::State& s) { core_warp(s, stratum::sample_uniform_sphere<double>); });
  benchmark::RegisterBenchmark("warp/core/cone",
                               [cone](benchmark::State& s) { core_warp(s, [&](A2 u) { return cone.sample(u); }); });
  benchmark::RegisterBenchmark("warp/core/triangle-3d", [triangle](benchmark::State& s) {
    core_warp(s, [&](A2 u) { return triangle.sample(u); });
  });
  benchmark::RegisterBenchmark(
      "warp/core/normal", [normal](benchmark::State& s) { core_warp(s, [&](A2 u) { return normal.sample(u[0]); }); });
  benchmark::RegisterBenchmark("warp/core/bilinear", [bilinear](benchmark::State& s) {
    core_warp(s, [&](A2 u) { return bilinear.sample(u); });
  });
  return true;
}();

}  // namespace
