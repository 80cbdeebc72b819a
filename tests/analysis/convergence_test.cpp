// Tests of integration and convergence studies: the least-squares slope
// against a hand-computed fit, the lecture's convergence rates (lecture §2–4)
// with tolerances from the slope's standard error, thread-count invariance,
// and bad input.
#include "stratum/analysis/convergence.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "../registry/error_of.hpp"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

using testing::error_of;

TEST(Convergence, LogLogFitMatchesHandComputation) {
  // Points (ln x, ln y) = (0,0), (1,1), (2,3): slope Sxy/Sxx = 3/2, intercept
  // 4/3 − 3/2 = −1/6, residuals 1/6, −1/3, 1/6, SSE = 1/6, SE = sqrt(SSE/1/Sxx) = sqrt(1/12).
  const std::vector<double> x{1, std::exp(1.0), std::exp(2.0)};
  const std::vector<double> y{1, std::exp(1.0), std::exp(3.0)};
  const SlopeFit fit = fit_log_log(x, y);
  EXPECT_NEAR(fit.slope, 1.5, 1e-14);
  EXPECT_NEAR(fit.intercept, -1.0 / 6, 1e-14);
  EXPECT_NEAR(fit.slope_standard_error, std::sqrt(1.0 / 12), 1e-14);
  EXPECT_EQ(fit.points, 3u);
  const SlopeFit two = fit_log_log(std::vector<double>{1, 4}, std::vector<double>{2, 0.5});
  EXPECT_NEAR(two.slope, -1.0, 1e-15);
  EXPECT_TRUE(std::isnan(two.slope_standard_error));
  EXPECT_THROW(fit_log_log(std::vector<double>{1, 2}, std::vector<double>{1, 0}), invalid_argument);
  EXPECT_THROW(fit_log_log(std::vector<double>{2, 2}, std::vector<double>{1, 3}), invalid_argument);
}

TEST(Convergence, ParseCounts) {
  EXPECT_EQ(parse_counts("16:128"), (std::vector<std::uint64_t>{16, 32, 64, 128}));
  EXPECT_EQ(parse_counts("16:4096:4"), (std::vector<std::uint64_t>{16, 64, 256, 1024, 4096}));
  EXPECT_EQ(parse_counts("16:5000:4"), (std::vector<std::uint64_t>{16, 64, 256, 1024, 4096}));
  EXPECT_EQ(parse_counts("100,1000,10000"), (std::vector<std::uint64_t>{100, 1000, 10000}));
  EXPECT_EQ(parse_counts("7"), (std::vector<std::uint64_t>{7}));
  for (const char* bad : {"16:100", "0:16", "64:16", "a,b", "16,8", "16:64:1", "", "16:", "-4", "16,,32", "1e3"})
    EXPECT_NE(error_of([&] { parse_counts(bad); }).find("invalid n = "), std::string::npos) << bad;
  EXPECT_NE(error_of([] { parse_counts("16:100"); }).find("powers of two"), std::string::npos);
}

TEST(Convergence, ParseSamplerChoice) {
  const auto plain = parse_sampler_choice("jittered");
  EXPECT_EQ(plain.name, "jittered");
  EXPECT_EQ(plain.randomize, "");
  const auto owen = parse_sampler_choice("sobol:owen");
  EXPECT_EQ(owen.name, "sobol");
  EXPECT_EQ(owen.randomize, "owen");
  EXPECT_THROW(parse_sampler_choice("sobol:"), invalid_argument);
  EXPECT_THROW(parse_sampler_choice(":owen"), invalid_argument);
  // The spec grammar, with parameters (registry/spec.hpp).
  const auto strata = parse_sampler_choice("jittered(strata=4x8)");
  EXPECT_EQ(strata.name, "jittered");
  EXPECT_EQ(strata.params, (std::map<std::string, std::string>{{"strata", "4x8"}}));
  EXPECT_NE(error_of([] { parse_sampler_choice("halton:owen-hash"); }).find("invalid sampler = halton:owen-hash"),
            std::string::npos);
}

