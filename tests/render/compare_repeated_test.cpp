// A comparison repeated over paired seeds (src/render/compare_repeated.cpp):
// the statistics have their closed forms, repeat 0 is the plain
// comparison, the later repeats use other seeds, and the summary is the
// repeats' means, medians and geometric-mean ratios.
#include "stratum/render/compare_repeated.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "stratum/util/error.hpp"

namespace stratum::render {
namespace {

TEST(CompareRepeated, StatisticsHaveTheirClosedForms) {
  // Two configurations over two seeds: the second halves, then quarters,
  // the first's MSE and always takes twice its time.
  const auto rows = repeated_statistics({{1, 1}, {0.5, 0.25}}, {{1, 1}, {2, 2}});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_DOUBLE_EQ(rows[0].mse_ratio.estimate, 1);
  EXPECT_FALSE(rows[0].time_resolved);  // the baseline against itself
  EXPECT_DOUBLE_EQ(rows[1].mse.mean, 0.375);
  EXPECT_DOUBLE_EQ(rows[1].mse.standard_error, 0.125);  // sd 0.25/sqrt(2) over sqrt(2)
  EXPECT_DOUBLE_EQ(rows[1].median_seconds, 2);
  EXPECT_NEAR(rows[1].mse_ratio.estimate, std::sqrt(8.0), 1e-12);  // geometric mean of 2 and 4
  EXPECT_LT(rows[1].mse_ratio.low, 2);                             // log ratios ln 2, ln 4: t(1) at 97.5% is 12.7
  EXPECT_NEAR(rows[1].time_ratio.estimate, 2, 1e-12);
  EXPECT_NEAR(rows[1].time_ratio.low, 2, 1e-12);  // no timing noise: a resolved ratio
  EXPECT_TRUE(rows[1].time_resolved);
  EXPECT_NEAR(rows[1].efficiency_ratio.estimate, std::sqrt(2.0), 1e-12);  // costs 1 and 0.5 against 1
  EXPECT_THROW(repeated_statistics({{1, 1}, {1}}, {{1, 1}, {1, 1}}), invalid_argument);
  EXPECT_THROW(repeated_statistics({{1}, {0}}, {{1}, {1}}), invalid_argument);  // a zero MSE has no log ratio
}

TEST(CompareRepeated, RepeatZeroIsThePlainComparisonAndTheSummaryItsRepeats) {
  const std::string cache = (std::filesystem::temp_directory_path() / "stratum-compare-repeated").string();
  std::filesystem::remove_all(cache);
  const ComparisonScene scene = comparison_scene("", false, 8, 8);
  const auto configs = builtin_comparison("shadow-rays", 1, 3);
  CompareOptions options;
  options.reference_spp = 32;
  options.cache_dir = cache;
  const auto plain = compare(scene.scene, scene.key, configs, options);
  const RepeatedCompare one = compare_repeated(scene.scene, scene.key, configs, options, 1);
  ASSERT_EQ(one.summary.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(one.summary[c].mse, plain[c].mse);
    EXPECT_EQ(one.summary[c].mse_ratio, plain[c].mse_ratio);
  }
  const RepeatedCompare four = compare_repeated(scene.scene, scene.key, configs, options, 4);
  ASSERT_EQ(four.rows.size(), 4u);
  ASSERT_EQ(four.statistics.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(four.rows[0][c].mse, plain[c].mse) << "repeat 0 keeps the configuration's seed";
    double sum = 0, log_ratio = 0;
    for (unsigned k = 0; k < 4; ++k) {
      if (k > 0) {
        EXPECT_NE(four.rows[k][c].mse, four.rows[0][c].mse) << "repeat " << k << " reused the seed";
      }
      sum += four.rows[k][c].mse;
      log_ratio += std::log(four.rows[k][0].mse / four.rows[k][c].mse);
    }
    EXPECT_NEAR(four.summary[c].mse, sum / 4, 1e-15 * sum);
    EXPECT_NEAR(four.summary[c].mse_ratio, std::exp(log_ratio / 4), 1e-12);
    EXPECT_EQ(four.summary[c].seconds, four.statistics[c].median_seconds);
  }
  // 16 shadow rays against 1: the MSE ratio's 95% interval lies above 1.
  EXPECT_GT(four.statistics[1].mse_ratio.low, 1);
  EXPECT_THROW(compare_repeated(scene.scene, scene.key, configs, options, 0), invalid_argument);
  EXPECT_THROW(compare_repeated(scene.scene, scene.key, configs, options, 2, 1.0), invalid_argument);
  std::filesystem::remove_all(cache);
}

}  // namespace
}  // namespace stratum::render
