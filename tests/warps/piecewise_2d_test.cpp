#include "stratum/warps/piecewise_2d.hpp"

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

using A2 = std::array<double, 2>;

// 4 rows of 5: an all-zero row, zero cells, and a bright "sun".
constexpr std::size_t width = 5, height = 4;
const std::vector<double> image = {
    1,    2, 0, 0.5, 1,  //
    0,    0, 0, 0,   0,  //
    3,    9, 1, 0,   2,  //
    0.25, 1, 4, 1,   0.5,
};

/// Brute force: the inverse of the CDF of a piecewise-constant density on
/// [0,1] with bin weights f (bisection on the summed CDF).
double brute_inverse(const std::vector<double>& f, double u) {
  const auto cdf = [&](double x) {
    const double n = static_cast<double>(f.size());
    double total = 0, below = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      total += f[i];
      below += f[i] * std::clamp(x * n - static_cast<double>(i), 0.0, 1.0);
    }
    return below / total;
  };
  double lo = 0, hi = 1;
  for (int k = 0; k < 80; ++k) (cdf((lo + hi) / 2) >= u ? hi : lo) = (lo + hi) / 2;
  return hi;
}

// The marginal of the row from the row sums, then the column within the row.
TEST(WarpPiecewise2D, SamplesMatchBruteForceMarginalAndConditional) {
  const PiecewiseConstant2D<double> table(image, width, height);
  std::vector<double> row_sums(height, 0.0);
  for (std::size_t r = 0; r < height; ++r)
    for (std::size_t c = 0; c < width; ++c) row_sums[r] += image[r * width + c];
  for (std::uint64_t k = 0; k < 2000; ++k) {
    const A2 u = {uniform01(3, k, 0), uniform01(3, k, 1)};
    const A2 p = table.sample(u);
    ASSERT_NEAR(p[1], brute_inverse(row_sums, u[1]), 1e-12) << k;
    const std::size_t row = std::min(height - 1, static_cast<std::size_t>(p[1] * height));
    const std::vector<double> row_values(image.begin() + row * width, image.begin() + (row + 1) * width);
    ASSERT_NEAR(p[0], brute_inverse(row_values, u[0]), 1e-12) << k;
    ASSERT_NE(row, 1u);  // the all-zero row is never sampled
  }
}

TEST(WarpPiecewise2D, PdfIsTheNormalizedFunctionAndIntegratesToOne) {
  const PiecewiseConstant2D<double> table(image, width, height);
  double mean = 0;
  for (double v : image) mean += v / image.size();
  EXPECT_NEAR(table.integral(), mean, 1e-15);
  for (std::size_t r = 0; r < height; ++r)
    for (std::size_t c = 0; c < width; ++c)
      EXPECT_NEAR(table.pdf({(c + 0.4) / width, (r + 0.7) / height}), image[r * width + c] / mean, 1e-14) << r << c;
  double integral = 0;
  const int cells = 400;  // bin edges are multiples of 1/20: the midpoint rule is exact up to rounding
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) integral += table.pdf({(i + 0.5) / cells, (j + 0.5) / cells});
  EXPECT_NEAR(integral / cells / cells, 1.0, 1e-12);
  EXPECT_EQ(table.pdf({-0.1, 0.5}), 0.0);
  EXPECT_EQ(table.pdf({0.5, 1.1}), 0.0);
}

// χ² on a 20 × 16 grid (4 × 4 per table cell), a member of the χ² family
// (tests/warps/chi2.hpp: Šidák at family α = 0.01).
class WarpPiecewise2DChi2 : public testing::Chi2Fixture<> {};

TEST_F(WarpPiecewise2DChi2, MatchesPdf) {
  const PiecewiseConstant2D<double> table(image, width, height);
  testing::expect_chi2(testing::chi2_test(
      [&](const double* u, double* out) {
        const A2 p = table.sample({u[0], u[1]});
        out[0] = p[0], out[1] = p[1];
      },
      [&](const double* p) {
        return table.pdf({p[0], p[1]});
      },
      testing::Domain::box(0, 1, 0, 1, 20, 16)));
}

