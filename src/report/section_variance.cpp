/// §2 Variance and its cost: soft shadows in the Cornell box with 1 and with
/// 16 shadow rays per eye ray (render::builtin_comparison("shadow-rays"): 4
/// eye rays per pixel through the pixel centres, so that only the light
/// integral varies), each measured against a converged reference by MSE,
/// with its time and efficiency 1 / (MSE × seconds) (Hammersley,
/// Handscomb 1964, "Monte Carlo Methods", §5.1).
#include <fmt/core.h>

#include "render_support.hpp"
#include "sections.hpp"

namespace stratum::report {

Section variance_section(SectionContext& context) {
  Section section = context.start();
  const RenderScale scale = render_scale(context);
  const auto scene = render::comparison_scene("", false, scale.width, scale.height);
  const auto configs = render::builtin_comparison("shadow-rays", context.threads(), context.seed());
  const RenderedComparison comparison = run_comparison(scene, configs, scale.reference_spp, context.cache_dir());
  const render::CompareRow& one = comparison.rows.at(0);
  const render::CompareRow& sixteen = comparison.rows.at(1);

  section.figures.push_back(image_figure(
      context, comparison_panels(comparison), "shadow-rays",
      fmt::format("Soft shadows, {}×{} pixels, {} eye rays per pixel: the reference, 1 shadow ray and 16 shadow rays "
                  "per eye ray",
                  scale.width, scale.height, one.samples)));
  section.tables.push_back(comparison_table(
      comparison, fmt::format("1 vs 16 shadow rays against a {}-spp reference", comparison.reference_spp)));
  section.numbers = comparison_numbers(comparison);
  const double time_ratio = sixteen.seconds / one.seconds;
  section.numbers["time_ratio"] = time_ratio;

  section.text.push_back(fmt::format(
      "The variance of the mean of N independent samples is V[Y]/N; here each eye ray's shadow estimate averages "
      "M = 1 or M = 16 stratified shadow rays, {} eye rays per pixel, and the error is measured against a "
      "{}-spp reference of the same image.",
      one.samples, comparison.reference_spp));
  section.text.push_back(fmt::format(
      "With 1 shadow ray the MSE is {} ({}× that with 16 rays, {}); the per-sample variance estimated online from "
      "the pixels is {} and {}.",
      format_number(one.mse), format_number(sixteen.mse_ratio), format_number(sixteen.mse),
      format_number(section.numbers["rows"][one.label]["sample_variance"]),
      format_number(section.numbers["rows"][sixteen.label]["sample_variance"])));
  section.text.push_back(fmt::format(
      "16 rays took {}× the time of 1 ({} s against {} s), so the efficiency 1/(MSE × seconds) of 16 rays is {}× "
      "that of 1.",
      format_number(time_ratio), format_number(sixteen.seconds), format_number(one.seconds),
      format_number(sixteen.efficiency_ratio)));
  section.try_it = {"stratum compare --builtin shadow-rays --width 64 --height 64"};
  return section;
}

}  // namespace stratum::report
