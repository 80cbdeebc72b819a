// Ray throughput of the direct-lighting integrator against bare Embree
// (issue 5 §7): the integrator renders the Cornell box (1 eye ray + M shadow
// rays per sample, area light sampling); a recording pass replays the same
// sampler draws to list exactly the rays the integrator traces; bare Embree
// then traces that list (rtcIntersect1 for eye rays, rtcOccluded1 for shadow
// rays) in the same run, on the same number of threads; both on BVHs built
// beforehand, untimed (render(accelerator, …)). Counters: rays/s of both,
// samples/s of the integrator, and their ratio (target ≥ 0.8 on one thread),
// by wall-clock time and by process CPU time (ratio_cpu: less sensitive to
// other processes preempting this one on a loaded machine). A cost ladder
// between the two (trace_wrapped) splits render()'s time per sample into
// Embree, stratum's Accelerator calls, the sampler's draws and the rest of
// the integrator, and gives the ratio each rung alone would leave; a second
// bare pass traces each sample's shadow rays as 4-ray packets (rtcOccluded4).
// The third argument picks the scene: 0 the Cornell box, 1 the same with a
// 131k-triangle sphere mesh.
// The second argument picks the pixel sampler: random, sobol, jittered and
// pmj02 take the PixelSampler's direct paths, halton (permute) its
// table-free path (the permutations a set needs, built per pixel and
// dimension and per shadow-ray array; the same points as the registry);
// faure and halton:owen (exact base-b Owen scrambling) draw through their
// registry's SeededGenerator (a seed's keys written in place per pixel and
// dimension and per array). BM_PixelSamplerDraws times the draws alone for
// every sampler the renderer takes.
//
// Part of stratum_bench only when the renderer is built (bench/CMakeLists.txt
// leaves it out otherwise, since it needs stratum_render and Embree).
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>

#include <time.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <optional>
#include <vector>

#include "stratum/render/bsdf.hpp"
#include "stratum/render/camera_model.hpp"
#include "stratum/render/lights.hpp"
#include "stratum/render/pixel_sampler.hpp"
#include "stratum/render/render.hpp"
#include "stratum/registry.hpp"