/// Runs one sampler on one integrand over `counts` with R runs and checks the
/// variance slope. The tolerance is 4 standard errors of the slope, the larger
/// of the fit's own (from the scatter about the line) and the sampling error
/// alone: under normal estimates ln(sample variance) has SE sqrt(2/(R−1)), so
/// the slope has SE sqrt(2/(R−1)) / sqrt(Σ(ln N − mean)²).
///
/// With `log_factor`, the variance is C N^r ln N (Owen 1997 for scrambled
/// nets in d = 2: O(N^-3 (log N)^(d-1))); the least-squares slope of
/// ln V = c + r ln N + ln ln N over these N is r plus the least-squares slope
/// of ln ln N against ln N, which is added to the expected rate exactly.
void expect_rate(const std::string& integrand, const std::string& sampler, double expected,
                 const std::string& counts = "16:16384:4", unsigned runs = 128, bool log_factor = false) {
  ConvergenceRequest request;
  request.integrand.name = integrand;
  request.samplers = {parse_sampler_choice(sampler)};
  request.counts = parse_counts(counts);
  request.runs = runs;
  request.seed = 2024;
  request.threads = 2;
  const auto result = run_convergence(request);
  const auto& entry = result.samplers.front();
  ASSERT_EQ(entry.fitted, "variance");
  double mean = 0, sxx = 0;
  for (const auto& row : entry.rows) mean += std::log(double(row.n)) / entry.rows.size();
  for (const auto& row : entry.rows) sxx += std::pow(std::log(double(row.n)) - mean, 2);
  const double sampling_se = std::sqrt(2.0 / (request.runs - 1)) / std::sqrt(sxx);
  const double se = std::max(entry.slope.slope_standard_error, sampling_se);
  if (log_factor) {
    std::vector<double> n, log_n;
    for (const auto& row : entry.rows) {
      n.push_back(double(row.n));
      log_n.push_back(std::log(double(row.n)));
    }
    expected += fit_log_log(n, log_n).slope;
  }
  EXPECT_NEAR(entry.slope.slope, expected, 4 * se)
      << sampler << " on " << integrand << ": slope " << entry.slope.slope << " ± " << entry.slope.slope_standard_error
      << " (sampling SE " << sampling_se << ")";
  for (const auto& row : entry.rows) {
    // Unbiased samplers: the mean error is within 4.5 standard errors of 0
    // (Šidák over the 6 rows × 5 calls at family α ≈ 1e-4 would be 4.4).
    EXPECT_LT(std::abs(row.mean_error), 4.5 * std::sqrt(row.variance / request.runs)) << sampler << " n=" << row.n;
    EXPECT_NEAR(row.rmse * row.rmse, row.mean_error * row.mean_error + row.variance * (request.runs - 1) / request.runs,
                1e-9 * row.rmse * row.rmse);
    EXPECT_DOUBLE_EQ(row.efficiency, 1 / (row.variance * row.seconds));
  }
}

TEST(Convergence, RandomSamplingRateIsMinusOne) { expect_rate("gaussian", "random", -1.0); }

TEST(Convergence, JitteredOnAnEdgeIsMinusOneAndAHalf) { expect_rate("step", "jittered", -1.5); }

TEST(Convergence, JitteredOnASmoothIntegrandIsMinusTwo) { expect_rate("gaussian", "jittered", -2.0); }

// Owen (1997, "Scrambled net variance for integrals of smooth functions"):
// O(N^-3 (log N)^(d-1)) for d = 2, at powers of two.
TEST(Convergence, OwenScrambledSobolOnSmoothIntegrandsIsMinusThree) {
  expect_rate("gaussian", "sobol:owen", -3.0, "16:4096", 64, true);
  expect_rate("bilinear", "sobol:owen-hash", -3.0, "16:4096", 64, true);
}

TEST(Convergence, ResultsDoNotDependOnThreads) {
  ConvergenceRequest request;
  request.integrand.name = "disk";
  request.samplers = {parse_sampler_choice("sobol:owen"), parse_sampler_choice("random")};
  request.counts = {10, 100, 1000};
  request.runs = 16;
  request.seed = 9;
  request.threads = 1;
  const auto one = run_convergence(request);
  request.threads = 2;
  const auto two = run_convergence(request);
  ASSERT_EQ(one.samplers.size(), 2u);
  EXPECT_EQ(one.samplers[0].sampler.randomize, "owen");
  EXPECT_EQ(one.samplers[1].sampler.randomize, "none");
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(one.samplers[s].rows[k].rmse, two.samplers[s].rows[k].rmse);
      EXPECT_EQ(one.samplers[s].rows[k].variance, two.samplers[s].rows[k].variance);
      EXPECT_EQ(one.samplers[s].rows[k].mean_error, two.samplers[s].rows[k].mean_error);
    }
  EXPECT_EQ(one.samplers[0].slope.slope, two.samplers[0].slope.slope);
}

