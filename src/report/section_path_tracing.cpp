/// §9 Path tracing, complete versus incomplete: the same budget of 64 shadow
/// rays per pixel spent as 4 eye rays × 16 shadow rays ("complete": every
/// eye ray gets a full set of light samples) or as 64 eye rays × 1 shadow ray
/// ("incomplete", which also samples the pixel area and every later bounce
/// 16 times as often); render::builtin_comparison("path"), measured against a
/// converged path-traced reference (Kajiya 1986, "The rendering equation";
/// next-event estimation as in Shirley et al. 1996, "Monte Carlo techniques
/// for direct lighting calculations"). Both at equal ray count and at equal
/// time, over several seeds (repeated_comparison.hpp).
#include <fmt/core.h>

#include "render_support.hpp"
#include "repeated_comparison.hpp"
#include "sections.hpp"

namespace stratum::report {

namespace {

/// Where the two shapes differ: the ceiling, lit only by light that bounced
/// (sampled by every eye ray's path: 4 paths a pixel against 64), and the
/// tall block's left edge against the back wall (the pixel area: 4 eye rays
/// against 64).
const Crop ceiling{0.16, 0.02, 0.25, 0.2, "ceiling, lit by bounces only"};
const Crop block_edge{0.17, 0.36, 0.22, 0.22, "tall block's edge"};

/// The first seed drawn at the pictures' size (256×256 in the full report):
/// the reference; complete and incomplete at equal rays; the complete shape
/// given the incomplete render's time; each outlined where they differ, the
/// crops enlarged and the errors as heat maps. Returns its numbers.
nlohmann::json path_tracing_picture(SectionContext& context, Section& section,
                                    const std::vector<render::CompareConfig>& configs) {
  const RenderScale scale = picture_scale(context);
  const auto scene = render::comparison_scene("", false, scale.width, scale.height);
  const RenderedComparison rays = run_comparison(scene, configs, scale.reference_spp, context.cache_dir());
  std::vector<render::CompareConfig> timed{configs.at(0)};
  timed.front().label = "complete 4x16 per pass";
  const double budget = rays.rows.at(1).seconds;
  const RenderedComparison time = run_comparison(scene, timed, scale.reference_spp, context.cache_dir(), budget);
  const render::CompareRow& complete = rays.rows.at(0);
  const render::CompareRow& incomplete = rays.rows.at(1);
  const render::CompareRow& complete_timed = time.rows.at(0);
  const std::vector<GridColumn> columns{
      {&rays.reference, fmt::format("reference ({} spp)", rays.reference_spp)},
      {&rays.images.at(0), fmt::format("complete {}×{}\nMSE {}", complete.samples, configs.at(0).settings.light_samples,
                                       format_number(complete.mse))},
      {&rays.images.at(1),
       fmt::format("incomplete {}×{}, {}\nMSE {}", incomplete.samples, configs.at(1).settings.light_samples,
                   format_seconds(incomplete.seconds), format_number(incomplete.mse))},
      {&time.images.at(0), fmt::format("complete, the same time: {}×{}\nMSE {}", complete_timed.samples,
                                       configs.at(0).settings.light_samples, format_number(complete_timed.mse))}};
  section.figures.push_back(image_figure(
      context, picture_grid(columns, {ceiling, block_edge}, &rays.reference, "|error| against the reference"),
      "complete-incomplete-picture",
      fmt::format("Complete against incomplete path tracing at {}×{} pixels (first seed): the reference, both at {} "
                  "shadow rays per pixel, and the complete shape given the incomplete render's time ({}); below, "
                  "the ceiling (lit only by light that bounced) and the tall block's edge enlarged, and each render's "
                  "error",
                  scale.width, scale.height, complete.samples * configs.at(0).settings.light_samples,
                  format_seconds(budget)),
      4));
  section.text.push_back(fmt::format(
      "Drawn at {}×{} pixels against a {}-spp reference (first seed), the complete render's MSE is {} and the "
      "incomplete one's {}; given the incomplete render's {}, the complete shape reaches {} eye rays per pixel and "
      "MSE {}. The enlarged ceiling shows the bounced light each shape sees through its number of paths, the "
      "block's edge the pixel area each samples with its number of eye rays.",
      scale.width, scale.height, rays.reference_spp, format_number(complete.mse), format_number(incomplete.mse),
      format_seconds(budget), complete_timed.samples, format_number(complete_timed.mse)));
  nlohmann::json numbers = comparison_numbers(rays);
  numbers["equal_time_seconds"] = budget;
  numbers["complete_at_equal_time"] = comparison_numbers(time)["rows"];
  return numbers;
}

}  // namespace

Section path_tracing_section(SectionContext& context) {
  Section section = context.start();
  const RenderScale scale = render_scale(context);
  const auto scene = render::comparison_scene("", false, scale.width, scale.height);
  const auto configs = render::builtin_comparison("path", context.threads(), context.seed());
  const unsigned repeats = context.quick() ? 3 : 6;
  render::CompareOptions options;
  options.reference_spp = scale.reference_spp;
  options.cache_dir = context.cache_dir();
  const RepeatedComparison rays = run_repeated_comparison(scene, configs, options, repeats);
  const std::vector<RowStatistics> ray_stats = row_statistics(rays, rays.mse);

  // Equal time: both render passes until the same budget has passed — the
  // incomplete render's median time at equal rays, so the complete one gets
  // the extra passes its cheaper samples buy. The incomplete passes are 4
  // eye rays (not 64) so that the last pass overshoots the budget little.
  std::vector<render::CompareConfig> timed = configs;
  timed.at(0).label = "complete 4x16 per pass";
  timed.at(1).label = "incomplete 4x1 per pass";
  timed.at(1).settings.sampler.spp = 4;
  render::CompareOptions timed_options = options;
  timed_options.equal_time = ray_stats.at(1).median_seconds;
  const RepeatedComparison timed_run = run_repeated_comparison(scene, timed, timed_options, repeats);
  const std::vector<RowStatistics> time_stats = row_statistics(timed_run, timed_run.mse);

  const std::uint32_t complete_spp = configs.at(0).settings.sampler.spp,
                      incomplete_spp = configs.at(1).settings.sampler.spp;
  const std::uint32_t complete_shadow = configs.at(0).settings.light_samples;
  const std::uint32_t incomplete_shadow = configs.at(1).settings.light_samples;
  nlohmann::json panels = nlohmann::json::array();
  panels.push_back(image_panel(rays.reference, fmt::format("reference ({} spp)", rays.reference_spp)));
  for (const RepeatedComparison* run : {&rays, &timed_run})
    for (std::size_t i = 0; i < run->labels.size(); ++i)
      panels.push_back(image_panel(run->images[0][i],
                                   fmt::format("{}{}\nMSE {}", run->labels[i], run == &timed_run ? " (equal time)" : "",
                                               format_number(run->mse[i][0]))));
  section.figures.push_back(image_figure(
      context, panels, "complete-incomplete",
      fmt::format("Path tracing (up to {} bounces), {}×{} pixels, first seed: the reference; {} eye rays × {} shadow "
                  "rays and {} eye rays × {} shadow ray per pixel (equal rays); in the second row both at equal "
                  "time, {} each",
                  configs.at(0).settings.max_depth, scale.width, scale.height, complete_spp, complete_shadow,
                  incomplete_spp, incomplete_shadow, format_seconds(timed_options.equal_time)),
      3));
  const std::string method = interval_method(repeats);
  section.tables.push_back(
      repeated_table(rays, ray_stats,
                     fmt::format("At equal ray count ({} shadow rays per pixel), against a {}-spp reference ({})",
                                 complete_spp * complete_shadow, rays.reference_spp, method)));
  section.tables.push_back(repeated_table(
      timed_run, time_stats,
      fmt::format("At equal time ({} per render, the incomplete render's median time at equal rays; eye rays per "
                  "pixel are what each reached), against the same reference ({})",
                  format_seconds(timed_options.equal_time), method)));
  section.numbers["equal_rays"] = repeated_numbers(rays, ray_stats);
  section.numbers["equal_time"] = repeated_numbers(timed_run, time_stats);
  section.numbers["shadow_rays_per_pixel"] = {{configs.at(0).label, complete_spp * complete_shadow},
                                              {configs.at(1).label, incomplete_spp * incomplete_shadow}};

  // The headline: which wins at equal time, the comparison that counts. With
  // the times resolved, by the efficiency ratio; with times that agree within
  // their noise, by the MSE ratio (the efficiency ratio is then not quoted).
  const RowStatistics& at_time = time_stats.at(1);
  const RatioInterval& deciding = at_time.time_resolved ? at_time.efficiency_ratio : at_time.mse_ratio;
  const bool incomplete_wins = deciding.low > 1, complete_wins = deciding.high < 1;
  section.numbers["equal_time_winner"] = incomplete_wins ? "incomplete" : complete_wins ? "complete" : "neither";
  section.numbers["equal_time_decided_by"] = at_time.time_resolved ? "efficiency_ratio" : "mse_ratio";
  const RatioInterval& ray_mse = ray_stats.at(1).mse_ratio;
  const std::string at_rays = ray_mse.low > 1    ? "the incomplete render has the lower MSE"
                              : ray_mse.high < 1 ? "the complete render has the lower MSE"
                                                 : "neither has a lower MSE beyond the noise";
  const std::string measure =
      at_time.time_resolved
          ? fmt::format("the incomplete render's efficiency 1/(MSE × seconds) is {} the complete one's",
                        format_factor(at_time.efficiency_ratio))
          : fmt::format("their times agree within ±{}%, and the MSE ratio complete/incomplete is {}",
                        format_number(noise_percent(at_time.time_ratio), 2), format_interval(at_time.mse_ratio));
  section.text.push_back(fmt::format(
      "At equal time, {}: {}. At equal ray count {} (ratio complete/incomplete {}), but that is not equal cost: the "
      "incomplete render took {} as long.",
      incomplete_wins ? "incomplete path tracing wins"
      : complete_wins ? "complete path tracing wins"
                      : "neither wins beyond the noise",
      measure, at_rays, format_interval(ray_mse), format_factor(ray_stats.at(1).time_ratio)));
  section.text.push_back(fmt::format(
      "The complete render spends {} shadow rays per pixel at the first hit ({} eye rays × {} shadow rays) and the "
      "incomplete one {} ({} × {}); the incomplete one also samples the pixel area and every later bounce {}× as "
      "often, and each of its eye rays costs a whole path, hence its time. Given the same {} per render, the "
      "complete render reaches {} eye rays per pixel (in passes of {} × {}) and the incomplete one {}.",
      complete_spp * complete_shadow, complete_spp, complete_shadow, incomplete_spp * incomplete_shadow, incomplete_spp,
      incomplete_shadow, format_number(double(incomplete_spp) / complete_spp), format_seconds(timed_options.equal_time),
      median(std::vector<double>(timed_run.samples[0].begin(), timed_run.samples[0].end())), complete_spp,
      complete_shadow, median(std::vector<double>(timed_run.samples[1].begin(), timed_run.samples[1].end()))));
  section.text.push_back("Intervals: " + method + ".");
  section.numbers["picture"] = path_tracing_picture(context, section, configs);
  section.try_it = {"stratum compare --builtin path --width 64 --height 64",
                    "stratum compare --builtin path --width 64 --height 64 --equal-time 2"};
  return section;
}

}  // namespace stratum::report