namespace {
using namespace stratum::render;

constexpr int kSize = 64;
constexpr std::uint32_t kSpp = 4, kShadow = 4;

/// Name and randomizer (empty: the sampler's default) of each sampler argument.
constexpr std::array<std::array<const char*, 2>, 7> kSamplers = {{{"random", ""},
                                                                  {"sobol", ""},
                                                                  {"jittered", ""},
                                                                  {"pmj02", ""},
                                                                  {"halton", ""},
                                                                  {"faure", ""},
                                                                  {"halton", "owen"}}};

std::string sampler_label(std::size_t k) {
  return std::string(kSamplers[k][0]) + (*kSamplers[k][1] ? std::string(":") + kSamplers[k][1] : "");
}

RenderSettings bench_settings(unsigned threads, std::size_t sampler = 0) {
  RenderSettings s;
  s.integrator = "direct";
  s.light_strategy = "area";
  s.light_samples = kShadow;
  s.sampler.sampler = kSamplers[sampler][0];
  s.sampler.randomize = kSamplers[sampler][1];
  s.sampler.spp = kSpp;
  s.sampler.seed = 1;
  s.passes = 1;
  s.threads = threads;
  return s;
}

/// A UV sphere of `rings` × 2·`rings` quads (two triangles each), outward-facing.
Shape mesh_sphere(Vec3 center, double radius, int rings, std::size_t material) {
  Shape shape;
  shape.type = ShapeType::triangles;
  shape.material = material;
  const int segments = 2 * rings;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = M_PI * i / rings, phi = 2 * M_PI * j / segments;
      shape.vertices.push_back(
          center + radius * Vec3{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const unsigned a = unsigned(i * segments + j), b = unsigned(i * segments + (j + 1) % segments);
      const unsigned c = a + unsigned(segments), d = b + unsigned(segments);
      shape.indices.push_back({a, c, b});
      shape.indices.push_back({b, c, d});
    }
  return shape;
}

/// 0: the Cornell box (18 primitives: Embree's cheapest rays); 1: the same
/// with a 131k-triangle sphere mesh in the air (a scene where a ray costs
/// what it costs in production), to show how the ratio follows Embree's share.
Scene bench_scene(int kind = 0) {
  Scene scene = cornell_box();
  scene.camera.width = scene.camera.height = kSize;
  if (kind == 1) {
    scene.shapes.push_back(mesh_sphere({160, 260, 380}, 90, 256, scene.shapes[0].material));
    validate_scene(scene);
  }
  return scene;
}

struct Recorded {
  std::vector<RTCRay> eye, shadow;  // for bare Embree
  // The same rays as stratum's, for the cost ladder (BM_CostLadder): by eye
  // ray (one per sample, in record()'s order), whether it hits and where its
  // shadow rays end in shadow_rays.
  std::vector<Ray> eye_rays, shadow_rays;
  std::vector<std::uint32_t> shadow_end;
};

RTCRay to_rtc(const Ray& ray, double t_near) {
  RTCRay r{};
  r.org_x = float(ray.origin.x), r.org_y = float(ray.origin.y), r.org_z = float(ray.origin.z);
  r.dir_x = float(ray.direction.x), r.dir_y = float(ray.direction.y), r.dir_z = float(ray.direction.z);
  r.tnear = float(t_near);
  r.tfar = ray.t_max >= 1e30 ? std::numeric_limits<float>::infinity() : float(ray.t_max);
  r.time = float(ray.time);
  r.mask = ~0u;
  return r;
}

/// The rays the direct integrator traces (same sampler draws in the same order as render() and integrators.cpp).
Recorded record(const Scene& scene, const RenderSettings& s) {
  const Accelerator accelerator(scene);
  const CameraModel camera(scene.camera);
  PixelSampler sampler(s.sampler);
  Recorded rays;
  const double eps = accelerator.epsilon();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (std::uint32_t index = 0; index < kSpp; ++index) {
        sampler.start_pixel_sample(std::uint32_t(x), std::uint32_t(y), index);
        const auto film = sampler.get_pixel_2d();
        const double time = sampler.get_time();
        const auto lens = sampler.get_2d();
        const Ray ray = camera.generate(x + film[0], y + film[1], lens, time);
        rays.eye.push_back(to_rtc(ray, eps));
        rays.eye_rays.push_back(ray);
        const auto hit = accelerator.intersect(ray);
        if (!hit) {
          rays.shadow_end.push_back(std::uint32_t(rays.shadow_rays.size()));
          continue;
        }
        const Material& m = scene.materials[scene.shapes[hit->shape].material];
        const Vec3 n = dot(hit->normal, ray.direction) < 0 ? hit->normal : -hit->normal;
        const Bsdf bsdf(m, n, -normalize(ray.direction));
        std::array<double, 2> u[kShadow];
        sampler.get_2d_array(kShadow, u);
        const auto offset = static_cast<std::size_t>(sampler.get_1d() * double(scene.lights.size()));
        for (std::uint32_t i = 0; i < kShadow; ++i) {
          const Light& light = scene.lights[(i + offset) % scene.lights.size()];
          const auto ls = sample_light(scene, light, hit->position, n, time, u[i], LightStrategy::area);
          if (!ls || dot(n, ls->wi) <= 0) continue;
          const Vec3 f = bsdf.eval(ls->wi);
          if (f.x <= 0 && f.y <= 0 && f.z <= 0) continue;
          const Ray shadow{hit->position, ls->wi, time, ls->distance - 2 * eps};
          rays.shadow.push_back(to_rtc(shadow, eps));
          rays.shadow_rays.push_back(shadow);
        }
        rays.shadow_end.push_back(std::uint32_t(rays.shadow_rays.size()));
      }
  return rays;
}

/// A bare Embree scene of the same shapes (quads, spheres, triangles; two time steps when moving).
struct BareScene {
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  explicit BareScene(const Scene& s) {
    for (const Shape& shape : s.shapes) {
      const bool moves = shape.motion.x != 0 || shape.motion.y != 0 || shape.motion.z != 0;
      const unsigned steps = moves ? 2 : 1;
      RTCGeometry g = nullptr;
      if (shape.type == ShapeType::sphere) {
        g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        rtcSetGeometryTimeStepCount(g, steps);
        for (unsigned t = 0; t < steps; ++t) {
          auto* v =
              static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, t, RTC_FORMAT_FLOAT4, 16, 1));
          const Vec3 c = shape.center + double(t) * shape.motion;
          v[0] = float(c.x), v[1] = float(c.y), v[2] = float(c.z), v[3] = float(shape.radius);
        }
      } else {
        const bool quad = shape.type == ShapeType::quad;  // Embree quads, as the Accelerator uses
        std::vector<Vec3> vertices = shape.vertices;
        if (quad)
          vertices = {shape.corner, shape.corner + shape.edge_u, shape.corner + shape.edge_u + shape.edge_v,
                      shape.corner + shape.edge_v};
        if (!quad && shape.indices.empty()) continue;
        g = rtcNewGeometry(device, quad ? RTC_GEOMETRY_TYPE_QUAD : RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryTimeStepCount(g, steps);
        for (unsigned t = 0; t < steps; ++t) {
          auto* v = static_cast<float*>(
              rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, t, RTC_FORMAT_FLOAT3, 12, vertices.size()));
          for (std::size_t i = 0; i < vertices.size(); ++i) {
            const Vec3 p = vertices[i] + double(t) * shape.motion;
            v[3 * i] = float(p.x), v[3 * i + 1] = float(p.y), v[3 * i + 2] = float(p.z);
          }
        }
        if (quad) {
          auto* idx =
              static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 16, 1));
          for (unsigned k = 0; k < 4; ++k) idx[k] = k;
        } else {
          auto* idx = static_cast<unsigned*>(
              rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, shape.indices.size()));
          for (std::size_t i = 0; i < shape.indices.size(); ++i)
            for (int k = 0; k < 3; ++k) idx[3 * i + k] = shape.indices[i][k];
        }
      }
      rtcCommitGeometry(g);
      rtcAttachGeometry(scene, g);
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(scene);
  }
  ~BareScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
};

