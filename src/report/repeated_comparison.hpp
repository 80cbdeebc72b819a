#pragma once
/// A render comparison repeated over independent seeds (§8, §9): each
/// repeat renders every configuration with the same seed (repeat k > 0 with
/// hash64(seed, k)), so the configurations are compared in pairs, and the
/// report quotes medians of the timings and confidence intervals of the
/// ratios (seed_statistics.hpp) instead of one timed run.
#include <cstdint>
#include <string>
#include <vector>

#include "render_support.hpp"
#include "section_context.hpp"
#include "seed_statistics.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/render/compare_repeated.hpp"

namespace stratum::report {

struct RepeatedComparison {
  std::vector<std::string> labels;
  std::vector<std::vector<render::Image>> images;   ///< [repeat][configuration]
  std::vector<std::vector<double>> mse, seconds;    ///< [configuration][repeat]
  std::vector<std::vector<std::uint32_t>> samples;  ///< eye rays per pixel taken, [configuration][repeat]
  render::Image reference;                          ///< of the first configuration's estimand
  std::uint32_t reference_spp = 0;
  bool reference_cached = true;
  double equal_time = 0;  ///< seconds per render at equal time; 0: equal samples
  unsigned repeats = 0;
};

/// Runs render::compare `repeats` times (options.equal_time applies to each).
RepeatedComparison run_repeated_comparison(const render::ComparisonScene& scene,
                                           const std::vector<render::CompareConfig>& configs,
                                           const render::CompareOptions& options, unsigned repeats);

/// One configuration against the first, over the repeats.
using RowStatistics = render::RepeatedStatistics;

/// Statistics of each configuration from `mse` ([configuration][repeat]:
/// the comparison's own or one over a mask of pixels) and its timings.
std::vector<RowStatistics> row_statistics(const RepeatedComparison& comparison,
                                          const std::vector<std::vector<double>>& mse, double confidence = 0.95);

/// The interval method, in words, for captions and report.json.
std::string interval_method(unsigned repeats, double confidence = 0.95);

/// The table: configuration, eye rays per pixel, MSE (mean ± standard error),
/// median seconds, the MSE ratio, the time ratio and the efficiency ratio
/// with their intervals; an efficiency ratio whose times are not resolved is
/// left out, with the timing noise stated.
Table repeated_table(const RepeatedComparison& comparison, const std::vector<RowStatistics>& statistics,
                     const std::string& caption);

/// What report.json holds of it: per configuration the per-seed MSE and
/// seconds, their summaries, the three ratio intervals and (with images)
/// the first seed's per-sample variance (mean_sample_variance); the
/// reference's mean variance of the mean (the floor under every MSE).
nlohmann::json repeated_numbers(const RepeatedComparison& comparison, const std::vector<RowStatistics>& statistics);

/// The first seed as a picture grid (render_support.hpp picture_grid): the
/// reference, then each configuration with its MSE; the heat maps show
/// |render − reference|.
nlohmann::json repeated_grid(const RepeatedComparison& comparison, const std::vector<Crop>& crops);

/// The interval as JSON: {estimate, low, high, count, confidence}.
nlohmann::json interval_json(const RatioInterval& interval);

/// A sentence part: "2.1× (95% CI 1.8–2.5)" for a resolved efficiency
/// ratio, else "not resolved: the times agree within ±7%".
std::string efficiency_text(const RowStatistics& row);

/// A sentence on a configuration's time and efficiency against the first's:
/// "took 3.9× (95% CI 3.7–4.1) the time of 1 shadow ray, so its efficiency
/// 1/(MSE × seconds) is 4.4× (95% CI …) that of 1 shadow ray" when the time
/// ratio's interval excludes 1, else that the times agree within their noise
/// (±x%, noise_percent) and no efficiency ratio is quoted.
std::string time_and_efficiency_text(const RowStatistics& row, const std::string& first_label);

}  // namespace stratum::report
