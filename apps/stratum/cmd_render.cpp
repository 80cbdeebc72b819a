/// `stratum render [SCENE.json]`: renders a scene (the built-in Cornell box
/// without one) and writes a PNG and optionally a linear EXR and the
/// per-pixel variance; `--reference` renders (or loads from the cache) the
/// converged reference of the same estimand instead.
#ifdef STRATUM_HAS_RENDER
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <optional>
#include <utility>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/distributed.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/render/render.hpp"
#include "stratum/render/render_job.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::cli {

namespace {

/// The command line's job (checked by prepare_render_job alone) and its outputs.
struct RenderOptions {
  std::string output = "render.png", exr, variance;
  render::RenderJob job;
  SamplerOptions sampler{"sobol"};
  bool quiet = false, progress = false;
};

void run_render(RenderOptions& options) {
  render::RenderJob& job = options.job;
  job.sampler = options.sampler.sampler;
  job.sampler_params = options.sampler.params;
  job.randomize = options.sampler.randomize;
  job.seed = options.sampler.seed;
  job.variance = options.variance;
  render::prepare_render_job(job);
  // Every output checked and staged before the render, not after it (docs/outputs.md).
  render::check_image_path("output", options.output);
  if (!options.exr.empty()) render::check_image_path("exr", options.exr);
  if (!options.variance.empty()) render::check_variance_path("variance", options.variance);
  io::OutputGroup outputs;
  io::OutputFile* png = outputs.add("output", options.output);
  io::OutputFile* exr = outputs.add("exr", options.exr);
  io::OutputFile* variance = outputs.add("variance", options.variance);
  outputs.prepare();
  std::vector<std::string> warnings;
  const render::Scene scene = render::job_scene(job, &warnings);
  for (const auto& warning : warnings) fmt::print(stderr, "stratum: warning: {}\n", warning);
  // One bar for the whole job: the passes end together on every rank of a
  // distributed job (each pass closes with a collective), so rank 0's count
  // is the job's and only rank 0 prints. On a terminal the bar redraws in
  // place; with --progress elsewhere (a log, mpirun's forwarded stderr) it
  // writes a line per pass.
  const bool terminal = isatty(STDERR_FILENO) != 0;
  const bool show = !options.quiet && distributed::is_root() && (terminal || options.progress);
  auto progress = [&](std::uint32_t done, std::uint32_t total, double seconds) {
    if (!show) return;
    const double eta = seconds / done * (total - done);
    fmt::print(stderr, "{}rendering: pass {}/{}  {:.1f} s  ETA {:.1f} s{}", terminal ? "\r" : "", done, total, seconds,
               eta, terminal ? "   " : "\n");
    if (terminal && done == total) fmt::print(stderr, "\n");
  };
  // A first Ctrl-C stops a render within a tile and keeps its partial
  // image (written below, then exit 130); a second one ends the process at
  // once, leaving no output (io::StopOnInterrupt).
  std::optional<io::StopOnInterrupt> stop_keeps_work;
  if (!job.reference) stop_keeps_work.emplace();
  const render::RenderJobResult result = render::run_render_job(job, scene, progress, &interrupt_flag());
  const render::Image& image = result.image;
  const bool cached = result.cached;
  if (job.reference)
    fmt::print(stderr, "stratum: reference ({} spp) {} {}\n", job.reference_spp,
               cached ? "loaded from the cache" : "rendered and cached in", result.cache_entry);
  render::write_image(image, *png);
  if (exr) render::write_image(image, *exr);
  if (variance) render::write_variance_image(image, *variance);
  outputs.commit();  // all or none: a failure here removes the outputs committed before it
  if (image.stopped) {
    if (show) fmt::print(stderr, "\n");
    throw interrupted(fmt::format(
        "stopped by Ctrl-C: {} holds the {} of {} passes completed ({} of {} spp per pixel{})", options.output,
        image.passes, std::clamp<std::uint32_t>(job.settings.passes, 1, job.settings.sampler.spp), image.samples,
        job.settings.sampler.spp,
        image.partial_pass > 0 ? fmt::format("; {:.0f}% of the tiles also the next pass", 100 * image.partial_pass)
                               : ""));
  }
  if (!options.quiet)
    fmt::print("{}: {}x{}, {} spp, {:.2f} s{}\n", options.output, image.width, image.height, image.samples,
               image.seconds, job.reference ? (cached ? " (reference, cached)" : " (reference)") : "");
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  auto& s = options->job.settings;
  auto* command = app.add_subcommand("render", "Render a scene (the built-in Cornell box without SCENE)");
  command->add_option("scene", options->job.scene, "JSON scene file (docs/scenes.md)");
  command->add_option("-o,--output", options->output, "tonemapped sRGB image (.png)")->capture_default_str();
  command->add_option("--exr", options->exr, "also write the linear image (.exr)");
  command->add_option("--spp", options->job.spp, "eye rays per pixel")->capture_default_str();
  command->add_option("--integrator", s.integrator, "direct|irradiance|path")->capture_default_str();
  command->add_option("--light-samples", s.light_samples, "shadow rays per eye ray (M)")->capture_default_str();
  command->add_option("--light-strategy", s.light_strategy, "area|solid-angle|projected-solid-angle|bsdf|mis")
      ->capture_default_str();
  command->add_option("--hemisphere", s.hemisphere, "irradiance sampling: uniform|cosine")->capture_default_str();
  command->add_option("--max-depth", s.max_depth, "longest path")->capture_default_str();
  add_sampler_options(*command, options->sampler,
                      "the pixel sampler: any registry sampler that takes spp points (latin-square: its first two "
                      "coordinates; the space-time patterns are --time-pattern)",
                      "seed")
      ->capture_default_str();
  command->add_option("--time-pattern", s.sampler.time_pattern, "random|cook|magic-square (spp = m^2)");
  command
      ->add_option("--frame", options->job.frame,
                   "animation frame K: continues each pixel's sequence (samples K*spp..) for a progressive "
                   "sampler, a fresh seed otherwise (docs/render.md)")
      ->capture_default_str();
  add_threads_option(*command, s.threads, "threads");
  command->add_option("--passes", s.passes, "progressive passes")->capture_default_str();
  command->add_option("--time-limit", s.time_limit, "seconds; stops after the pass that reaches it (0: none)");
  command->add_option("--width", options->job.width, "override the scene's image width");
  command->add_option("--height", options->job.height, "override the scene's image height");
  command->add_option("--variance", options->variance, "also write the variance of each pixel's mean (.exr)");
  command->add_flag("--reference", options->job.reference,
                    "render the converged reference of this estimand (Owen-scrambled Sobol', cached) instead");
  command->add_option("--reference-spp", options->job.reference_spp, "samples per pixel of --reference")
      ->capture_default_str();
  command->add_option("--cache", options->job.cache, "folder of cached references")->capture_default_str();
  command->add_flag("-q,--quiet", options->quiet, "no progress bar or summary");
  command->add_flag("--progress", options->progress,
                    "show the progress even when stderr is not a terminal: a line per pass (under mpirun: rank 0's, "
                    "for the whole job)");
  command->callback([options] { run_render(*options); });
}

}  // namespace stratum::cli
#endif
