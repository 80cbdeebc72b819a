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
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::cli {

namespace {

struct RenderOptions {
  std::string scene, output = "render.png", exr, variance, cache = ".stratum-cache";
  render::RenderSettings settings;
  SamplerOptions sampler{"sobol"};
  std::int64_t spp = 16, reference_spp = 1024, frame = 0;
  std::optional<std::int64_t> width, height;  ///< given: overrides the scene's
  bool quiet = false, reference = false, progress = false;
};

void run_render(RenderOptions& options) {
  require(options.spp >= 1 && options.spp <= (std::int64_t{1} << 24), "spp", options.spp, "must be in [1, 2^24]");
  options.settings.sampler.spp = static_cast<std::uint32_t>(options.spp);
  render::set_pixel_sampler(options.settings.sampler, "sampler", options.sampler.sampler, options.sampler.params,
                            options.sampler.randomize);
  options.settings.sampler.seed = options.sampler.seed;
  require(options.frame >= 0 && options.frame <= std::int64_t{0xffffffff}, "frame", options.frame,
          "must be an integer in [0, 2^32 - 1] with (frame + 1) * spp <= 2^32");
  options.settings.sampler.frame = static_cast<std::uint32_t>(options.frame);
  render::validate_settings(options.settings);
  // Each given size overrides the scene's (as stratum.render's width= and height=); 0 is not "unset".
  for (const auto& [name, size] : {std::pair{"width", options.width}, std::pair{"height", options.height}})
    require(!size || (*size >= 1 && *size <= 16384), name, size.value_or(0), "must be an integer in [1, 16384]");
  require(options.variance.empty() || options.reference || options.spp >= 2, "variance", options.variance,
          "needs --spp 2 or more: a pixel's variance is estimated from its samples (this render takes " +
              std::to_string(options.spp) + ")");
  require(options.reference_spp >= 1 && options.reference_spp <= (std::int64_t{1} << 24), "reference-spp",
          options.reference_spp, "must be in [1, 2^24]");
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
  render::Scene scene = options.scene.empty() ? render::cornell_box() : render::load_scene(options.scene, &warnings);
  for (const auto& warning : warnings) fmt::print(stderr, "stratum: warning: {}\n", warning);
  if (options.width) scene.camera.width = static_cast<int>(*options.width);
  if (options.height) scene.camera.height = static_cast<int>(*options.height);
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
  render::Image image;
  bool cached = false;
  if (options.reference) {
    const std::string key = render::scene_fingerprint(scene), spp_text = std::to_string(options.reference_spp);
    const auto spp = std::uint32_t(options.reference_spp);
    image = render::reference_image(scene, key, options.settings, spp, options.cache, &cached, nullptr, progress);
    fmt::print(stderr, "stratum: reference ({} spp) {} {}\n", spp_text,
               cached ? "loaded from the cache" : "rendered and cached in",
               render::reference_cache_path(scene, key, options.settings, spp, options.cache));
  } else {
    // A first Ctrl-C stops the render within a tile and keeps its partial
    // image (written below, then exit 130); a second one ends the process at
    // once, leaving no output (io::StopOnInterrupt).
    io::StopOnInterrupt stop_keeps_work;
    image = render::render(scene, options.settings, progress, &interrupt_flag());
  }
  require(options.variance.empty() || image.variance.size() == image.rgb.size(), "variance", options.variance,
          "needs per-pixel variances: this cached reference has none (delete it from --cache to render it again)");
  render::write_image(image, *png);
  if (exr) render::write_image(image, *exr);
  if (variance) render::write_variance_image(image, *variance);
  outputs.commit();  // all or none: a failure here removes the outputs committed before it
  if (image.stopped) {
    if (show) fmt::print(stderr, "\n");
    throw interrupted(fmt::format(
        "stopped by Ctrl-C: {} holds the {} of {} passes completed ({} of {} spp per pixel{})", options.output,
        image.passes, std::clamp<std::uint32_t>(options.settings.passes, 1, options.settings.sampler.spp),
        image.samples, options.settings.sampler.spp,
        image.partial_pass > 0 ? fmt::format("; {:.0f}% of the tiles also the next pass", 100 * image.partial_pass)
                               : ""));
  }
  if (!options.quiet)
    fmt::print("{}: {}x{}, {} spp, {:.2f} s{}\n", options.output, image.width, image.height, image.samples,
               image.seconds, options.reference ? (cached ? " (reference, cached)" : " (reference)") : "");
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  auto& s = options->settings;
  auto* command = app.add_subcommand("render", "Render a scene (the built-in Cornell box without SCENE)");
  command->add_option("scene", options->scene, "JSON scene file (docs/scenes.md)");
  command->add_option("-o,--output", options->output, "tonemapped sRGB image (.png)")->capture_default_str();
  command->add_option("--exr", options->exr, "also write the linear image (.exr)");
  command->add_option("--spp", options->spp, "eye rays per pixel")->capture_default_str();
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
      ->add_option("--frame", options->frame,
                   "animation frame K: continues each pixel's sequence (samples K*spp..) for a progressive "
                   "sampler, a fresh seed otherwise (docs/render.md)")
      ->capture_default_str();
  add_threads_option(*command, s.threads, "threads");
  command->add_option("--passes", s.passes, "progressive passes")->capture_default_str();
  command->add_option("--time-limit", s.time_limit, "seconds; stops after the pass that reaches it (0: none)");
  command->add_option("--width", options->width, "override the scene's image width");
  command->add_option("--height", options->height, "override the scene's image height");
  command->add_option("--variance", options->variance, "also write the variance of each pixel's mean (.exr)");
  command->add_flag("--reference", options->reference,
                    "render the converged reference of this estimand (Owen-scrambled Sobol', cached) instead");
  command->add_option("--reference-spp", options->reference_spp, "samples per pixel of --reference")
      ->capture_default_str();
  command->add_option("--cache", options->cache, "folder of cached references")->capture_default_str();
  command->add_flag("-q,--quiet", options->quiet, "no progress bar or summary");
  command->add_flag("--progress", options->progress,
                    "show the progress even when stderr is not a terminal: a line per pass (under mpirun: rank 0's, "
                    "for the whole job)");
  command->callback([options] { run_render(*options); });
}

}  // namespace stratum::cli
#endif
