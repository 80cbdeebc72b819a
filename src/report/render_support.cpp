#include "render_support.hpp"

#include <fmt/core.h>

#include <cmath>

#include "sections.hpp"
#include "stratum/util/error.hpp"

namespace stratum::report {

RenderScale render_scale(const SectionContext& context) {
  return context.quick() ? RenderScale{32, 32, 64} : RenderScale{96, 96, 1024};
}

RenderedComparison run_comparison(const render::ComparisonScene& scene, const std::vector<render::CompareConfig>& configs,
                                  std::uint32_t reference_spp, const std::string& cache_dir) {
  render::CompareOptions options;
  options.reference_spp = reference_spp;
  options.cache_dir = cache_dir;
  render::CompareImages pictures;
  RenderedComparison result;
  result.rows = render::compare(scene.scene, scene.key, configs, options, &pictures);
  result.images = std::move(pictures.images);
  result.reference = std::move(pictures.reference);
  result.reference_cached = pictures.reference_cached;
  result.reference_spp = reference_spp;
  double sum = 0;
  for (const double v : result.reference.variance) sum += v;
  result.reference_variance = result.reference.variance.empty() ? 0 : sum / double(result.reference.variance.size());
  return result;
}

double masked_mean_squared_error(const render::Image& image, const render::Image& reference, const std::vector<bool>& mask) {
  require(image.rgb.size() == reference.rgb.size() && mask.size() * 3 == image.rgb.size(), "mask", mask.size(),
          "must hold one flag per pixel of images of equal size");
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < mask.size(); ++p) {
    if (!mask[p]) continue;
    for (int c = 0; c < 3; ++c) {
      const double e = image.rgb[3 * p + c] - reference.rgb[3 * p + c];
      sum += e * e;
    }
    count += 3;
  }
  return count == 0 ? 0 : sum / double(count);
}

double mean_sample_variance(const render::Image& image) {
  if (image.variance.empty()) return 0;
  double sum = 0;
  for (const double v : image.variance) sum += v;
  return sum / double(image.variance.size()) * image.samples;
}

nlohmann::json image_panel(const render::Image& image, const std::string& title) {
  std::vector<double> rgb(image.rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = std::isfinite(image.rgb[i]) ? std::round(image.rgb[i] * 1e4) / 1e4 : 0;
  return {{"title", title}, {"width", image.width}, {"height", image.height}, {"rgb", rgb}};
}

Figure image_figure(SectionContext& context, const nlohmann::json& panels, const std::string& name,
                    const std::string& caption, int columns) {
  nlohmann::json data = {{"panels", panels}};
  if (columns > 0) data["columns"] = columns;
  return context.plot("report_images", std::move(data), name, caption);
}

nlohmann::json comparison_panels(const RenderedComparison& comparison) {
  nlohmann::json panels = nlohmann::json::array();
  panels.push_back(image_panel(comparison.reference, fmt::format("reference ({} spp)", comparison.reference_spp)));
  for (std::size_t i = 0; i < comparison.rows.size(); ++i)
    panels.push_back(image_panel(comparison.images[i], fmt::format("{}\nMSE {}", comparison.rows[i].label,
                                                                   format_number(comparison.rows[i].mse))));
  return panels;
}

Table comparison_table(const RenderedComparison& comparison, const std::string& caption) {
  Table table{caption,
              {"configuration", "eye rays/pixel", "MSE", "relative MSE", "seconds", "efficiency 1/(MSE·s)",
               "MSE ratio (first/this)", "efficiency ratio (this/first)"},
              {}};
  for (const render::CompareRow& row : comparison.rows)
    table.rows.push_back({row.label, std::to_string(row.samples), format_number(row.mse), format_number(row.relative_mse),
                          format_number(row.seconds), format_number(row.efficiency), format_number(row.mse_ratio),
                          format_number(row.efficiency_ratio)});
  return table;
}

nlohmann::json comparison_numbers(const RenderedComparison& comparison) {
  nlohmann::json rows = nlohmann::json::object();
  for (std::size_t i = 0; i < comparison.rows.size(); ++i) {
    const render::CompareRow& row = comparison.rows[i];
    rows[row.label] = {{"spp", row.samples},
                       {"mse", row.mse},
                       {"relative_mse", row.relative_mse},
                       {"seconds", row.seconds},
                       {"efficiency", row.efficiency},
                       {"mse_ratio", row.mse_ratio},
                       {"efficiency_ratio", row.efficiency_ratio},
                       {"sample_variance", mean_sample_variance(comparison.images[i])}};
  }
  return {{"width", comparison.reference.width},
          {"height", comparison.reference.height},
          {"reference_spp", comparison.reference_spp},
          {"reference_cached", comparison.reference_cached},
          {"reference_variance", comparison.reference_variance},
          {"rows", rows}};
}

}  // namespace stratum::report
