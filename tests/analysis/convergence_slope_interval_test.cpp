// The confidence interval of a convergence slope (slope_interval: the
// jackknife over runs): against a brute-force jackknife, its coverage of the
// true rate −1 of `random` over 200 seeds, and its faces in run_convergence.
#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "../registry/error_of.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

using testing::error_of;

double sample_variance(const std::vector<double>& values) {
  double mean = 0, sum = 0;
  for (double v : values) mean += v / values.size();
  for (double v : values) sum += (v - mean) * (v - mean);
  return sum / (values.size() - 1);
}

TEST(SlopeInterval, EqualsABruteForceJackknife) {
  const std::vector<double> x{16, 64, 256};
  const unsigned runs = 5;
  const std::vector<double> estimates{0.51,  0.47,  0.55, 0.40,  0.52,    // N = 16
                                      0.49,  0.505, 0.52, 0.47,  0.50,    // N = 64
                                      0.501, 0.497, 0.51, 0.492, 0.503};  // N = 256
  auto slope_without = [&](int left_out) {
    std::vector<double> variances;
    for (std::size_t k = 0; k < x.size(); ++k) {
      std::vector<double> cell;
      for (unsigned r = 0; r < runs; ++r)
        if (int(r) != left_out) cell.push_back(estimates[k * runs + r]);
      variances.push_back(sample_variance(cell));
    }
    return fit_log_log(x, variances).slope;
  };
  double mean = 0, spread = 0;
  std::vector<double> partial;
  for (unsigned r = 0; r < runs; ++r) partial.push_back(slope_without(int(r)));
  for (double s : partial) mean += s / runs;
  for (double s : partial) spread += (s - mean) * (s - mean);
  const double se = std::sqrt((runs - 1.0) / runs * spread);
  const SlopeInterval interval = slope_interval(x, estimates, runs, 0.9);
  EXPECT_NEAR(interval.slope, slope_without(-1), 1e-12);
  EXPECT_NEAR(interval.standard_error, se, 1e-12);
  const double t = boost::math::quantile(boost::math::students_t(runs - 1), 0.95);
  EXPECT_NEAR(interval.low, interval.slope - t * se, 1e-12);
  EXPECT_NEAR(interval.high, interval.slope + t * se, 1e-12);
  EXPECT_EQ(interval.confidence, 0.9);
  EXPECT_NE(error_of([&] { slope_interval(x, estimates, 2, 0.9); }).find("invalid runs = 2"), std::string::npos);
  EXPECT_NE(error_of([&] { slope_interval(x, estimates, 4, 0.9); }).find("invalid estimates = 15"), std::string::npos);
  EXPECT_NE(error_of([&] { slope_interval(x, estimates, runs, 1.0); }).find("invalid confidence"), std::string::npos);
}

/// Runs `random` on `integrand` at N = 16, 64, 256, 1024 with 16 runs for
/// seeds 0..199 and counts the 95% intervals that hold the true slope −1
/// (the variance of i.i.d. estimates is σ²/N exactly).
int covering_seeds(const std::string& integrand) {
  ConvergenceRequest request;
  request.integrand.name = integrand;
  request.samplers = {parse_sampler_choice("random")};
  request.counts = parse_counts("16:1024:4");
  request.runs = 16;
  int covered = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    request.seed = seed;
    const auto entry = run_convergence(request).samplers.front();
    EXPECT_EQ(entry.fitted, "variance");
    EXPECT_NEAR(entry.interval.slope, entry.slope.slope, 1e-12);
    covered += entry.interval.low <= -1 && -1 <= entry.interval.high ? 1 : 0;
  }
  return covered;
}

// Coverage inside the binomial(200, 0.95) band of probability 0.999 for the
// two integrands together (Šidák: 0.9995 each). The fit's residual standard
// error, which converge printed as ±, covers 123 (gaussian) and 121 (step)
// of these 200 seeds as slope ± SE.
TEST(SlopeInterval, CoversTheTrueRateOfRandomSampling) {
  const boost::math::binomial band(200, 0.95);
  const double alpha = 1 - std::sqrt(0.999);
  for (const char* integrand : {"gaussian", "step"}) {
    const int covered = covering_seeds(integrand);
    EXPECT_GE(covered, boost::math::quantile(band, alpha / 2)) << integrand;
    EXPECT_LE(covered, boost::math::quantile(boost::math::complement(band, alpha / 2))) << integrand;
  }
}

TEST(SlopeInterval, NaNWhereRunsDoNotDiffer) {
  ConvergenceRequest request;
  request.integrand.name = "gaussian";
  request.samplers = {parse_sampler_choice("halton:none"), parse_sampler_choice("random")};
  request.counts = {64, 256, 1024};
  request.runs = 4;
  request.confidence = 0.8;
  const auto result = run_convergence(request);
  EXPECT_EQ(result.samplers[0].fitted, "mse");
  EXPECT_TRUE(std::isnan(result.samplers[0].interval.low) && std::isnan(result.samplers[0].interval.standard_error));
  EXPECT_EQ(result.samplers[1].interval.confidence, 0.8);
  EXPECT_LT(result.samplers[1].interval.low, result.samplers[1].interval.high);
  request.runs = 2;  // a jackknife needs 3 runs
  EXPECT_TRUE(std::isnan(run_convergence(request).samplers[1].interval.low));
  request.confidence = 1.5;
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid confidence = 1.5"), std::string::npos);
}

}  // namespace
}  // namespace stratum::analysis
