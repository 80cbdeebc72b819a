#include "repeated_comparison.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "sections.hpp"
#include "stratum/util/error.hpp"

namespace stratum::report {

RepeatedComparison run_repeated_comparison(const render::ComparisonScene& scene,
                                           const std::vector<render::CompareConfig>& configs,
                                           const render::CompareOptions& options, unsigned repeats) {
  std::vector<render::CompareImages> pictures;
  render::RepeatedCompare repeated =
      render::compare_repeated(scene.scene, scene.key, configs, options, repeats, 0.95, &pictures);
  RepeatedComparison result;
  result.repeats = repeats;
  result.reference_spp = options.reference_spp;
  result.equal_time = options.equal_time;
  result.mse = std::move(repeated.mse);
  result.seconds = std::move(repeated.seconds);
  result.samples.resize(configs.size());
  for (const auto& config : configs) result.labels.push_back(config.label);
  for (unsigned k = 0; k < repeats; ++k) {
    for (std::size_t c = 0; c < configs.size(); ++c) {
      result.samples[c].push_back(repeated.rows[k][c].samples);
    }
    result.reference_cached = result.reference_cached && pictures[k].reference_cached;
    if (k == 0) result.reference = std::move(pictures[k].reference);
    result.images.push_back(std::move(pictures[k].images));
  }
  return result;
}

std::vector<RowStatistics> row_statistics(const RepeatedComparison& comparison,
                                          const std::vector<std::vector<double>>& mse, double confidence) {
  require(mse.size() == comparison.labels.size(), "mse", mse.size(), "must hold one list per configuration");
  return render::repeated_statistics(mse, comparison.seconds, confidence);
}

std::string interval_method(unsigned repeats, double confidence) {
  return fmt::format(
      "{} seeds, each rendering every configuration (paired); a ratio is the geometric mean of the "
      "per-seed ratios with a Student-t {:g}% interval on their logarithms ({} degrees of freedom); "
      "seconds are medians",
      repeats, 100 * confidence, repeats - 1);
}

namespace {

std::string mse_text(const MeanError& m) {
  return m.standard_error > 0 ? format_number(m.mean) + " ± " + format_number(m.standard_error, 2)
                              : format_number(m.mean);
}

}  // namespace

std::string efficiency_text(const RowStatistics& row) {
  if (row.time_resolved) return format_factor(row.efficiency_ratio);
  return fmt::format("not resolved: the times agree within ±{}%", format_number(noise_percent(row.time_ratio), 2));
}

std::string time_and_efficiency_text(const RowStatistics& row, const std::string& first_label) {
  if (row.time_resolved)
    return fmt::format("took {} the time of {}, so its efficiency 1/(MSE × seconds) is {} that of {}",
                       format_factor(row.time_ratio), first_label, format_factor(row.efficiency_ratio), first_label);
  return fmt::format(
      "took the time of {} within the timing noise (the times agree within ±{}%), so no efficiency "
      "ratio is quoted beyond the MSE ratio",
      first_label, format_number(noise_percent(row.time_ratio), 2));
}

Table repeated_table(const RepeatedComparison& comparison, const std::vector<RowStatistics>& statistics,
                     const std::string& caption) {
  Table table{caption,
              {"configuration", "eye rays/pixel", "MSE (mean ± s.e.)", "median seconds", "MSE ratio (first/this)",
               "time ratio (this/first)", "efficiency ratio (this/first)"},
              {}};
  for (std::size_t c = 0; c < statistics.size(); ++c) {
    const RowStatistics& row = statistics[c];
    const auto& samples = comparison.samples[c];
    const std::uint32_t low = *std::min_element(samples.begin(), samples.end());
    const std::uint32_t high = *std::max_element(samples.begin(), samples.end());
    const std::string spp = low == high ? std::to_string(low) : std::to_string(low) + "–" + std::to_string(high);
    if (c == 0) {
      table.rows.push_back({comparison.labels[c], spp, mse_text(row.mse), format_number(row.median_seconds),
                            "1 (baseline)", "1 (baseline)", "1 (baseline)"});
      continue;
    }
    table.rows.push_back({comparison.labels[c], spp, mse_text(row.mse), format_number(row.median_seconds),
                          format_interval(row.mse_ratio), format_interval(row.time_ratio),
                          row.time_resolved ? format_interval(row.efficiency_ratio)
                                            : fmt::format("not quoted: times equal within ±{}%",
                                                          format_number(noise_percent(row.time_ratio), 2))});
  }
  return table;
}

nlohmann::json repeated_grid(const RepeatedComparison& comparison, const std::vector<Crop>& crops) {
  std::vector<GridColumn> columns{{&comparison.reference, fmt::format("reference ({} spp)", comparison.reference_spp)}};
  for (std::size_t c = 0; c < comparison.labels.size(); ++c)
    columns.push_back({&comparison.images.at(0)[c],
                       fmt::format("{}\nMSE {}", comparison.labels[c], format_number(comparison.mse[c].at(0)))});
  return picture_grid(columns, crops, &comparison.reference, "|error| against the reference");
}

nlohmann::json interval_json(const RatioInterval& interval) {
  return {{"estimate", interval.estimate},
          {"low", interval.low},
          {"high", interval.high},
          {"count", interval.count},
          {"confidence", interval.confidence}};
}

nlohmann::json repeated_numbers(const RepeatedComparison& comparison, const std::vector<RowStatistics>& statistics) {
  nlohmann::json rows = nlohmann::json::object();
  for (std::size_t c = 0; c < statistics.size(); ++c) {
    const RowStatistics& row = statistics[c];
    rows[comparison.labels[c]] = {
        {"spp_per_seed", comparison.samples[c]},
        {"mse_per_seed", comparison.mse[c]},
        {"seconds_per_seed", comparison.seconds[c]},
        {"mse_mean", row.mse.mean},
        {"mse_standard_error", row.mse.standard_error},
        {"seconds_median", row.median_seconds},
        {"mse_ratio", interval_json(row.mse_ratio)},
        {"time_ratio", interval_json(row.time_ratio)},
        {"time_resolved", row.time_resolved},
        // Quoted only when the times differ beyond their noise (else null).
        {"efficiency_ratio", row.time_resolved ? interval_json(row.efficiency_ratio) : nlohmann::json(nullptr)},
        {"efficiency_ratio_unresolved", interval_json(row.efficiency_ratio)}};
    if (!comparison.images.empty())  // the first seed's, for the unbiasedness checks of the tests
      rows[comparison.labels[c]]["sample_variance"] = mean_sample_variance(comparison.images.front().at(c));
  }
  double reference_variance = 0;
  for (const double v : comparison.reference.variance) reference_variance += v;
  if (!comparison.reference.variance.empty()) reference_variance /= double(comparison.reference.variance.size());
  return {{"width", comparison.reference.width},
          {"height", comparison.reference.height},
          {"reference_spp", comparison.reference_spp},
          {"reference_cached", comparison.reference_cached},
          {"repeats", comparison.repeats},
          {"equal_time_seconds", comparison.equal_time},
          {"reference_variance", reference_variance},
          {"interval_method", interval_method(comparison.repeats)},
          {"rows", rows}};
}

}  // namespace stratum::report
