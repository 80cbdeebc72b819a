/// Statistics across seeds (analysis/paired_statistics.hpp, src/report/seed_statistics.hpp,
/// repeated_comparison.hpp): the paired Student-t interval on log ratios
/// holds its point estimate, shrinks with more seeds and covers the true
/// ratio at its level; an efficiency ratio is quoted only when the time
/// ratio's interval excludes 1. Fixed seeds; the coverage test states its α.
#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <random>

#include "report/repeated_comparison.hpp"
#include "report/seed_statistics.hpp"

namespace stratum::report {
namespace {

/// K pairs (a, b) with log a − log b ~ Normal(log ratio, 0.3²) (b itself
/// varies from pair to pair, as the MSE of a seed does).
std::pair<std::vector<double>, std::vector<double>> pairs(std::mt19937_64& generator, unsigned k, double ratio) {
  std::normal_distribution<double> noise(0, 0.3), level(0, 1);
  std::vector<double> a, b;
  for (unsigned i = 0; i < k; ++i) {
    const double base = std::exp(level(generator));
    b.push_back(base);
    a.push_back(base * ratio * std::exp(noise(generator)));
  }
  return {a, b};
}

TEST(PairedRatioInterval, HoldsTheEstimateAndShrinksWithSeeds) {
  std::mt19937_64 generator(7);
  double previous_width = 1e300;
  for (const unsigned k : {4u, 16u, 64u, 256u}) {
    const auto [a, b] = pairs(generator, k, 2.0);
    const RatioInterval interval = paired_ratio_interval(a, b);
    EXPECT_EQ(interval.count, k);
    EXPECT_LT(interval.low, interval.estimate);
    EXPECT_GT(interval.high, interval.estimate);
    const double width = std::log(interval.high / interval.low);
    // The expected log-width is 2 t σ/√K: it halves (about) from K to 4K.
    EXPECT_LT(width, previous_width) << k;
    previous_width = width;
  }
  // The geometric mean of the ratios, exactly; one pair: a point interval.
  const RatioInterval two = paired_ratio_interval({2, 8}, {1, 1});
  EXPECT_NEAR(two.estimate, 4.0, 1e-12);
  const RatioInterval one = paired_ratio_interval({3}, {2});
  EXPECT_DOUBLE_EQ(one.estimate, 1.5);
  EXPECT_DOUBLE_EQ(one.low, 1.5);
  EXPECT_DOUBLE_EQ(one.high, 1.5);
  // Swapping the pairs inverts the interval.
  const auto [a, b] = pairs(generator, 8, 3.0);
  const RatioInterval forward = paired_ratio_interval(a, b), backward = paired_ratio_interval(b, a);
  EXPECT_NEAR(forward.low * backward.high, 1.0, 1e-12);
  EXPECT_NEAR(forward.estimate * backward.estimate, 1.0, 1e-12);
  EXPECT_THROW(paired_ratio_interval({1, 0}, {1, 1}), std::exception);
  EXPECT_THROW(paired_ratio_interval({1}, {1, 1}), std::exception);
}

// With normal log ratios the t interval is exact: over 2000 trials of K = 6
// pairs the 95% interval covers the true ratio Binomial(2000, 0.95) times;
// two-sided α = 1e-4 acceptance region from the binomial quantiles.
TEST(PairedRatioInterval, CoversTheTrueRatioAtItsLevel) {
  std::mt19937_64 generator(11);
  const int trials = 2000;
  int covered = 0;
  for (int t = 0; t < trials; ++t) {
    const auto [a, b] = pairs(generator, 6, 0.5);
    covered += paired_ratio_interval(a, b).contains(0.5);
  }
  const boost::math::binomial coverage(trials, 0.95);
  EXPECT_GE(covered, boost::math::quantile(coverage, 5e-5));
  EXPECT_LE(covered, boost::math::quantile(boost::math::complement(coverage, 5e-5)));
}

TEST(PairedRatioInterval, MedianAndMeanError) {
  EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2);
  EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_TRUE(std::isnan(median({})));
  const MeanError m = mean_and_error({1, 2, 3, 4});
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_NEAR(m.standard_error, std::sqrt(5.0 / 3 / 4), 1e-15);
}

/// A comparison of two configurations over `times`-long repeats, without renders.
RepeatedComparison synthetic(const std::vector<double>& mse_b, const std::vector<double>& seconds_b) {
  RepeatedComparison c;
  c.labels = {"a", "b"};
  c.repeats = unsigned(mse_b.size());
  c.mse = {std::vector<double>(c.repeats, 1.0), mse_b};
  c.seconds = {std::vector<double>(c.repeats, 1.0), seconds_b};
  c.samples = {std::vector<std::uint32_t>(c.repeats, 4), std::vector<std::uint32_t>(c.repeats, 4)};
  return c;
}

TEST(RepeatedComparison, EfficiencyQuotedOnlyWhenTheTimesDifferBeyondTheirNoise) {
  // Equal work: the times scatter around the baseline's, so the time ratio's
  // interval holds 1 and the efficiency ratio is not quoted.
  const RepeatedComparison same = synthetic({0.5, 0.55, 0.45, 0.5}, {1.1, 0.9, 1.05, 0.97});
  const auto equal = row_statistics(same, same.mse);
  EXPECT_FALSE(equal[0].time_resolved);  // the baseline
  EXPECT_FALSE(equal[1].time_resolved);
  EXPECT_TRUE(equal[1].time_ratio.contains(1.0));
  EXPECT_NE(efficiency_text(equal[1]).find("not resolved"), std::string::npos);
  EXPECT_TRUE(repeated_numbers(same, equal)["rows"]["b"]["efficiency_ratio"].is_null());
  // Twice the time, resolved: efficiency ratio = MSE ratio / time ratio, per seed.
  const RepeatedComparison slow = synthetic({0.5, 0.55, 0.45, 0.5}, {2.1, 1.9, 2.05, 1.97});
  const auto resolved = row_statistics(slow, slow.mse);
  EXPECT_TRUE(resolved[1].time_resolved);
  EXPECT_NEAR(resolved[1].efficiency_ratio.estimate, resolved[1].mse_ratio.estimate / resolved[1].time_ratio.estimate,
              1e-12);
  const auto json = repeated_numbers(slow, resolved)["rows"]["b"];
  EXPECT_NEAR(json["efficiency_ratio"]["estimate"].get<double>(), resolved[1].efficiency_ratio.estimate, 1e-15);
  EXPECT_EQ(json["mse_per_seed"].size(), 4u);
  const Table table = repeated_table(slow, resolved, "caption");
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[1].back(), format_interval(resolved[1].efficiency_ratio));
}

}  // namespace
}  // namespace stratum::report
