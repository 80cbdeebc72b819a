#pragma once
/// What the render-based sections of the report (§1 camera, §2 variance,
/// §3 importance, §8 space-time, §9 path tracing) share: the image size and
/// reference quality for quick and full runs, a comparison that keeps its
/// images (render::compare measures the same way but keeps only the rows),
/// and figures of renders side by side (report_images.py).
#include <cstdint>
#include <string>
#include <vector>

#include "section_context.hpp"
#include "stratum/render/compare.hpp"

namespace stratum::report {

/// Image size and reference samples of a section's comparisons.
struct RenderScale {
  int width = 0, height = 0;
  std::uint32_t reference_spp = 0;
  /// Enough for comparisons whose renders take at most 64 light samples
  /// per pixel (picture_scale: 4 light samples per reference spp).
  std::uint32_t few_samples_reference_spp = 0;
};

/// Quick: 32×32 with a 64-spp reference; full: 96×96 with a 1024-spp
/// reference (the reference spp of `stratum compare`).
RenderScale render_scale(const SectionContext& context);

/// The pictures of §1-3, made to be looked at: quick 32×32 with 64-spp
/// references; full 256×256 with a 256-spp reference (of owen-hash Sobol',
/// 4 shadow rays each: 1024 light samples per pixel, for renders of 400)
/// and, for renders of at most 64 light samples per pixel, a 64-spp one
/// (256 light samples, whose variance is a few percent of theirs).
RenderScale picture_scale(const SectionContext& context);

/// The comparison box (pinhole, nothing moving) with its ceiling light
/// grown from 130 × 105 mm to 300 × 300 mm about the same centre, its
/// radiance scaled down by the areas' ratio (the same power): shadows with
/// wide penumbras, and near the light a strong variation of the 1/r² and
/// cosine factors over the light, where light sampling strategies differ.
render::ComparisonScene large_light_box(int width, int height);

/// A region where a picture's effect lives, in fractions of the image
/// (so that it scales with the image), and what it shows.
struct Crop {
  double x = 0, y = 0, width = 0, height = 0;  ///< top-left corner and size, fractions of the image
  std::string label;                           ///< "penumbra", "focus plane", …
};

/// A crop in whole pixels of a `width`×`height` image (at least one pixel).
struct PixelBox {
  int x = 0, y = 0, width = 1, height = 1;
};
PixelBox crop_pixels(const Crop& crop, int width, int height);

/// The pixels of `box` (its mean and variance) as an image of their own.
render::Image crop_image(const render::Image& image, const PixelBox& box);

/// |luminance(image) − luminance(other)| per pixel, row-major.
std::vector<double> absolute_difference(const render::Image& image, const render::Image& other);

/// The same of the values as displayed: each channel clamped to [0, 1] and
/// sRGB-encoded, as the PNG shows it (so that a bright light's blurred edge
/// does not outshine every other difference).
std::vector<double> displayed_difference(const render::Image& image, const render::Image& other);

/// The square window of side `fraction` × the image's shorter side that
/// holds the largest sum of `weight` (width·height, row-major; the first
/// such from the top left), as a crop: where an effect is largest.
Crop heaviest_window(const std::vector<double>& weight, int width, int height, double fraction,
                     const std::string& label);

/// Per-pixel flags of the pixels inside `box` (for masked_mean_squared_error).
std::vector<bool> box_mask(const PixelBox& box, int width, int height);

/// A column of a picture grid: an image and its title.
struct GridColumn {
  const render::Image* image = nullptr;
  std::string title;
};

/// A grid of report_images.py panels, one column per image: the renders
/// with every crop outlined, then one row per crop (the crop enlarged),
/// then, when `baseline` is given, the heat map of |luminance − baseline's|
/// on one colour scale (the 99th percentile of the row's differences;
/// blank under the baseline itself) with `difference_title` above it;
/// `displayed`: of the displayed values (displayed_difference).
/// The grid is columns.size() wide.
nlohmann::json picture_grid(const std::vector<GridColumn>& columns, const std::vector<Crop>& crops,
                            const render::Image* baseline, const std::string& difference_title, bool displayed = false);

/// A render's mean squared error against `reference` and its mean
/// per-sample variance inside `box`.
struct RegionError {
  double mse = 0, sample_variance = 0;
};
RegionError region_error(const render::Image& image, const render::Image& reference, const PixelBox& box);

/// Configurations rendered and measured against a converged reference of
/// their estimand (cached in the context's cache folder).
struct RenderedComparison {
  std::vector<render::CompareRow> rows;  ///< ratios against the first row
  std::vector<render::Image> images;     ///< one per row
  render::Image reference;               ///< of the first row's estimand
  std::uint32_t reference_spp = 0;
  bool reference_cached = false;  ///< loaded from the cache (every estimand)
  /// Mean over pixels and channels of the reference's own variance of the
  /// mean: the floor under every MSE (MSE ≈ variance + this).
  double reference_variance = 0;
};

/// Renders each configuration of `configs` on `scene` and measures it with
/// render::compare (MSE, relative MSE, seconds, efficiency = 1 / (MSE ×
/// seconds), ratios to the first row), keeping the images for the figures.
/// `equal_time` > 0: each configuration renders passes until that many
/// seconds (render::CompareOptions::equal_time).
RenderedComparison run_comparison(const render::ComparisonScene& scene,
                                  const std::vector<render::CompareConfig>& configs, std::uint32_t reference_spp,
                                  const std::string& cache_dir, double equal_time = 0);

/// Mean squared error over the pixels flagged in `mask` (width·height).
double masked_mean_squared_error(const render::Image& image, const render::Image& reference,
                                 const std::vector<bool>& mask);

/// Mean over pixels and channels of Image::variance (the variance of each
/// pixel's mean) times the samples per pixel: the per-sample variance.
double mean_sample_variance(const render::Image& image);

/// A panel of report_images.py: the linear image (rounded to 4 decimals)
/// and its title.
nlohmann::json image_panel(const render::Image& image, const std::string& title);

/// A row (or grid, `columns` wide) of renders drawn with nearest-neighbour
/// upscaling, each with its title.
Figure image_figure(SectionContext& context, const nlohmann::json& panels, const std::string& name,
                    const std::string& caption, int columns = 0);

/// Panels of a comparison: the reference, then every row with its MSE.
nlohmann::json comparison_panels(const RenderedComparison& comparison);

/// A comparison as a picture grid: the reference, then every row with its
/// MSE; the heat maps show |render − reference|.
nlohmann::json comparison_grid(const RenderedComparison& comparison, const std::vector<Crop>& crops);

/// The table of a comparison: label, spp, MSE, relative MSE, seconds,
/// efficiency and the two ratios.
Table comparison_table(const RenderedComparison& comparison, const std::string& caption);

/// The comparison's measurements for report.json, by row label.
nlohmann::json comparison_numbers(const RenderedComparison& comparison);

}  // namespace stratum::report
