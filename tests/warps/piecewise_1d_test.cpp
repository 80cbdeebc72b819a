#include "stratum/warps/piecewise_1d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "chi2.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/warp_registry.hpp"

namespace stratum {
namespace {

const std::vector<double> values = {0.5, 2, 0, 0, 3.25, 1, 0.125, 4, 0, 2.5};

/// Brute force: the CDF of the piecewise-constant density at x, by summing bins.
double brute_cdf(const std::vector<double>& f, double x) {
  const double n = static_cast<double>(f.size());
  double total = 0, below = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    total += f[i];
    const double lo = static_cast<double>(i) / n, hi = static_cast<double>(i + 1) / n;
    below += f[i] * std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
  }
  return below / total;
}
/// Brute force: the smallest x with brute_cdf(x) >= u, by bisection.
double brute_inverse(const std::vector<double>& f, double u) {
  double lo = 0, hi = 1;
  for (int k = 0; k < 80; ++k) {
    const double mid = (lo + hi) / 2;
    (brute_cdf(f, mid) >= u ? hi : lo) = mid;
  }
  return hi;
}

TEST(WarpPiecewise1D, CdfAndSamplesMatchBruteForce) {
  const PiecewiseConstant1D<double> table(values);
  double mean = 0;
  for (double v : values) mean += v / values.size();
  EXPECT_NEAR(table.integral(), mean, 1e-15);
  for (std::size_t i = 0; i <= values.size(); ++i)
    EXPECT_NEAR(table.cdf()[i], brute_cdf(values, static_cast<double>(i) / values.size()), 1e-15) << i;
  for (std::uint64_t k = 0; k < 2000; ++k) {
    const double u = uniform01(3, k, 0);
    ASSERT_NEAR(table.sample(u), brute_inverse(values, u), 1e-12) << u;
  }
  EXPECT_EQ(table.sample(0.0), 0.0);
}

TEST(WarpPiecewise1D, PdfIsTheNormalizedFunctionAndIntegratesToOne) {
  const PiecewiseConstant1D<double> table(values);
  double integral = 0;
  const int cells = 100000;  // the bins' edges are multiples of 1/10: the midpoint rule is exact up to rounding
  for (int k = 0; k < cells; ++k) integral += table.pdf((k + 0.5) / cells) / cells;
  EXPECT_NEAR(integral, 1.0, 1e-12);
  for (std::size_t i = 0; i < values.size(); ++i)
    EXPECT_DOUBLE_EQ(table.pdf((i + 0.3) / values.size()), values[i] / table.integral()) << i;
  EXPECT_EQ(table.pdf(-0.1), 0.0);
  EXPECT_EQ(table.pdf(1.5), 0.0);
  EXPECT_EQ(table.pdf(NAN), 0.0);
}

// χ² on 40 equal bins (4 per table bin), a member of the χ² family
// (tests/warps/chi2.hpp: Šidák at family α = 0.01).
class WarpPiecewise1DChi2 : public testing::Chi2Fixture<> {};

TEST_F(WarpPiecewise1DChi2, MatchesPdf) {
  const PiecewiseConstant1D<double> table(values);
  testing::Chi2Options options;
  options.input_dim = 1;
  testing::expect_chi2(testing::chi2_test([&](const double* u, double* out) { out[0] = table.sample(u[0]); },
                                          [&](const double* p) { return table.pdf(p[0]); },
                                          testing::Domain::interval(0, 1, 40), options));
}

TEST(WarpPiecewise1D, InverseRoundTripAndEmptyBinsNeverSampled) {
  const PiecewiseConstant1D<double> table(values);
  for (std::uint64_t k = 0; k < 20000; ++k) {
    const double u = uniform01(5, k, 0);
    const double x = table.sample(u);
    ASSERT_GT(table.pdf(x), 0.0) << u;  // zero-valued bins are skipped
    ASSERT_NEAR(table.invert(x), u, 1e-14) << u;
    ASSERT_NEAR(table.sample(table.invert(x)), x, 1e-14) << u;
  }
  EXPECT_NEAR(table.invert(1.0), 1.0, 1e-15);
  EXPECT_EQ(table.invert(0.0), 0.0);
}

// Strata of u map to intervals of equal probability (by the brute-force CDF):
// a jittered input puts one point in each.
TEST(WarpPiecewise1D, StratifiedInputStaysStratifiedInProbability) {
  const PiecewiseConstant1D<double> table(values);
  const int n = 256;
  std::vector<int> hits(n, 0);
  for (int i = 0; i < n; ++i) {
    const double x = table.sample((i + uniform01(7, i, 0)) / n);
    ++hits[std::min(n - 1, static_cast<int>(brute_cdf(values, x) * n))];
  }
  for (int i = 0; i < n; ++i) ASSERT_EQ(hits[i], 1) << i;
}

TEST(WarpPiecewise1D, FloatAgreesWithDouble) {
  const std::vector<float> values_float(values.begin(), values.end());
  const PiecewiseConstant1D<float> table_float(values_float);
  const PiecewiseConstant1D<double> table(values);
  for (std::uint64_t k = 0; k < 5000; ++k) {
    const double u = uniform01(9, k, 0);
    const float x = table_float.sample(static_cast<float>(u));
    ASSERT_LT(x, 1.0f);
    ASSERT_NEAR(x, table.sample(u), 1e-6) << u;
  }
}

std::string error_of(const WarpParams& params) {
  try {
    make_warp("piecewise-1d", params);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WarpPiecewise1D, BadInput) {
  const std::string negative = error_of({{"values", {1, -2, 3}}, {"width", {3}}});
  EXPECT_NE(negative.find("invalid values[1] = -2: must be a finite real in [0, inf)"), std::string::npos) << negative;
  const std::string zero = error_of({{"values", {0, 0}}, {"width", {2}}});
  EXPECT_NE(zero.find("invalid values = (all 2 values zero): at least one value must be positive"), std::string::npos)
      << zero;
  EXPECT_NE(error_of({{"values", {1, NAN}}, {"width", {2}}}).find("invalid values[1] = nan: must be a finite real"),
            std::string::npos);
  const std::string count = error_of({{"values", {1, 2, 3}}, {"width", {4}}});
  EXPECT_NE(count.find("invalid values = (3 values): must hold width = 4 values"), std::string::npos) << count;
  for (double bad : {0.0, -3.0, 2.5}) {
    const std::string width = error_of({{"values", {1, 2}}, {"width", {bad}}});
    EXPECT_NE(width.find("invalid width = " + to_message_string(bad) + ": must be an integer in [1, 2^40]"),
              std::string::npos)
        << width;
  }
  EXPECT_NE(error_of({{"values", {1, 2}}, {"width", {2, 2}}}).find("invalid width = (2 values): must be an integer"),
            std::string::npos);
  EXPECT_NE(error_of({{"width", {2}}}).find("invalid values = (missing)"), std::string::npos);
  const std::string empty = [] {
    try {
      PiecewiseConstant1D<double> table(std::vector<double>{});
    } catch (const invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  EXPECT_NE(empty.find("invalid values = (0 values): needs at least one value"), std::string::npos) << empty;
  EXPECT_EQ(error_of({{"values", {1, 2}}, {"width", {2}}}), "");
}

TEST(WarpPiecewise1D, RegistryEntryMatchesTheCore) {
  const auto warp = make_warp("piecewise-1d", {{"values", values}, {"width", {double(values.size())}}});
  const PiecewiseConstant1D<double> table(values);
  const double u[3] = {0.1, 0.5, 0.95};
  const auto x = warp_sample(*warp, u, 3);
  const auto pdf = warp_pdf(*warp, x.data(), 3);
  const auto back = warp_invert(*warp, x.data(), 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(x[i], table.sample(u[i]));
    EXPECT_EQ(pdf[i], table.pdf(x[i]));
    EXPECT_NEAR(back[i], u[i], 1e-15);
  }
}

}  // namespace
}  // namespace stratum
