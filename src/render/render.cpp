#include "stratum/render/render.hpp"

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "stratum/distributed.hpp"
#include "stratum/memory.hpp"
#include "stratum/render/accelerator.hpp"
#include "stratum/render/camera_model.hpp"
#include "stratum/render/integrators.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::render {

void validate_settings(const RenderSettings& s) {
  const auto& i = s.integrator;
  require(i == "direct" || i == "irradiance" || i == "path", "integrator", i, "allowed: direct, irradiance, path");
  const auto& l = s.light_strategy;
  require(l == "area" || l == "solid-angle" || l == "projected-solid-angle" || l == "bsdf" || l == "mis",
          "light-strategy", l, "allowed: area, solid-angle, projected-solid-angle, bsdf, mis");
  require(s.hemisphere == "uniform" || s.hemisphere == "cosine", "hemisphere", s.hemisphere,
          "allowed: uniform, cosine");
  require(s.light_samples >= 1 && s.light_samples <= 65536, "light-samples", s.light_samples, "must be in [1, 65536]");
  require(s.max_depth >= 1 && s.max_depth <= 1024, "max-depth", s.max_depth, "must be in [1, 1024]");
  require(s.threads >= 1 && s.threads <= 1024, "threads", s.threads, "must be in [1, 1024]");
  require(std::isfinite(s.time_limit) && s.time_limit >= 0, "time-limit", s.time_limit, "must be >= 0 seconds");
  require(s.sampler.spp >= 1, "spp", s.sampler.spp, "must be a positive integer");
  // More passes than spp are clamped to spp (a pass takes at least one sample); 0 passes would render nothing.
  require(s.passes >= 1 && s.passes <= (1u << 24), "passes", s.passes, "must be in [1, 2^24] (at most spp are used)");
  const PixelSampler sampler(s.sampler);  // validates sampler, randomizer, spp and time pattern
  try {  // the shadow-ray arrays: n = light_samples points of the sampler (jittered needs n = k²)
    sampler.draw_for_test(s.light_samples, 0);
  } catch (const invalid_argument& e) {
    throw invalid_argument(
        "light-samples", std::to_string(s.light_samples),
        "the sampler " + sampler.spec() + " cannot draw that many points per shading point (" + e.what() + ")");
  }
}

