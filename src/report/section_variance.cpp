/// §2 Variance and its cost: soft shadows with 1 and with 16 shadow rays
/// per eye ray (render::builtin_comparison("shadow-rays"): 4 eye rays per
/// pixel through the pixel centres, so that only the light integral
/// varies), in the Cornell box with its light grown to 300 × 300 mm
/// (large_light_box) so that the shadows are wide penumbras. Each render is
/// measured against a converged reference by MSE, over the image and inside
/// a penumbra, with its time and efficiency 1 / (MSE × seconds)
/// (Hammersley, Handscomb 1964, "Monte Carlo Methods", §5.1).
#include <fmt/core.h>

#include "render_support.hpp"
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
  const RenderedComparison comparison = run_comparison(scene, configs, scale.few_samples_reference_spp, context.cache_dir());
  const render::CompareRow& one = comparison.rows.at(0);
  const render::CompareRow& sixteen = comparison.rows.at(1);

  section.figures.push_back(image_figure(
      context, comparison_grid(comparison, {penumbra}), "shadow-rays",
      fmt::format("Soft shadows under a 300 × 300 mm light, {}×{} pixels, {} eye rays per pixel through the pixel "
                  "centres: the reference, 1 shadow ray and 16 shadow rays per eye ray; below, the penumbra "
                  "outlined above, enlarged, and each render's error",
                  scale.width, scale.height, one.samples),
      3));
  section.tables.push_back(comparison_table(
      comparison, fmt::format("1 vs 16 shadow rays against a {}-spp reference", comparison.reference_spp)));
  section.numbers = comparison_numbers(comparison);
  const double time_ratio = sixteen.seconds / one.seconds;
  section.numbers["time_ratio"] = time_ratio;

  // Inside the penumbra, where the light is partly hidden and a shadow ray's
  // answer is a coin toss.
  const PixelBox box = crop_pixels(penumbra, scale.width, scale.height);
  Table region{"Inside the penumbra outlined in the figure",
               {"configuration", "pixels", "MSE", "per-sample variance", "MSE ratio (1 ray / this)"}, {}};
  const RegionError one_region = region_error(comparison.images[0], comparison.reference, box);
  for (std::size_t i = 0; i < comparison.rows.size(); ++i) {
    const RegionError error = region_error(comparison.images[i], comparison.reference, box);
    region.rows.push_back({comparison.rows[i].label, std::to_string(box.width * box.height), format_number(error.mse),
                           format_number(error.sample_variance), format_number(one_region.mse / error.mse)});
    section.numbers["penumbra"][comparison.rows[i].label] = {{"mse", error.mse},
                                                             {"sample_variance", error.sample_variance}};
  }
  section.numbers["penumbra"]["box"] = {box.x, box.y, box.width, box.height};
  section.tables.push_back(std::move(region));
  const auto& pen = section.numbers["penumbra"];

  section.text.push_back(fmt::format(
      "The variance of the mean of N independent samples is V[Y]/N; here each eye ray's shadow estimate averages "
      "M = 1 or M = 16 stratified shadow rays, {} eye rays per pixel, and the error is measured against a "
      "{}-spp reference of the same image. The light is 300 × 300 mm (the box's own is 130 × 105 mm), so that "
      "most of the floor lies in penumbra, where one shadow ray either reaches the light or does not.",
      one.samples, comparison.reference_spp));
  section.text.push_back(fmt::format(
      "With 1 shadow ray the MSE is {} ({}× that with 16 rays, {}); the per-sample variance estimated online from "
      "the pixels is {} and {}. Inside the penumbra outlined in the figure the per-sample variance is {} with 1 ray "
      "and {} with 16, and the MSE falls {}×.",
      format_number(one.mse), format_number(sixteen.mse_ratio), format_number(sixteen.mse),
      format_number(section.numbers["rows"][one.label]["sample_variance"]),
      format_number(section.numbers["rows"][sixteen.label]["sample_variance"]),
      format_number(pen[one.label]["sample_variance"]), format_number(pen[sixteen.label]["sample_variance"]),
      format_number(pen[one.label]["mse"].get<double>() / pen[sixteen.label]["mse"].get<double>())));
  section.text.push_back(fmt::format(
      "16 rays took {}× the time of 1 ({} against {}), so the efficiency 1/(MSE × seconds) of 16 rays is {}× "
      "that of 1.",
      format_number(time_ratio), format_seconds(sixteen.seconds), format_seconds(one.seconds),
      format_number(sixteen.efficiency_ratio)));
  section.try_it = {"stratum compare --builtin shadow-rays --width 64 --height 64"};
  return section;
}

}  // namespace stratum::report
