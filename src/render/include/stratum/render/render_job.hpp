#pragma once
/// A render as a face asks for it (`stratum render`, stratum.render()): the
/// counts, sizes and sampler spec a user types, checked here and only here,
/// so that the CLI and Python pass them through and cannot disagree.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stratum/render/compare.hpp"
#include "stratum/render/compare_repeated.hpp"
#include "stratum/render/render.hpp"
#include "stratum/render/scene.hpp"

namespace stratum::render {

struct RenderJob {
  std::string scene;                          ///< a JSON scene file (docs/scenes.md); empty: the built-in Cornell box
  std::optional<std::int64_t> width, height;  ///< given: replace the scene's, in [1, 16384]
  std::int64_t spp = 16;                      ///< eye rays per pixel, [1, 2^24]
  std::int64_t frame = 0;                     ///< animation frame, [0, 2^32 − 1] with (frame + 1)·spp ≤ 2^32
  std::string sampler = "sobol";              ///< a sampler spec (docs/samplers.md)
  std::vector<std::string> sampler_params;    ///< the spec's parameters given apart (-p KEY=VALUE items)
  std::string randomize;                      ///< the spec's :RANDOMIZER given apart (--randomize)
  std::uint64_t seed = 0;
  bool reference = false;             ///< render the converged reference of this estimand instead (cached)
  std::int64_t reference_spp = 1024;  ///< [1, 2^24]
  std::string cache = ".stratum-cache";
  /// Non-empty: the caller wants the variance of each pixel's mean (needs
  /// spp ≥ 2, or a cached reference that has it); the text says how it was
  /// asked for, in messages (the CLI's --variance path, Python's True).
  std::string variance;
  std::string variance_argument = "variance";  ///< its name in messages (Python's with_variance)
  /// Everything else (integrator, light sampling, threads, passes, …);
  /// `settings.sampler` is filled in by prepare_render_job.
  RenderSettings settings;
};

/// Checks every field (the message names the argument as the CLI spells
/// it, its value and what is allowed: stratum::invalid_argument) and fills
/// job.settings.sampler from the spec, seed, spp and frame.
void prepare_render_job(RenderJob& job);

/// The job's scene: loaded (or the built-in box) with width and height applied.
Scene job_scene(const RenderJob& job, std::vector<std::string>* warnings = nullptr);

/// What run_render_job did.
struct RenderJobResult {
  Image image;
  bool cached = false;      ///< a reference loaded from the cache
  std::string cache_entry;  ///< the reference's file in the cache (reference jobs)
};

/// Renders a prepared job's scene (or loads or renders its reference);
/// `progress` and `stop` as render()'s. Refuses (invalid_argument naming
/// "variance") a with_variance job whose cached reference has no variances.
RenderJobResult run_render_job(const RenderJob& job, const Scene& scene,
                               const std::function<void(std::uint32_t, std::uint32_t, double)>& progress = {},
                               const std::atomic<bool>* stop = nullptr);

/// A comparison as `stratum compare` and stratum.compare() ask for it,
/// checked by run_compare_job alone.
struct CompareJob {
  std::string scene;    ///< a JSON scene file; empty: the built-in Cornell box (docs/render.md)
  std::string builtin;  ///< a built-in comparison; empty: "shadow-rays" unless `configs` is given
  std::optional<std::string>
      configs;  ///< configurations as JSON text (docs/render.md); absent: the built-in comparison
  std::string configs_origin = "(the configs given)";  ///< where `configs` came from, for messages (a file)
  std::int64_t reference_spp = 1024;                   ///< [1, 2^24]
  std::int64_t width = 64, height = 64;                ///< [1, 16384]
  std::int64_t repeats = 1;                            ///< seeds per configuration, [1, 1000]
  std::optional<double> confidence;                    ///< in (0, 1), with repeats ≥ 2; default 0.95
  unsigned threads = 1;
  std::uint64_t seed = 0;
  CompareOptions options;  ///< cache, equal time, variance images (reference_spp is set from the job)
};

/// What run_compare_job measured, and of which scene.
struct CompareJobResult {
  RepeatedCompare repeated;
  std::string scene_name;
  std::string scene_note;  ///< what the comparison's scene leaves out ("" when nothing)
  double confidence = 0.95;
};

/// Checks the job (invalid_argument naming the argument as the CLI spells
/// it), builds its configurations and scene, and runs the comparison.
CompareJobResult run_compare_job(const CompareJob& job);

}  // namespace stratum::render