TEST(Convergence, DeterministicSamplerFitsTheSquaredError) {
  ConvergenceRequest request;
  request.integrand.name = "gaussian";
  request.samplers = {parse_sampler_choice("halton:none")};
  request.counts = {64, 256, 1024};
  request.runs = 2;
  const auto result = run_convergence(request);
  EXPECT_EQ(result.samplers[0].rows[0].variance, 0.0);
  EXPECT_EQ(result.samplers[0].fitted, "mse");
  EXPECT_LT(result.samplers[0].slope.slope, -1.0);  // QMC beats N^-1 on a smooth integrand
}

/// An integrate() request of `sampler` on `integrand` with n points and `runs` runs.
IntegrationRequest integration_request(const std::string& integrand, const std::string& sampler, std::uint64_t n,
                                       unsigned runs = 1) {
  IntegrationRequest request;
  request.integrand.name = integrand;
  request.sampler = parse_sampler_choice(sampler);
  request.n = n;
  request.runs = runs;
  return request;
}

TEST(Convergence, IntegrateOneRunAndReplicates) {
  IntegrationRequest request = integration_request("bilinear", "random", 10000);
  request.seed = 3;
  const auto single = integrate(request);
  EXPECT_EQ(single.standard_error_kind, "iid");
  EXPECT_EQ(single.exact, 0.25);
  // xy has variance 1/9 − 1/16 = 7/144: the iid standard error is ≈ sqrt(7/144/n) (relative SE ~1%).
  EXPECT_NEAR(single.standard_error, std::sqrt(7.0 / 144 / 10000), 0.05 * std::sqrt(7.0 / 144 / 10000));
  EXPECT_LT(std::abs(single.error), 4 * single.standard_error);  // z = 4: α = 6e-5
  request.sampler = parse_sampler_choice("sobol:owen");
  request.runs = 8;
  request.n = 1024;
  const auto replicated = integrate(request);
  EXPECT_EQ(replicated.standard_error_kind, "replicates");
  EXPECT_EQ(replicated.run_estimates.size(), 8u);
  EXPECT_EQ(replicated.randomize, "owen");
  EXPECT_LT(replicated.standard_error, 1e-3 * single.standard_error * 10);
  // t_{7, 0.9999} ≈ 5.4: a replicate t-test at α = 2e-4.
  EXPECT_LT(std::abs(replicated.error), 5.4 * replicated.standard_error);
  request.threads = 2;
  EXPECT_EQ(integrate(request).estimate, replicated.estimate);
}

// The faces' default counts work for every integrand of the registry: each
// sampler skips, and lists, the counts it refuses (2D jittered: non-squares),
// runs the others, and the seeds of the cells it runs are those of a request
// that lists only them.
TEST(Convergence, DefaultCountsWorkForEveryIntegrand) {
  const std::vector<std::uint64_t> defaults = parse_counts(default_counts);
  for (const auto& info : integrands()) {
    ConvergenceRequest request;
    request.integrand.name = info.name;
    request.samplers = {parse_sampler_choice("random"), parse_sampler_choice("jittered")};
    request.counts = defaults;
    request.runs = 2;
    request.skip_refused_counts = true;
    ConvergenceResult result;
    ASSERT_NO_THROW(result = run_convergence(request)) << info.name;
    ASSERT_EQ(result.samplers.size(), 2u);
    EXPECT_EQ(result.samplers[0].rows.size(), defaults.size()) << info.name;
    EXPECT_TRUE(result.samplers[0].skipped.empty()) << info.name;
    const auto& jittered = result.samplers[1];
    EXPECT_EQ(jittered.rows.size() + jittered.skipped.size(), defaults.size()) << info.name;
    EXPECT_GE(jittered.rows.size(), 3u) << info.name;  // enough for a slope and its standard error
    for (const auto& row : jittered.rows) {
      const auto k = static_cast<std::uint64_t>(std::llround(std::sqrt(static_cast<double>(row.n))));
      EXPECT_EQ(k * k, row.n) << info.name;  // d = 2 by default: squares only
    }
    for (const auto& skip : jittered.skipped)
      EXPECT_NE(skip.reason.find("invalid n = " + std::to_string(skip.n)), std::string::npos);
    EXPECT_FALSE(std::isnan(jittered.slope.slope)) << info.name;
  }
  // Without skip_refused_counts a refused count still fails, and a sampler that
  // takes none of the counts fails with skipping too.
  ConvergenceRequest request;
  request.integrand.name = "disk";
  request.samplers = {parse_sampler_choice("jittered")};
  request.counts = defaults;
  request.runs = 2;
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid n = 32"), std::string::npos);
  request.skip_refused_counts = true;
  request.counts = {32, 128};
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("takes none of these counts"), std::string::npos);
  // The skipped cells change nothing in the others.
  request.counts = {16, 32, 64};
  const auto skipping = run_convergence(request);
  request.counts = {16, 64};
  request.skip_refused_counts = false;
  const auto plain = run_convergence(request);
  ASSERT_EQ(skipping.samplers[0].rows.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_EQ(skipping.samplers[0].rows[k].variance, plain.samplers[0].rows[k].variance);
}

