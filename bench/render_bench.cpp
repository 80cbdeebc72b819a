// Ray throughput of the direct-lighting integrator against bare Embree
// (issue 5 §7): the integrator renders the Cornell box (1 eye ray + M shadow
// rays per sample, area light sampling); a recording pass replays the same
// sampler draws to list exactly the rays the integrator traces; bare Embree
// then traces that list (rtcIntersect1 for eye rays, rtcOccluded1 for shadow
// rays) in the same run, on the same number of threads. Counters: rays/s of
// both, samples/s of the integrator, and their ratio (target ≥ 0.8 on one
// thread), by wall-clock time and by process CPU time (ratio_cpu: less
// sensitive to other processes preempting this one on a loaded machine), and
// ratio_traced without render()'s BVH build (timed alone each iteration;
// the bare scene's build is untimed), which matters for the third argument's
// scene 1, the Cornell box with a 131k-triangle sphere mesh.
// The second argument picks the pixel sampler: random, sobol, jittered and
// pmj02 take the PixelSampler's direct paths, halton (permute) its
// table-free path (the permutations a set needs, built per pixel and
// dimension and per shadow-ray array; the same points as the registry).
//
// Not in bench/*_bench.cpp (the glob of stratum_bench) because stratum_bench
// does not link stratum_render and Embree; see /work/helpers/notes/render.md.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>

#include <time.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <limits>
#include <vector>

#include "stratum/render/bsdf.hpp"
#include "stratum/render/camera_model.hpp"
#include "stratum/render/lights.hpp"
#include "stratum/render/render.hpp"

namespace {
using namespace stratum::render;

constexpr int kSize = 64;
constexpr std::uint32_t kSpp = 4, kShadow = 4;

constexpr std::array<const char*, 5> kSamplers = {"random", "sobol", "jittered", "pmj02", "halton"};

RenderSettings bench_settings(unsigned threads, const char* sampler = "random") {
  RenderSettings s;
  s.integrator = "direct";
  s.light_strategy = "area";
  s.light_samples = kShadow;
  s.sampler.sampler = sampler;
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
      shape.vertices.push_back(center + radius * Vec3{std::sin(theta) * std::cos(phi), std::cos(theta),
                                                      std::sin(theta) * std::sin(phi)});
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
  std::vector<RTCRay> eye, shadow;
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
        const auto hit = accelerator.intersect(ray);
        if (!hit) continue;
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
          rays.shadow.push_back(to_rtc({hit->position, ls->wi, time, ls->distance - 2 * eps}, eps));
        }
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
          auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, t, RTC_FORMAT_FLOAT4, 16, 1));
          const Vec3 c = shape.center + double(t) * shape.motion;
          v[0] = float(c.x), v[1] = float(c.y), v[2] = float(c.z), v[3] = float(shape.radius);
        }
      } else {
        const bool quad = shape.type == ShapeType::quad;  // Embree quads, as the Accelerator uses
        std::vector<Vec3> vertices = shape.vertices;
        if (quad) vertices = {shape.corner, shape.corner + shape.edge_u, shape.corner + shape.edge_u + shape.edge_v, shape.corner + shape.edge_v};
        if (!quad && shape.indices.empty()) continue;
        g = rtcNewGeometry(device, quad ? RTC_GEOMETRY_TYPE_QUAD : RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryTimeStepCount(g, steps);
        for (unsigned t = 0; t < steps; ++t) {
          auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, t, RTC_FORMAT_FLOAT3, 12, vertices.size()));
          for (std::size_t i = 0; i < vertices.size(); ++i) {
            const Vec3 p = vertices[i] + double(t) * shape.motion;
            v[3 * i] = float(p.x), v[3 * i + 1] = float(p.y), v[3 * i + 2] = float(p.z);
          }
        }
        if (quad) {
          auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 16, 1));
          for (unsigned k = 0; k < 4; ++k) idx[k] = k;
        } else {
          auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, shape.indices.size()));
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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// CPU seconds used by this process (all its threads).
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void BM_DirectVsBareEmbree(benchmark::State& state) {
  const unsigned threads = unsigned(state.range(0));
  const char* sampler = kSamplers[std::size_t(state.range(1))];
  state.SetLabel(std::string(sampler) + (state.range(2) == 1 ? " mesh-sphere" : ""));
  const Scene scene = bench_scene(int(state.range(2)));
  const RenderSettings settings = bench_settings(threads, sampler);
  const Recorded rays = record(scene, settings);
  const BareScene bare(scene);
  const double ray_count = double(rays.eye.size() + rays.shadow.size());
  tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
  double render_seconds = 0, bare_seconds = 0, render_cpu = 0, bare_cpu = 0, build_seconds = 0;
  std::int64_t iterations = 0;
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    double cpu = process_cpu_seconds();
    benchmark::DoNotOptimize(render(scene, settings).rgb.data());
    render_seconds += seconds_since(start);
    render_cpu += process_cpu_seconds() - cpu;
    start = std::chrono::steady_clock::now();
    cpu = process_cpu_seconds();
    benchmark::DoNotOptimize(trace(bare, rays));
    bare_seconds += seconds_since(start);
    bare_cpu += process_cpu_seconds() - cpu;
    // render() builds its BVH each call; the bare scene's was built once,
    // untimed. The same build, timed alone, for ratio_traced.
    start = std::chrono::steady_clock::now();
    { const Accelerator build(scene); }
    build_seconds += seconds_since(start);
    ++iterations;
  }
  const double integrator_rate = ray_count * double(iterations) / render_seconds;
  const double bare_rate = ray_count * double(iterations) / bare_seconds;
  state.counters["rays"] = ray_count;
  state.counters["integrator_rays_per_s"] = integrator_rate;
  state.counters["bare_embree_rays_per_s"] = bare_rate;
  state.counters["samples_per_s"] = double(kSize * kSize * kSpp) * double(iterations) / render_seconds;
  state.counters["ratio"] = integrator_rate / bare_rate;
  state.counters["ratio_cpu"] = bare_cpu / render_cpu;
  state.counters["ratio_traced"] = bare_seconds / (render_seconds - build_seconds);  // without the BVH build
  state.counters["build_ms"] = 1e3 * build_seconds / double(iterations);
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

}  // namespace

BENCHMARK(BM_DirectVsBareEmbree)
    ->ArgsProduct({{1, 2}, {0, 1, 2, 3, 4}, {0}})
    ->ArgsProduct({{1}, {0, 1, 2, 3}, {1}})
    ->ArgNames({"threads", "sampler", "scene"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_RenderSetup)->Unit(benchmark::kMillisecond);
#ifdef STRATUM_RENDER_BENCH_MAIN  // built on its own (see the note at the top)
BENCHMARK_MAIN();
#endif