TEST(WarpPiecewise2D, InverseRoundTrip) {
  const PiecewiseConstant2D<double> table(image, width, height);
  for (std::uint64_t k = 0; k < 20000; ++k) {
    const A2 u = {uniform01(5, k, 0), uniform01(5, k, 1)};
    const A2 p = table.sample(u);
    ASSERT_GT(table.pdf(p), 0.0);
    const A2 back = table.invert(p);
    ASSERT_NEAR(back[0], u[0], 1e-13) << k;
    ASSERT_NEAR(back[1], u[1], 1e-13) << k;
  }
  // A point in the all-zero row still inverts (uniform conditional) inside [0,1)².
  const A2 zero_row = table.invert({0.5, 0.3});
  EXPECT_NEAR(zero_row[0], 0.5, 1e-15);
  EXPECT_GE(zero_row[1], 0.0);
  EXPECT_LT(zero_row[1], 1.0);
}

TEST(WarpPiecewise2D, FloatAgreesWithDouble) {
  const std::vector<float> image_float(image.begin(), image.end());
  const PiecewiseConstant2D<float> table_float(image_float, width, height);
  const PiecewiseConstant2D<double> table(image, width, height);
  for (std::uint64_t k = 0; k < 5000; ++k) {
    const A2 u = {uniform01(9, k, 0), uniform01(9, k, 1)};
    const auto pf = table_float.sample({float(u[0]), float(u[1])});
    const A2 p = table.sample(u);
    ASSERT_NEAR(pf[0], p[0], 1e-5) << k;
    ASSERT_NEAR(pf[1], p[1], 1e-5) << k;
  }
}

std::string error_of(const WarpParams& params) {
  try {
    make_warp("piecewise-2d", params);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WarpPiecewise2D, BadInput) {
  const std::string count = error_of({{"values", {1, 2, 3, 4, 5}}, {"width", {2}}, {"height", {2}}});
  EXPECT_NE(count.find("invalid values = (5 values): must hold width × height = 2 × 2 = 4 values"), std::string::npos)
      << count;
  const std::string negative = error_of({{"values", {1, 2, 3, -4}}, {"width", {2}}, {"height", {2}}});
  EXPECT_NE(negative.find("invalid values[3] = -4: must be a finite real in [0, inf)"), std::string::npos) << negative;
  const std::string zero = error_of({{"values", {0, 0, 0, 0}}, {"width", {2}}, {"height", {2}}});
  EXPECT_NE(zero.find("invalid values = (all 4 values zero)"), std::string::npos) << zero;
  EXPECT_NE(error_of({{"values", {1, 2, INFINITY, 4}}, {"width", {2}}, {"height", {2}}})
                .find("invalid values[2] = inf: must be a finite real"),
            std::string::npos);
  EXPECT_NE(error_of({{"values", {1, 2}}, {"width", {2}}, {"height", {0}}})
                .find("invalid height = 0: must be an integer in [1, 2^40]"),
            std::string::npos);
  EXPECT_NE(error_of({{"values", {1, 2}}, {"width", {1.5}}, {"height", {1}}})
                .find("invalid width = 1.5: must be an integer in [1, 2^40]"),
            std::string::npos);
  EXPECT_NE(error_of({{"values", {1, 2}}, {"width", {2}}}).find("invalid height = (missing)"), std::string::npos);
  EXPECT_EQ(error_of({{"values", {1, 2}}, {"width", {2}}, {"height", {1}}}), "");
}

TEST(WarpPiecewise2D, RegistryEntryMatchesTheCore) {
  const auto warp =
      make_warp("piecewise-2d", {{"values", image}, {"width", {double(width)}}, {"height", {double(height)}}});
  const PiecewiseConstant2D<double> table(image, width, height);
  const double u[4] = {0.1, 0.5, 0.95, 0.2};
  const auto p = warp_sample(*warp, u, 2);
  const auto pdf = warp_pdf(*warp, p.data(), 2);
  for (int i = 0; i < 2; ++i) {
    const A2 q = table.sample({u[2 * i], u[2 * i + 1]});
    EXPECT_EQ(p[2 * i], q[0]);
    EXPECT_EQ(p[2 * i + 1], q[1]);
    EXPECT_EQ(pdf[i], table.pdf(q));
  }
}

}  // namespace
}  // namespace stratum
