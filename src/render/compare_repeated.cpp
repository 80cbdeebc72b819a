#include "stratum/render/compare_repeated.hpp"

#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {

std::vector<RepeatedStatistics> repeated_statistics(const std::vector<std::vector<double>>& mse,
                                                    const std::vector<std::vector<double>>& seconds,
                                                    double confidence) {
  require(!mse.empty() && mse.size() == seconds.size(), "mse", mse.size(),
          "must hold one list per configuration, as many as the seconds");
  const std::size_t repeats = mse.front().size();
  const auto cost = [&](std::size_t c) {  // MSE × seconds: 1 / efficiency
    require(mse[c].size() == repeats && seconds[c].size() == repeats, "repeats", mse[c].size(),
            "must be the same for every configuration");
    std::vector<double> result;
    for (std::size_t k = 0; k < repeats; ++k) result.push_back(mse[c][k] * seconds[c][k]);
    return result;
  };
  const std::vector<double> first_cost = cost(0);
  std::vector<RepeatedStatistics> result;
  for (std::size_t c = 0; c < mse.size(); ++c) {
    RepeatedStatistics row;
    row.mse = analysis::mean_and_error(mse[c]);
    row.median_seconds = analysis::median(seconds[c]);
    row.mse_ratio = analysis::paired_ratio_interval(mse.front(), mse[c], confidence);
    row.time_ratio = analysis::paired_ratio_interval(seconds[c], seconds.front(), confidence);
    row.efficiency_ratio = analysis::paired_ratio_interval(first_cost, cost(c), confidence);
    row.time_resolved = c > 0 && repeats > 1 && !row.time_ratio.contains(1.0);
    result.push_back(row);
  }
  return result;
}

RepeatedCompare compare_repeated(const Scene& scene, const std::string& scene_key,
                                 const std::vector<CompareConfig>& configs, const CompareOptions& options,
                                 unsigned repeats, double confidence, std::vector<CompareImages>* images) {
  require(repeats >= 1 && repeats <= 1000, "repeats", repeats, "must be in [1, 1000]");
  require(confidence > 0 && confidence < 1, "confidence", confidence, "must be in (0, 1)");
  RepeatedCompare result;
  result.repeats = repeats;
  result.confidence = confidence;
  result.mse.resize(configs.size());
  result.seconds.resize(configs.size());
  for (unsigned k = 0; k < repeats; ++k) {
    std::vector<CompareConfig> seeded = configs;
    if (k > 0)  // every configuration of a repeat shares its seed: paired comparisons
      for (auto& config : seeded) config.settings.sampler.seed = hash64(config.settings.sampler.seed, k);
    CompareImages pictures;
    result.rows.push_back(compare(scene, scene_key, seeded, options, images ? &pictures : nullptr));
    for (std::size_t c = 0; c < configs.size(); ++c) {
      result.mse[c].push_back(result.rows.back()[c].mse);
      result.seconds[c].push_back(result.rows.back()[c].seconds);
    }
    if (images) images->push_back(std::move(pictures));
  }
  result.statistics = repeated_statistics(result.mse, result.seconds, confidence);
  result.summary = result.rows.front();
  if (repeats > 1)
    for (std::size_t c = 0; c < configs.size(); ++c) {
      CompareRow& row = result.summary[c];
      const RepeatedStatistics& statistics = result.statistics[c];
      std::vector<double> relative;
      for (const auto& repeat : result.rows) relative.push_back(repeat[c].relative_mse);
      row.mse = statistics.mse.mean;
      row.relative_mse = analysis::mean_and_error(relative).mean;
      row.seconds = statistics.median_seconds;
      row.efficiency = 1 / (row.mse * row.seconds);
      row.mse_ratio = statistics.mse_ratio.estimate;
      row.efficiency_ratio = statistics.efficiency_ratio.estimate;
    }
  return result;
}

}  // namespace stratum::render