namespace {

using Clock = std::chrono::steady_clock;

/// render()'s work from `start` (when its clock started: before or after the BVH build).
Image render_from(Clock::time_point start, const Accelerator& accelerator, const RenderSettings& settings,
                  const std::function<void(std::uint32_t, std::uint32_t, double)>& progress,
                  const std::atomic<bool>* stop) {
  const Scene& scene = accelerator.scene();
  const PixelSampler prototype = [&] {  // one per tile is copied from it
    PixelSamplerSettings sampler = settings.sampler;
    sampler.resolution = std::uint32_t(std::max(scene.camera.width, scene.camera.height));
    return PixelSampler(std::move(sampler));
  }();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const CameraModel camera(scene.camera);
  const Integrator integrator(scene, accelerator, settings);
  const int width = camera.width(), height = camera.height();
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  // Per pixel and channel: Σ L and Σ L² over the samples taken (written by
  // pass 0, which visits every pixel, so not initialized here).
  const auto sum = std::make_unique_for_overwrite<double[]>(3 * pixels);
  const auto sum2 = std::make_unique_for_overwrite<double[]>(3 * pixels);

  const std::uint32_t spp = settings.sampler.spp;
  const std::uint32_t passes = std::clamp<std::uint32_t>(settings.passes, 1, spp);
  constexpr int tile = 16;
  const int tiles_x = (width + tile - 1) / tile, tiles_y = (height + tile - 1) / tile;
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, settings.threads);
  // Rows of tiles are a job's items: each process of a distributed job
  // renders its rows (every pixel is a pure function of its samples) and
  // the rows are gathered after the last pass. Rows are dealt round-robin,
  // not in contiguous blocks: a scene's cost varies down the image (the
  // light, the floor), and dealt rows give every process a like mix.
  const distributed::Dealt rows = distributed::dealt(std::size_t(tiles_y));
  const int my_tiles = int(rows.size()) * tiles_x;
  const auto tile_of = [&](int local) { return int(rows[std::size_t(local / tiles_x)]) * tiles_x + local % tiles_x; };
  // A process alone checks `stop` per pixel, so that Ctrl-C ends a long pass
  // within a pixel's samples; the ranks of a distributed job stop together after a pass.
  const bool alone = distributed::size() == 1;
  const auto stop_requested = [&] { return stop && stop->load(std::memory_order_relaxed); };
  std::vector<std::uint32_t> tile_samples(std::size_t(tiles_x) * std::size_t(tiles_y), 0);  // taken per tile
  std::uint32_t taken = 0, passes_done = 0;
  bool stopped = false;
  for (std::uint32_t pass = 0; pass < passes; ++pass) {
    const std::uint32_t first = std::uint64_t(spp) * pass / passes, last = std::uint64_t(spp) * (pass + 1) / passes;
    tbb::parallel_for(0, my_tiles, [&](int local) {
      const int t = tile_of(local);
      try {  // a stop seen inside the sampler's draws (check_interrupt) leaves the tile as it was, too
        PixelSampler sampler(prototype);  // per tile: its own per-pixel cache
        const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
        const int x1 = std::min(x0 + tile, width), y1 = std::min(y0 + tile, height);
        // The tile's new sums, stored only when the whole tile is done: a stop
        // (checked per pixel) leaves the tile as the passes before left it.
        double tile_sum[tile * tile][3], tile_sum2[tile * tile][3];
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x) {
            if (alone && stop_requested()) return;
            const std::size_t p = 3 * (std::size_t(y) * width + x);
            const int q = (y - y0) * tile + (x - x0);
            // The pixel's sums in registers, added to in the same order as
            // sample by sample into memory (the same bits), stored once.
            double s[3] = {0, 0, 0}, s2[3] = {0, 0, 0};
            if (pass > 0)
              for (int c = 0; c < 3; ++c) s[c] = sum[p + c], s2[c] = sum2[p + c];
            for (std::uint32_t index = first; index < last; ++index) {
              sampler.start_pixel_sample(std::uint32_t(x), std::uint32_t(y), index);
              const auto film = settings.pixel_centers ? std::array{0.5, 0.5} : sampler.get_pixel_2d();
              const double time = sampler.get_time();
              const auto lens = sampler.get_2d();
              const Ray ray = camera.generate(x + film[0], y + film[1], lens, time);
              const Vec3 l = integrator.radiance(ray, sampler);
              for (int c = 0; c < 3; ++c) {
                const double v = std::isfinite(l[c]) ? l[c] : 0.0;  // a NaN path counts as black
                s[c] += v;
                s2[c] += v * v;
              }
            }
            for (int c = 0; c < 3; ++c) tile_sum[q][c] = s[c], tile_sum2[q][c] = s2[c];
          }
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x) {
            const std::size_t p = 3 * (std::size_t(y) * width + x);
            const int q = (y - y0) * tile + (x - x0);
            for (int c = 0; c < 3; ++c) sum[p + c] = tile_sum[q][c], sum2[p + c] = tile_sum2[q][c];
          }
        tile_samples[std::size_t(t)] = last;
      } catch (const interrupted&) {
        if (!alone) throw;
      }
    });
    bool complete = true;
    for (int local = 0; local < my_tiles; ++local)
      complete = complete && tile_samples[std::size_t(tile_of(local))] == last;
    if (!complete) {  // stopped within the pass (alone only)
      stopped = true;
      break;
    }
    taken = last, passes_done = pass + 1;
    if (progress) progress(pass + 1, passes, elapsed());
    const bool out_of_time = settings.time_limit > 0 && elapsed() >= settings.time_limit;
    const bool stopping = stop_requested();
    if (distributed::any(out_of_time || stopping)) {  // every process stops after the same pass
      stopped = passes_done < passes && distributed::any(stopping);
      break;
    }
  }
  // Tile row r holds pixel rows [16r, min(16r + 16, height)): 3 sums each per pixel.
  const auto row_offset = [&](std::size_t r) {
    return 3 * std::size_t(width) * std::min<std::size_t>(tile * r, height);
  };
  distributed::gather_dealt({sum.get(), 3 * pixels}, std::size_t(tiles_y), row_offset);
  distributed::gather_dealt({sum2.get(), 3 * pixels}, std::size_t(tiles_y), row_offset);

  Image image;
  image.width = width;
  image.height = height;
  image.samples = taken;
  image.passes = passes_done;
  image.stopped = stopped;
  image.rgb.assign(3 * pixels, 0.0);
  image.variance.assign(3 * pixels, 0.0);
  std::size_t ahead = 0;  // tiles that finished the pass a stop cut short
  for (const std::uint32_t n : tile_samples) ahead += n > taken;
  image.partial_pass = stopped ? double(ahead) / double(tile_samples.size()) : 0.0;
  for (std::size_t i = 0; i < 3 * pixels; ++i) {
    const std::size_t pixel = i / 3, x = pixel % std::size_t(width), y = pixel / std::size_t(width);
    // Each pixel averages the samples its tile took (the same for all after a whole pass).
    const double n = alone ? tile_samples[y / tile * std::size_t(tiles_x) + x / tile] : taken;
    if (n > 0) image.rgb[i] = sum[i] / n;  // a tile a stop left unrendered stays black
    if (n > 1) image.variance[i] = std::max(0.0, (sum2[i] - n * image.rgb[i] * image.rgb[i]) / (n - 1)) / n;
  }
  image.seconds = elapsed();
  return image;
}

}  // namespace

double render_working_bytes(const Camera& camera) {
  // Per pixel and channel: the sums of L and L² while the Image's mean and variance are filled.
  return double(camera.width) * double(camera.height) * 3 * 4 * sizeof(double);
}

void require_render_memory(const Camera& camera, double extra_per_pixel, const std::string& what) {
  const double pixels = double(camera.width) * double(camera.height);
  require_memory(render_working_bytes(camera) + pixels * extra_per_pixel,
                 "a " + std::to_string(camera.width) + "x" + std::to_string(camera.height) + " " + what);
}

Image render(const Scene& scene, const RenderSettings& settings,
             const std::function<void(std::uint32_t, std::uint32_t, double)>& progress, const std::atomic<bool>* stop) {
  validate_settings(settings);
  require_render_memory(scene.camera, 0, "render (its sums, mean and variance per pixel)");
  const auto start = Clock::now();
  const Accelerator accelerator(scene);
  return render_from(start, accelerator, settings, progress, stop);
}

Image render(const Accelerator& accelerator, const RenderSettings& settings,
             const std::function<void(std::uint32_t, std::uint32_t, double)>& progress, const std::atomic<bool>* stop) {
  validate_settings(settings);
  require_render_memory(accelerator.scene().camera, 0, "render (its sums, mean and variance per pixel)");
  return render_from(Clock::now(), accelerator, settings, progress, stop);
}

}  // namespace stratum::render
