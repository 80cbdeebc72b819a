#pragma once
/// A render comparison repeated over independent seeds, for statistics that
/// say how sure they are: repeat k renders every configuration with the
/// same seed (the configuration's seed for k = 0, hash64(seed, k) after),
/// so the configurations are compared in pairs; each one gets its MSE's
/// mean and standard error, its median seconds and, against the first,
/// Student-t intervals on the MSE, time and efficiency ratios
/// (analysis/paired_statistics.hpp). A time ratio whose interval holds 1 is
/// unresolved: the timings do not differ beyond their noise, and its
/// efficiency ratio says no more than the MSE ratio.
#include <cstdint>
#include <string>
#include <vector>

#include "stratum/analysis/paired_statistics.hpp"
#include "stratum/render/compare.hpp"

namespace stratum::render {

/// One configuration against the first, over the repeats.
struct RepeatedStatistics {
  analysis::MeanError mse;
  double median_seconds = 0;
  analysis::RatioInterval mse_ratio;         ///< first's MSE / this one's
  analysis::RatioInterval time_ratio;        ///< this one's seconds / first's
  analysis::RatioInterval efficiency_ratio;  ///< this one's 1/(MSE·s) / first's
  /// The time ratio's interval excludes 1 (and there are at least 2 repeats).
  bool time_resolved = false;
};

/// The statistics of each configuration from its per-repeat MSE and
/// seconds ([configuration][repeat], every value positive and finite).
std::vector<RepeatedStatistics> repeated_statistics(const std::vector<std::vector<double>>& mse,
                                                    const std::vector<std::vector<double>>& seconds,
                                                    double confidence = 0.95);

struct RepeatedCompare {
  std::vector<std::vector<CompareRow>> rows;      ///< [repeat][configuration]
  std::vector<std::vector<double>> mse, seconds;  ///< the rows' MSE and seconds, [configuration][repeat]
  std::vector<RepeatedStatistics> statistics;     ///< [configuration]
  /// What the faces print, one row per configuration: the first repeat's
  /// row (its spp, passes, variance image and error spectrum) with MSE and
  /// relative MSE the means over the repeats, seconds the median,
  /// efficiency 1/(mean MSE × median seconds) and the two ratios the paired
  /// geometric means; for one repeat, exactly that repeat's rows.
  std::vector<CompareRow> summary;
  unsigned repeats = 0;
  double confidence = 0.95;
};

/// Runs compare() `repeats` times with paired seeds; `images`, when given,
/// receives each repeat's pictures.
RepeatedCompare compare_repeated(const Scene& scene, const std::string& scene_key,
                                 const std::vector<CompareConfig>& configs, const CompareOptions& options,
                                 unsigned repeats, double confidence = 0.95,
                                 std::vector<CompareImages>* images = nullptr);

}  // namespace stratum::render