/// Traces every recorded ray; returns the number of eye hits plus occluded shadow rays (kept alive).
std::size_t trace(const BareScene& bare, const Recorded& rays) {
  std::atomic<std::size_t> hits{0};
  const std::size_t chunk = 4096, total = rays.eye.size() + rays.shadow.size();
  tbb::parallel_for(std::size_t(0), (total + chunk - 1) / chunk, [&](std::size_t c) {
    std::size_t local = 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t i = c * chunk; i < std::min(total, (c + 1) * chunk); ++i) {
      if (i < rays.eye.size()) {
        RTCRayHit q{};
        q.ray = rays.eye[i];
        q.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(bare.scene, &context, &q);
        local += q.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      } else {
        RTCRay q = rays.shadow[i - rays.eye.size()];
        rtcOccluded1(bare.scene, &context, &q);
        local += q.tfar < 0;
      }
    }
    hits += local;
  });
  return hits;
}

/// trace() with each sample's shadow rays (they share their origin) as 4-ray
/// packets (rtcOccluded4): the tracing design change an integrator could
/// make, measured on bare Embree (counter ns_embree_packets).
std::size_t trace_packets(const BareScene& bare, const Recorded& rays) {
  std::atomic<std::size_t> hits{0};
  const std::size_t samples = rays.eye.size(), chunk = 1024;
  tbb::parallel_for(std::size_t(0), (samples + chunk - 1) / chunk, [&](std::size_t c) {
    std::size_t local = 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t s = c * chunk; s < std::min(samples, (c + 1) * chunk); ++s) {
      RTCRayHit q{};
      q.ray = rays.eye[s];
      q.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(bare.scene, &context, &q);
      local += q.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      const std::size_t first = s == 0 ? 0 : rays.shadow_end[s - 1], count = rays.shadow_end[s] - first;
      for (std::size_t k = 0; k < count; k += 4) {
        alignas(16) RTCRay4 packet{};
        alignas(16) int valid[4] = {0, 0, 0, 0};
        for (std::size_t l = 0; l < 4 && k + l < count; ++l) {
          const RTCRay& r = rays.shadow[first + k + l];
          valid[l] = -1;
          packet.org_x[l] = r.org_x, packet.org_y[l] = r.org_y, packet.org_z[l] = r.org_z;
          packet.dir_x[l] = r.dir_x, packet.dir_y[l] = r.dir_y, packet.dir_z[l] = r.dir_z;
          packet.tnear[l] = r.tnear, packet.tfar[l] = r.tfar, packet.time[l] = r.time;
          packet.mask[l] = r.mask, packet.id[l] = r.id, packet.flags[l] = r.flags;
        }
        rtcOccluded4(valid, bare.scene, &context, &packet);
        for (std::size_t l = 0; l < 4 && k + l < count; ++l) local += packet.tfar[l] < 0;
      }
    }
    hits += local;
  });
  return hits;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// CPU seconds used by this process (all its threads).
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// The cost ladder between bare Embree and render(): the recorded rays
/// through stratum's Accelerator (double rays converted to Embree's, hits
/// made into Hit records), sample by sample as the integrator traces them;
/// with `draws`, each sample also takes the sampler draws the integrator
/// takes (film, time, lens; at a hit the shadow-ray array and the light
/// offset). What render() takes beyond this is the integrator's own
/// arithmetic (camera, light samples, BSDF, sums) and its frame (tiles,
/// film), which no integrator over these draws and wrappers can avoid
/// entirely. Returns the hit count (kept alive).
std::size_t trace_wrapped(const Accelerator& accelerator, const Recorded& rays, const PixelSampler* draws) {
  std::atomic<std::size_t> hits{0};
  const std::size_t samples = rays.eye_rays.size(), chunk = 1024;
  tbb::parallel_for(std::size_t(0), (samples + chunk - 1) / chunk, [&](std::size_t c) {
    std::optional<PixelSampler> sampler;
    if (draws) sampler.emplace(*draws);
    std::size_t local = 0;
    double drawn = 0;
    std::array<double, 2> u[kShadow];
    for (std::size_t s = c * chunk; s < std::min(samples, (c + 1) * chunk); ++s) {
      if (sampler) {  // record()'s order: pixels row by row, kSpp samples each
        const std::size_t pixel = s / kSpp;
        sampler->start_pixel_sample(std::uint32_t(pixel % kSize), std::uint32_t(pixel / kSize),
                                    std::uint32_t(s % kSpp));
        drawn += sampler->get_pixel_2d()[0] + sampler->get_time() + sampler->get_2d()[0];
      }
      const auto hit = accelerator.intersect(rays.eye_rays[s]);
      if (!hit) continue;
      ++local;
      if (sampler) {
        sampler->get_2d_array(kShadow, u);
        drawn += u[0][0] + sampler->get_1d();
      }
      for (std::size_t r = s == 0 ? 0 : rays.shadow_end[s - 1]; r < rays.shadow_end[s]; ++r)
        local += accelerator.occluded(rays.shadow_rays[r]);
    }
    benchmark::DoNotOptimize(drawn);
    hits += local;
  });
  return hits;
}

