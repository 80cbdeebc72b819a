#pragma once
/// Measuring renders (LECTURE.md §2): each configuration against a
/// converged reference of the same estimand, by MSE, relative MSE, time
/// and efficiency = 1 / (MSE × seconds), with its ratio to the first
/// configuration (the baseline).
#include <nlohmann/json.hpp>
#include <limits>
#include <string>
#include <vector>

#include "stratum/render/render.hpp"

namespace stratum::render {

struct CompareConfig {
  std::string label;
  RenderSettings settings;
};

struct CompareRow {
  std::string label;
  std::uint32_t samples = 0;  ///< eye rays per pixel taken
  double mse = 0, relative_mse = 0, seconds = 0, efficiency = 0;
  double mse_ratio = 1, efficiency_ratio = 1;  ///< baseline / this for MSE; this / baseline for efficiency
  std::uint32_t passes = 1;                    ///< equal time: independent renders averaged (1 at equal samples)
  /// Where the error goes (analysis/image_spectrum.hpp): the power spectrum
  /// of the luminance of render − reference, normalized so white noise is 1;
  /// low_frequency_power is its mean below a quarter of Nyquist (< 1: blue
  /// noise). NaN and empty for images under 4 pixels a side.
  double low_frequency_power = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> error_radial_frequency, error_radial_power;
  std::string variance_path;  ///< where its variance image was written (CompareOptions::variance_dir)
};

/// How compare() runs, beyond the configurations.
struct CompareOptions {
  std::uint32_t reference_spp = 1024;
  std::string cache_dir = ".stratum-cache";
  /// Equal time: seconds of rendering per configuration (see
  /// render_equal_time); 0: equal samples, each configuration at its spp.
  double equal_time = 0;
  /// When set, each configuration's per-pixel variance image (Image::variance)
  /// is written there as <row index>-<label>.exr.
  std::string variance_dir;
};

/// The pictures behind a comparison, for callers that show them (the report).
struct CompareImages {
  std::vector<Image> images;     ///< one per configuration, in order
  Image reference;               ///< the first configuration's reference
  bool reference_cached = true;  ///< every reference was loaded from the cache
};

/// Names of the built-in comparisons, each with a one-line description.
const std::vector<std::pair<std::string, std::string>>& builtin_comparisons();

/// The configurations of built-in comparison `name` (throws invalid_argument
/// listing the names), with `threads` and `seed` applied.
std::vector<CompareConfig> builtin_comparison(const std::string& name, unsigned threads, std::uint64_t seed);

/// Configurations from JSON: [{"label": ..., "integrator": ..., "spp": ...,
/// "light_samples": ..., "light_strategy": ..., "hemisphere": ...,
/// "sampler": ..., "randomize": ..., "time_pattern": ..., "max_depth": ...}, ...]
std::vector<CompareConfig> parse_configs(const nlohmann::json& configs, unsigned threads, std::uint64_t seed);

/// The configurations' fields (keys, JSON types, ranges) read over
/// `defaults`, without the checks that need the registry, which
/// parse_configs adds (the sampler spec, validate_settings): what the fuzz
/// target reaches. Throws invalid_argument naming configs[i].KEY.
std::vector<CompareConfig> read_configs(const nlohmann::json& configs, const RenderSettings& defaults);

/// Sets the pixel sampler's name and randomizer from a sampler spec
/// (docs/samplers.md) with -p items and a separate randomizer folded in
/// (combine_sampler_options, which names the spec in errors).
void set_pixel_sampler(PixelSamplerSettings& settings, const std::string& spec, const std::vector<std::string>& params,
                       const std::string& randomize);

/// The converged reference for `settings`' estimand (integrator, depth,
/// scene, resolution): loaded from `cache_dir` when there, else rendered
/// with `spp` samples of owen-hash Sobol' (solid-angle light sampling,
/// 4 shadow rays) and stored as EXR. `scene_key` identifies the scene's
/// content. `cached` tells which happened. An entry is its image, its
/// variance image and a metadata file (X.json: size and FNV-1a fingerprint
/// of each), written atomically with the metadata last; an entry that does
/// not match its metadata is rendered again, with a warning in `warning`
/// (or on stderr when null). `progress` is render()'s, called for each pass of a render.
Image reference_image(const Scene& scene, const std::string& scene_key, const RenderSettings& settings,
                      std::uint32_t spp, const std::string& cache_dir, bool* cached = nullptr,
                      std::string* warning = nullptr,
                      const std::function<void(std::uint32_t, std::uint32_t, double)>& progress = {});

/// Mean squared error over pixels and channels, and the relative MSE
/// (each squared error over reference² + 0.01, as pbrt's imgtool).
double mean_squared_error(const Image& image, const Image& reference);
double relative_mean_squared_error(const Image& image, const Image& reference);

/// Runs every configuration and measures it against its reference.
std::vector<CompareRow> compare(const Scene& scene, const std::string& scene_key,
                                const std::vector<CompareConfig>& configs, std::uint32_t reference_spp,
                                const std::string& cache_dir);

/// Reads an image written by write_image (EXR) back (for cached references).
Image read_image(const std::string& path);

/// Where reference_image caches the reference for these arguments (the
/// variance image sits beside it, with ".variance.exr" for ".exr").
std::string reference_cache_path(const Scene& scene, const std::string& scene_key, const RenderSettings& settings,
                                 std::uint32_t spp, const std::string& cache_dir);

/// Runs every configuration, at equal samples or at equal time
/// (options.equal_time), and measures it against its reference; `images`,
/// when given, receives the renders and the first reference. The
/// configurations share one BVH, built before the first: a row's seconds
/// are its sampling and tracing, what the configurations differ in.
std::vector<CompareRow> compare(const Scene& scene, const std::string& scene_key,
                                const std::vector<CompareConfig>& configs, const CompareOptions& options,
                                CompareImages* images = nullptr);

/// Equal-time rendering (LECTURE.md §2: efficiency at equal cost): passes
/// of the configuration's spp samples per pixel until `seconds` have passed
/// (at least one; the pass that reaches the time finishes). Samplers whose
/// every point is uniform on its own (random; sobol with owen-hash) continue
/// one set per pixel (4096 samples; render's time_limit stops it), so a QMC
/// sequence keeps its convergence; any other sampler or time pattern takes
/// complete, independent renders (pass k > 0 with seed hash(seed, k)), each a
/// whole pattern, unbiased for stratified patterns too. The result is the
/// mean of all samples: samples = spp × passes, seconds the total wall time
/// (≥ `seconds`; the BVH, built beforehand, is not in it), variance that
/// of the mean.
Image render_equal_time(const Accelerator& accelerator, const RenderSettings& settings, double seconds,
                        std::uint32_t* passes = nullptr);

/// Writes `image.variance` (the variance of each pixel's mean, per channel)
/// as a linear EXR; `path` must end in .exr (checked before any work by
/// check_variance_path). Never half-written, as write_image.
void write_variance_image(const Image& image, const std::string& path);
/// The same into a prepared output's staging file (the caller commits).
void write_variance_image(const Image& image, io::OutputFile& file);
void check_variance_path(const std::string& argument, const std::string& path);

/// The luminance (Rec. 709 weights) of image − reference, per pixel, row-major.
std::vector<double> luminance_error(const Image& image, const Image& reference);

/// A fingerprint of everything in a scene that changes its image (camera,
/// materials, every shape's numbers and mesh, lights), as 16 hex digits:
/// the scene key of cached references, so an edited mesh file or another
/// resolution never hits a stale reference.
std::string scene_fingerprint(const Scene& scene);

/// The scene of a comparison and its key: the JSON scene at `path`, or
/// without one the built-in Cornell box with a pinhole camera and, unless
/// `keep_motion`, no moving shape (each comparison isolates its own
/// integral); `width`×`height` replace the camera's resolution.
struct ComparisonScene {
  Scene scene;
  std::string key;
  /// What the comparison's scene leaves out of the scene it was made from,
  /// for its output ("" when nothing): the built-in box's lens, its motion.
  std::string note;
};
ComparisonScene comparison_scene(const std::string& path, bool keep_motion, int width, int height);

}  // namespace stratum::render
