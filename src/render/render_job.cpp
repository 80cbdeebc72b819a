#include "stratum/render/render_job.hpp"

#include <charconv>

#include "stratum/io/json.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {

namespace {
constexpr std::int64_t max_spp = std::int64_t{1} << 24;
constexpr std::int64_t max_side = 16384;

/// An image width or height, the same rule and words for render and compare.
void check_image_side(const char* argument, std::int64_t value) {
  require(value >= 1 && value <= max_side, argument, value,
          "must be an integer in [1, " + std::to_string(max_side) + "]");
}

/// --reference-spp, read alike by render and compare.
void check_reference_spp(std::int64_t spp) {
  require(spp >= 1 && spp <= max_spp, "reference-spp", spp, "must be in [1, 2^24]");
}

/// A real as its shortest round-trip decimal (0.9, not 0.90000000000000002).
std::string shortest(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return {text, end};
}
}  // namespace

void prepare_render_job(RenderJob& job) {
  require(job.spp >= 1 && job.spp <= max_spp, "spp", job.spp, "must be in [1, 2^24]");
  RenderSettings& s = job.settings;
  s.sampler.spp = static_cast<std::uint32_t>(job.spp);
  set_pixel_sampler(s.sampler, job.sampler, job.sampler_params, job.randomize);
  s.sampler.seed = job.seed;
  require(job.frame >= 0 && job.frame <= std::int64_t{0xffffffff}, "frame", job.frame,
          "must be an integer in [0, 2^32 - 1] with (frame + 1) * spp <= 2^32");
  s.sampler.frame = static_cast<std::uint32_t>(job.frame);
  validate_settings(s);
  // Each given size replaces the scene's; 0 is not "unset".
  if (job.width) check_image_side("width", *job.width);
  if (job.height) check_image_side("height", *job.height);
  require(job.variance.empty() || job.reference || job.spp >= 2, job.variance_argument, job.variance,
          "needs spp 2 or more: a pixel's variance is estimated from its samples (this render takes " +
              std::to_string(job.spp) + ")");
  check_reference_spp(job.reference_spp);
}

Scene job_scene(const RenderJob& job, std::vector<std::string>* warnings) {
  Scene scene = job.scene.empty() ? cornell_box() : load_scene(job.scene, warnings);
  if (job.width) scene.camera.width = static_cast<int>(*job.width);
  if (job.height) scene.camera.height = static_cast<int>(*job.height);
  return scene;
}

RenderJobResult run_render_job(const RenderJob& job, const Scene& scene,
                               const std::function<void(std::uint32_t, std::uint32_t, double)>& progress,
                               const std::atomic<bool>* stop) {
  RenderJobResult result;
  if (job.reference) {
    const std::string key = scene_fingerprint(scene);
    const auto spp = static_cast<std::uint32_t>(job.reference_spp);
    result.image = reference_image(scene, key, job.settings, spp, job.cache, &result.cached, nullptr, progress);
    result.cache_entry = reference_cache_path(scene, key, job.settings, spp, job.cache);
  } else {
    result.image = render(scene, job.settings, progress, stop);
  }
  require(job.variance.empty() || result.image.variance.size() == result.image.rgb.size(), job.variance_argument,
          job.variance,
          "needs per-pixel variances: the cached reference " + result.cache_entry +
              " has none (delete it to render it again)");
  return result;
}

CompareJobResult run_compare_job(const CompareJob& job) {
  require(job.builtin.empty() || !job.configs, "configs", job.configs_origin,
          "give a built-in comparison or configurations, not both (builtin " + job.builtin + ")");
  check_reference_spp(job.reference_spp);
  check_image_side("width", job.width);
  check_image_side("height", job.height);
  require(job.repeats >= 1 && job.repeats <= 1000, "repeats", job.repeats, "must be in [1, 1000]");
  if (job.confidence)
    require(job.repeats >= 2, "confidence", shortest(*job.confidence),
            "applies with repeats 2 or more (intervals over the repeats' seeds)");
  CompareJobResult result;
  result.confidence = job.confidence.value_or(0.95);
  require(result.confidence > 0 && result.confidence < 1, "confidence", shortest(result.confidence),
          "must be in (0, 1)");
  const std::string builtin = job.builtin.empty() ? "shadow-rays" : job.builtin;
  const auto configs =
      job.configs ? parse_configs(io::parse_json(*job.configs, "configs", job.configs_origin), job.threads, job.seed)
                  : builtin_comparison(builtin, job.threads, job.seed);
  // Motion only for the time-pattern comparison: each isolates its own integral.
  const bool keep_motion = !job.configs && builtin == "time-pattern";
  const ComparisonScene prepared =
      comparison_scene(job.scene, keep_motion, static_cast<int>(job.width), static_cast<int>(job.height));
  CompareOptions options = job.options;
  options.reference_spp = static_cast<std::uint32_t>(job.reference_spp);
  result.repeated = compare_repeated(prepared.scene, prepared.key, configs, options, static_cast<unsigned>(job.repeats),
                                     result.confidence);
  result.scene_name = prepared.scene.name;
  result.scene_note = prepared.note;
  return result;
}

}  // namespace stratum::render