void BM_DirectVsBareEmbree(benchmark::State& state) {
  const unsigned threads = unsigned(state.range(0));
  const auto sampler = std::size_t(state.range(1));
  state.SetLabel(sampler_label(sampler) + (state.range(2) == 1 ? " mesh-sphere" : ""));
  const Scene scene = bench_scene(int(state.range(2)));
  const RenderSettings settings = bench_settings(threads, sampler);
  const Recorded rays = record(scene, settings);
  const BareScene bare(scene);
  const Accelerator accelerator(scene);
  const PixelSampler draws(settings.sampler);
  const double ray_count = double(rays.eye.size() + rays.shadow.size());
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
  // Each iteration times, in turn: render() on the BVH built above (as the
  // bare scene's, untimed), bare Embree, and the ladder's two rungs.
  enum { kRender, kBare, kWrapped, kDrawn, kPackets };
  double seconds[5] = {}, cpu[5] = {};
  std::int64_t iterations = 0;
  for (auto _ : state) {
    const auto timed = [&](int k, auto work) {
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = process_cpu_seconds();
      benchmark::DoNotOptimize(work());
      seconds[k] += seconds_since(start);
      cpu[k] += process_cpu_seconds() - cpu_start;
    };
    timed(kRender, [&] { return render(accelerator, settings).rgb[0]; });
    timed(kBare, [&] { return trace(bare, rays); });
    timed(kWrapped, [&] { return trace_wrapped(accelerator, rays, nullptr); });
    timed(kDrawn, [&] { return trace_wrapped(accelerator, rays, &draws); });
    timed(kPackets, [&] { return trace_packets(bare, rays); });
    ++iterations;
  }
  const double integrator_rate = ray_count * double(iterations) / seconds[kRender];
  const double bare_rate = ray_count * double(iterations) / seconds[kBare];
  const double samples = double(kSize * kSize * kSpp) * double(iterations);
  state.counters["rays"] = ray_count;
  state.counters["integrator_rays_per_s"] = integrator_rate;
  state.counters["bare_embree_rays_per_s"] = bare_rate;
  state.counters["samples_per_s"] = samples / seconds[kRender];
  state.counters["ratio"] = integrator_rate / bare_rate;
  state.counters["ratio_cpu"] = cpu[kBare] / cpu[kRender];
  // The ladder: the best ratio an integrator could reach with stratum's
  // Accelerator calls alone, and with them and the sampler's draws; and
  // where render()'s time per sample goes, in ns.
  state.counters["ratio_wrapped"] = seconds[kBare] / seconds[kWrapped];
  state.counters["ratio_wrapped_draws"] = seconds[kBare] / seconds[kDrawn];
  state.counters["ns_embree"] = 1e9 * seconds[kBare] / samples;
  state.counters["ns_wrappers"] = 1e9 * (seconds[kWrapped] - seconds[kBare]) / samples;
  state.counters["ns_draws"] = 1e9 * (seconds[kDrawn] - seconds[kWrapped]) / samples;
  state.counters["ns_integrator"] = 1e9 * (seconds[kRender] - seconds[kDrawn]) / samples;
  // Bare Embree again with the shadow rays in packets, and the ratio render() would reach if
  // tracing the same way saved it exactly what it saves bare Embree.
  state.counters["ns_embree_packets"] = 1e9 * seconds[kPackets] / samples;
  state.counters["ratio_if_packets"] = seconds[kBare] / (seconds[kRender] - seconds[kBare] + seconds[kPackets]);
}

