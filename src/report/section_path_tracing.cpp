/// §9 Path tracing, complete versus incomplete: the same budget of 64 shadow
/// rays per pixel spent as 4 eye rays × 16 shadow rays ("complete": every
/// eye ray gets a full set of light samples) or as 64 eye rays × 1 shadow ray
/// ("incomplete", which also samples the pixel area and every later bounce
/// 16 times as often); render::builtin_comparison("path"), measured against a
/// converged path-traced reference (Kajiya 1986, "The rendering equation";
/// next-event estimation as in Shirley et al. 1996, "Monte Carlo techniques
/// for direct lighting calculations").
#include <fmt/core.h>

#include "render_support.hpp"
#include "sections.hpp"

namespace stratum::report {

Section path_tracing_section(SectionContext& context) {
  Section section = context.start();
  const RenderScale scale = render_scale(context);
  const auto scene = render::comparison_scene("", false, scale.width, scale.height);
  const auto configs = render::builtin_comparison("path", context.threads(), context.seed());
  const RenderedComparison comparison = run_comparison(scene, configs, scale.reference_spp, context.cache_dir());
  const render::CompareRow& complete = comparison.rows.at(0);
  const render::CompareRow& incomplete = comparison.rows.at(1);
  const std::uint32_t complete_shadow = configs.at(0).settings.light_samples;
  const std::uint32_t incomplete_shadow = configs.at(1).settings.light_samples;

  section.figures.push_back(image_figure(
      context, comparison_panels(comparison), "complete-incomplete",
      fmt::format("Path tracing (up to {} bounces), {}×{} pixels: the reference, {} eye rays × {} shadow rays and {} "
                  "eye rays × {} shadow ray per pixel",
                  configs.at(0).settings.max_depth, scale.width, scale.height, complete.samples, complete_shadow,
                  incomplete.samples, incomplete_shadow)));
  section.tables.push_back(comparison_table(
      comparison, fmt::format("Complete vs incomplete at {} shadow rays per pixel, against a {}-spp reference",
                              complete.samples * complete_shadow, comparison.reference_spp)));
  section.numbers = comparison_numbers(comparison);
  section.numbers["shadow_rays_per_pixel"] = {{complete.label, complete.samples * complete_shadow},
                                              {incomplete.label, incomplete.samples * incomplete_shadow}};

  section.text.push_back(fmt::format(
      "The complete render spends {} shadow rays per pixel at the first hit ({} eye rays × {} shadow rays) and the "
      "incomplete one {} ({} × {}); the incomplete one also samples the pixel area and every later bounce {}× as "
      "often.",
      complete.samples * complete_shadow, complete.samples, complete_shadow, incomplete.samples * incomplete_shadow,
      incomplete.samples, incomplete_shadow, format_number(double(incomplete.samples) / complete.samples)));
  section.text.push_back(fmt::format(
      "Against a {}-spp reference, the complete render's MSE is {} and the incomplete one's {} (ratio "
      "complete/incomplete {}); they took {} s and {} s, so the incomplete render's efficiency 1/(MSE × seconds) is "
      "{}× the complete one's.",
      comparison.reference_spp, format_number(complete.mse), format_number(incomplete.mse),
      format_number(incomplete.mse_ratio), format_number(complete.seconds), format_number(incomplete.seconds),
      format_number(incomplete.efficiency_ratio)));
  section.try_it = {"stratum compare --builtin path --width 64 --height 64"};
  return section;
}

}  // namespace stratum::report