// The RQMC interval estimate ± t_{R−1} · SE covers the exact value at its
// level: 400 seeds of random on a smooth integrand (gaussian, n = 64, 8 runs);
// the count of covering intervals lies in the binomial(400, 0.95) band of
// probability 0.999. Its half-width scales with the Student-t quantile, and
// the efficiency is 1 / (one run's variance × one run's seconds).
TEST(Convergence, IntegrateIntervalCoversAtItsLevel) {
  IntegrationRequest request = integration_request("gaussian", "random", 64, 8);
  int covered = 0;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    request.seed = seed;
    const auto r = integrate(request);
    ASSERT_NEAR(r.half_width, r.interval_high - r.estimate, 1e-15);
    covered += r.interval_low <= r.exact && r.exact <= r.interval_high ? 1 : 0;
  }
  const boost::math::binomial band(400, 0.95);
  EXPECT_GE(covered, boost::math::quantile(band, 0.0005));
  EXPECT_LE(covered, boost::math::quantile(boost::math::complement(band, 0.0005)));
  request.seed = 1;
  const auto wide = integrate(request);
  request.confidence = 0.5;
  const auto narrow = integrate(request);
  const boost::math::students_t t7(7);
  EXPECT_NEAR(narrow.half_width / wide.half_width, boost::math::quantile(t7, 0.75) / boost::math::quantile(t7, 0.975),
              1e-12);
  EXPECT_EQ(narrow.confidence, 0.5);
  EXPECT_NEAR(wide.half_width, 2.3646242515927853 * wide.standard_error, 1e-12 * wide.standard_error);  // t_{7, 0.975}
  EXPECT_NEAR(wide.efficiency, 1 / (wide.standard_error * wide.standard_error * 8 * wide.seconds_per_run),
              1e-9 * wide.efficiency);
  EXPECT_GT(wide.seconds_per_run, 0.0);
  for (double level : {0.0, 1.0, -0.5, std::nan("")}) {
    request.confidence = level;
    EXPECT_NE(error_of([&] { integrate(request); }).find("invalid confidence"), std::string::npos) << level;
  }
  // No standard error, no interval: identical runs.
  request.confidence = 0.95;
  request.sampler = parse_sampler_choice("grid");
  const auto fixed = integrate(request);
  EXPECT_TRUE(std::isnan(fixed.interval_low) && std::isnan(fixed.half_width) && std::isnan(fixed.efficiency));
}

TEST(Convergence, BadInput) {
  ConvergenceRequest request;
  request.integrand.name = "gaussian";
  request.samplers = {parse_sampler_choice("jittered")};
  request.counts = {16, 32};
  request.runs = 4;
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid n = 32: equal strata in d = 2"),
            std::string::npos);
  request.counts = {16, 64};
  request.runs = 1;
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid runs = 1"), std::string::npos);
  request.runs = 4;
  request.samplers = {SamplerChoice{"nosuch", "", {}}};  // run_convergence checks what a caller builds by hand
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid sampler = nosuch"), std::string::npos);
  request.samplers = {SamplerChoice{"halton", "owen-hash", {}}};
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid randomize = owen-hash"), std::string::npos);
  request.samplers = {};
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid samplers"), std::string::npos);
  request.samplers = {parse_sampler_choice("random")};
  request.counts = {64, 16};
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid n = 16"), std::string::npos);
  request.counts = {16};
  request.threads = 0;
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid threads = 0"), std::string::npos);
  request.threads = 1;
  request.integrand.name = "nosuch";
  EXPECT_NE(error_of([&] { run_convergence(request); }).find("invalid integrand = nosuch"), std::string::npos);
  IntegrationRequest single;
  single.integrand.name = "disk";
  single.sampler = parse_sampler_choice("random");
  EXPECT_NE(error_of([&] { integrate(single); }).find("invalid n = 0"), std::string::npos);
  single.n = 10;
  single.integrand.d = 3;
  EXPECT_NE(error_of([&] { integrate(single); }).find("invalid d = 3"), std::string::npos);
}

}  // namespace
}  // namespace stratum::analysis