/// The fixed cost of one render() call (Embree device and BVH, buffers,
/// threads): the Cornell box at 1×1 pixel, 1 sample.
void BM_RenderSetup(benchmark::State& state) {
  Scene scene = bench_scene();
  scene.camera.width = scene.camera.height = 1;
  RenderSettings settings = bench_settings(1);
  settings.sampler.spp = 1;
  for (auto _ : state) benchmark::DoNotOptimize(render(scene, settings).rgb.data());
}

/// The draws of a direct-lighting sample alone (film position, time, lens,
/// the M = 4 shadow-ray array and the light offset), for every pixel of the
/// 64×64 image at 4 spp, one thread: what BM_DirectVsBareEmbree's ladder
/// calls "draws", for every sampler the renderer takes (its default
/// randomizer; halton also under owen). ns_per_sample; sobol's row is the peer.
void BM_PixelSamplerDraws(benchmark::State& state, const std::string& sampler, const std::string& randomize) {
  PixelSamplerSettings settings;
  settings.sampler = sampler;
  settings.randomize = randomize;
  settings.spp = kSpp;
  settings.seed = 1;
  settings.resolution = kSize;
  const PixelSampler prototype(settings);
  double sink = 0;
  for (auto _ : state) {
    PixelSampler draws(prototype);  // render() copies one per tile: its caches start empty
    for (std::uint32_t y = 0; y < kSize; ++y)
      for (std::uint32_t x = 0; x < kSize; ++x)
        for (std::uint32_t index = 0; index < kSpp; ++index) {
          draws.start_pixel_sample(x, y, index);
          const auto film = draws.get_pixel_2d();
          const double time = draws.get_time();
          const auto lens = draws.get_2d();
          std::array<double, 2> shadow[kShadow];
          draws.get_2d_array(kShadow, shadow);
          sink += film[0] + time + lens[1] + shadow[kShadow - 1][0] + draws.get_1d();
        }
  }
  benchmark::DoNotOptimize(sink);
  state.counters["ns_per_sample"] =  // seconds a sample, printed with its SI prefix (n)
      benchmark::Counter(double(kSize * kSize * kSpp),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

int register_pixel_sampler_draws() {
  std::vector<std::pair<std::string, std::string>> runs;
  for (const stratum::SamplerInfo& info : stratum::samplers())
    if (!info.flags.space_time) runs.emplace_back(info.name, "");
  runs.emplace_back("halton", "owen");
  for (const auto& [sampler, randomize] : runs)
    benchmark::RegisterBenchmark(
        ("BM_PixelSamplerDraws/" + sampler + (randomize.empty() ? "" : ":" + randomize)).c_str(), BM_PixelSamplerDraws,
        sampler, randomize)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        // The least of the repetitions: a loaded machine only ever adds time.
        ->ComputeStatistics("min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
  return 0;
}
const int pixel_sampler_draws_registered = register_pixel_sampler_draws();

}  // namespace

BENCHMARK(BM_DirectVsBareEmbree)
    ->ArgsProduct({{1, 2}, {0, 1, 2, 3, 4}, {0}})
    ->ArgsProduct({{1}, {0, 1, 2, 3}, {1}})
    ->ArgsProduct({{1}, {5, 6}, {0}})
    ->ArgNames({"threads", "sampler", "scene"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_RenderSetup)->Unit(benchmark::kMillisecond);
#ifdef STRATUM_RENDER_BENCH_MAIN  // built on its own (see the note at the top)
BENCHMARK_MAIN();
#endif
