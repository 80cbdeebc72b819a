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
};

/// Quick: 32×32 with a 64-spp reference; full: 96×96 with a 1024-spp
/// reference (the reference spp of `stratum compare`).
RenderScale render_scale(const SectionContext& context);

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
RenderedComparison run_comparison(const render::ComparisonScene& scene, const std::vector<render::CompareConfig>& configs,
                                  std::uint32_t reference_spp, const std::string& cache_dir);

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

/// The table of a comparison: label, spp, MSE, relative MSE, seconds,
/// efficiency and the two ratios.
Table comparison_table(const RenderedComparison& comparison, const std::string& caption);

/// The comparison's measurements for report.json, by row label.
nlohmann::json comparison_numbers(const RenderedComparison& comparison);

}  // namespace stratum::report
