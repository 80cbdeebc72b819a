/// §2 Variance and its cost: soft shadows with 1 and with 16 shadow rays
/// per eye ray (render::builtin_comparison("shadow-rays"): 4 eye rays per
/// pixel through the pixel centres, so that only the light integral
/// varies), in the Cornell box with its light grown to 300 × 300 mm
/// (large_light_box) so that the shadows are wide penumbras. Each render is
/// measured against a converged reference by MSE, over the image and inside
/// a penumbra, with its time and efficiency 1 / (MSE × seconds)
/// (Hammersley, Handscomb 1964, "Monte Carlo Methods", §5.1), over several
/// seeds with both configurations paired on each (repeated_comparison.hpp):
/// the ratios come with intervals, and an efficiency ratio only where the
/// times differ beyond their noise.
#include <fmt/core.h>

#include "render_support.hpp"
#include "repeated_comparison.hpp"
#include "sections.hpp"

namespace stratum::report {

namespace {

/// The floor between the sphere and the short block, in the penumbras of
/// both (see the figure).
const Crop penumbra{0.32, 0.72, 0.25, 0.25, "penumbra"};

}  // namespace

Section variance_section(SectionContext& context) {
  Section section = context.start();
  const RenderScale scale = picture_scale(context);
  const auto scene = large_light_box(scale.width, scale.height);
  const auto configs = render::builtin_comparison("shadow-rays", context.threads(), context.seed());
  render::CompareOptions options;
  options.reference_spp = scale.few_samples_reference_spp;
  options.cache_dir = context.cache_dir();
  const unsigned repeats = context.quick() ? 3 : 6;
  const RepeatedComparison comparison = run_repeated_comparison(scene, configs, options, repeats);
  const std::vector<RowStatistics> statistics = row_statistics(comparison, comparison.mse);
  const std::string& one = comparison.labels.at(0);
  const std::string& sixteen = comparison.labels.at(1);
  const RowStatistics& sixteen_row = statistics.at(1);
  const std::uint32_t eye_rays = comparison.samples.at(0).at(0);
  const std::string method = interval_method(repeats);

  section.figures.push_back(image_figure(
      context, repeated_grid(comparison, {penumbra}), "shadow-rays",
      fmt::format("Soft shadows under a 300 × 300 mm light, {}×{} pixels, {} eye rays per pixel through the pixel "
                  "centres: the reference, 1 shadow ray and 16 shadow rays per eye ray (first seed); below, the "
                  "penumbra outlined above, enlarged, and each render's error",
                  scale.width, scale.height, eye_rays),
      3));
  section.tables.push_back(repeated_table(
      comparison, statistics,
      fmt::format("1 vs 16 shadow rays against a {}-spp reference ({})", comparison.reference_spp, method)));
  section.tables.back().id = "shadow-rays";
  section.numbers = repeated_numbers(comparison, statistics);

  // Inside the penumbra, where the light is partly hidden and a shadow ray's
  // answer is a coin toss: the MSE of each seed over the crop, and the
  // per-sample variance of the first seed's pixels.
  const PixelBox box = crop_pixels(penumbra, scale.width, scale.height);
  const std::vector<bool> mask = box_mask(box, scale.width, scale.height);
  std::vector<std::vector<double>> penumbra_mse(configs.size());
  for (const auto& images : comparison.images)
    for (std::size_t c = 0; c < images.size(); ++c)
      penumbra_mse[c].push_back(masked_mean_squared_error(images[c], comparison.reference, mask));
  const std::vector<RowStatistics> local = row_statistics(comparison, penumbra_mse);
  Table region{
      fmt::format("Inside the penumbra outlined in the figure ({} seeds; per-sample variance of the first)", repeats),
      {"configuration", "pixels", "MSE (mean ± s.e.)", "per-sample variance", "MSE ratio (1 ray / this)"},
      {}};
  for (std::size_t c = 0; c < configs.size(); ++c) {
    const RegionError first = region_error(comparison.images[0][c], comparison.reference, box);
    region.rows.push_back({comparison.labels[c], std::to_string(box.width * box.height),
                           format_number(local[c].mse.mean) + " ± " + format_number(local[c].mse.standard_error, 2),
                           format_number(first.sample_variance),
                           c == 0 ? "1 (baseline)" : format_interval(local[c].mse_ratio)});
    section.numbers["penumbra"][comparison.labels[c]] = {{"mse_per_seed", penumbra_mse[c]},
                                                         {"mse_mean", local[c].mse.mean},
                                                         {"mse_standard_error", local[c].mse.standard_error},
                                                         {"mse_ratio", interval_json(local[c].mse_ratio)},
                                                         {"sample_variance", first.sample_variance}};
  }
  section.numbers["penumbra"]["box"] = {box.x, box.y, box.width, box.height};
  section.tables.push_back(std::move(region));
  const auto& pen = section.numbers["penumbra"];
  const auto& rows = section.numbers["rows"];

  section.text.push_back(fmt::format(
      "The variance of the mean of N independent samples is V[Y]/N; here each eye ray's shadow estimate averages "
      "M = 1 or M = 16 stratified shadow rays, {} eye rays per pixel, and the error is measured against a "
      "{}-spp reference of the same image, over {} seeds. The light is 300 × 300 mm (the box's own is "
      "130 × 105 mm), so that most of the floor lies in penumbra, where one shadow ray either reaches the light "
      "or does not.",
      eye_rays, comparison.reference_spp, repeats));
  section.text.push_back(fmt::format(
      "With 1 shadow ray the MSE is {} ± {}, {} that with 16 rays ({} ± {}); the per-sample variance estimated "
      "online from the pixels (first seed) is {} and {}. Inside the penumbra outlined in the figure the per-sample "
      "variance is {} with 1 ray and {} with 16, and the MSE falls {}.",
      format_number(statistics[0].mse.mean), format_number(statistics[0].mse.standard_error, 2),
      format_factor(sixteen_row.mse_ratio), format_number(sixteen_row.mse.mean),
      format_number(sixteen_row.mse.standard_error, 2), format_number(rows[one]["sample_variance"]),
      format_number(rows[sixteen]["sample_variance"]), format_number(pen[one]["sample_variance"]),
      format_number(pen[sixteen]["sample_variance"]), format_factor(local[1].mse_ratio)));
  section.text.push_back(
      fmt::format("16 rays {} (median {} against {}). Intervals: {}.", time_and_efficiency_text(sixteen_row, "1 ray"),
                  format_seconds(sixteen_row.median_seconds), format_seconds(statistics[0].median_seconds), method));
  section.try_it = {"stratum compare --builtin shadow-rays --width 64 --height 64"};
  return section;
}

}  // namespace stratum::report
