// Star discrepancy: published values (the Hammersley closed form, Thiémard's
// bounds for 10 Halton points), Thiémard bounds against the exact value, and
// the registry entry "star" with its bad-input messages.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "stratum/analysis/measures.hpp"
#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/util/error.hpp"

namespace {

using stratum::analysis::MeasureRequest;
using stratum::analysis::PointView;
namespace sa = stratum::analysis;

std::vector<double> random_points(std::size_t n, std::size_t d, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x(n * d);
  for (auto& v : x) v = u(rng);
  return x;
}

double radical_inverse(std::uint64_t i, unsigned base) {
  double r = 0, f = 1.0 / base;
  for (; i > 0; i /= base, f /= base) r += f * static_cast<double>(i % base);
  return r;
}

TEST(StarDiscrepancyPublished, HammersleyClosedForm) {
  // The 2D Hammersley set (i/N, φ2(i)), i < N = 2^m, has
  //   N·D*_N = m/3 + 13/9 − (−1)^m · 4/(9·2^m)
  // (De Clerck 1986, "A method for exact calculation of the star-discrepancy
  // of plane sets applied to the sequences of Hammersley", Monatsh. Math. 101;
  // restated by Kritzer 2006, J. Théor. Nombres Bordeaux 18). m = 1 is left
  // out: its two points (0,0), (1/2,1/2) give 3/4 by hand ([0,1/2]² holds both).
  for (unsigned m = 2; m <= 14; ++m) {
    const std::size_t n = std::size_t{1} << m;
    std::vector<double> x(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      x[2 * i] = static_cast<double>(i) / static_cast<double>(n);
      x[2 * i + 1] = radical_inverse(i, 2);
    }
    const double expected =
        (m / 3.0 + 13.0 / 9.0 - (m % 2 == 0 ? 1.0 : -1.0) * 4.0 / (9.0 * static_cast<double>(n))) / n;
    EXPECT_NEAR(sa::star_discrepancy_2d(PointView{x.data(), n, 2}), expected, 1e-14 * expected) << "m = " << m;
  }
}

TEST(StarDiscrepancyPublished, HaltonTenPointsWithinThiemardsBounds) {
  // Thiémard's own program on the first 10 Halton points in bases 2 and 3
  // (index 0 first) reports 0.266667 ≤ D* ≤ 0.267443 (J. Burkardt's
  // star_discrepancy test output, halton_02_00010_output.txt, epsilon 0.001).
  std::vector<double> x;
  for (std::uint64_t i = 0; i < 10; ++i) x.insert(x.end(), {radical_inverse(i, 2), radical_inverse(i, 3)});
  const double exact = sa::star_discrepancy_2d(PointView{x.data(), 10, 2});
  EXPECT_GE(exact, 0.266667 - 1e-6);
  EXPECT_LE(exact, 0.267443 + 1e-6);
}

TEST(StarDiscrepancyBounds, BracketTheExactValue) {
  struct Case {
    std::size_t n, d;
    double delta;
  };
  for (const Case c : {Case{50, 1, 0.01}, Case{200, 2, 0.02}, Case{1000, 2, 0.01}, Case{60, 3, 0.05},
                       Case{300, 3, 0.05}, Case{25, 4, 0.1}}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto x = random_points(c.n, c.d, seed * 31 + c.d);
      const PointView view{x.data(), c.n, c.d};
      const double exact = sa::star_discrepancy_exact(view);
      const auto b = sa::star_discrepancy_bounds(view, c.delta, std::uint64_t{1} << 26, 2);
      EXPECT_LE(b.lower, exact + 1e-12) << "n = " << c.n << " d = " << c.d;
      EXPECT_GE(b.upper, exact - 1e-12) << "n = " << c.n << " d = " << c.d;
      EXPECT_LE(b.upper - b.lower, c.delta + 1e-12);
      EXPECT_GT(b.boxes, 0u);
    }
  }
}

TEST(StarDiscrepancyBounds, BracketTheExactValueWithTiesAndOnes) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> k(0, 4);
  for (std::size_t d : {2u, 3u}) {
    std::vector<double> x(40 * d);
    for (auto& v : x) v = k(rng) / 4.0;
    const PointView view{x.data(), 40, d};
    const double exact = sa::star_discrepancy_exact(view);
    const auto b = sa::star_discrepancy_bounds(view, 0.02);
    EXPECT_LE(b.lower, exact + 1e-12);
    EXPECT_GE(b.upper, exact - 1e-12);
  }
}

TEST(StarDiscrepancyBounds, SameForAnyThreadCount) {
  const auto x = random_points(400, 3, 9);
  const PointView view{x.data(), 400, 3};
  const auto one = sa::star_discrepancy_bounds(view, 0.05, std::uint64_t{1} << 26, 1);
  const auto four = sa::star_discrepancy_bounds(view, 0.05, std::uint64_t{1} << 26, 4);
  EXPECT_EQ(one.lower, four.lower);
  EXPECT_EQ(one.upper, four.upper);
  EXPECT_EQ(one.boxes, four.boxes);
}

std::string error_of(const std::vector<double>& x, std::size_t n, std::size_t d,
                     std::map<std::string, std::string> params) {
  try {
    sa::compute_measure("star", PointView{x.data(), n, d}, MeasureRequest{std::move(params), 1});
  } catch (const stratum::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(StarMeasure, ExactKindForSmallInputs) {
  const auto x = random_points(100, 2, 1);
  const auto r = sa::compute_measure("star", PointView{x.data(), 100, 2}, {});
  EXPECT_EQ(r.kind, "exact");
  EXPECT_EQ(r.value, sa::star_discrepancy_2d(PointView{x.data(), 100, 2}));
  const auto y = random_points(100, 1, 1);
  EXPECT_EQ(sa::compute_measure("star", PointView{y.data(), 100, 1}, {}).value,
            sa::star_discrepancy_1d(PointView{y.data(), 100, 1}));
}

TEST(StarMeasure, BoundsKindWhenAskedOrBeyondTheExactLimit) {
  const auto x = random_points(200, 2, 2);
  const auto r = sa::compute_measure("star", PointView{x.data(), 200, 2},
                                     MeasureRequest{{{"method", "bounds"}, {"delta", "0.02"}}, 1});
  EXPECT_EQ(r.kind, "bounds");
  ASSERT_TRUE(r.lower && r.upper);
  const double exact = sa::star_discrepancy_2d(PointView{x.data(), 200, 2});
  EXPECT_LE(*r.lower, exact);
  EXPECT_GE(*r.upper, exact);
  EXPECT_EQ(r.value, *r.upper);
  EXPECT_EQ(r.extras.at("delta"), 0.02);
  // d = 6, n = 300 > star_dem_max_points(6) = 260, so auto gives bounds
  // (default delta 0.2 for d = 6); n = 40 is exact.
  const auto y = random_points(300, 6, 2);
  const auto auto_result = sa::compute_measure("star", PointView{y.data(), 300, 6}, {});
  EXPECT_EQ(auto_result.kind, "bounds");
  EXPECT_EQ(auto_result.extras.at("delta"), 0.2);
  EXPECT_LE(*auto_result.upper - *auto_result.lower, 0.2 + 1e-12);
  EXPECT_LE(*auto_result.lower, *auto_result.upper);
  const auto small = sa::compute_measure("star", PointView{y.data(), 40, 6}, {});
  EXPECT_EQ(small.kind, "exact");
  EXPECT_EQ(small.value, sa::star_discrepancy_grid(PointView{y.data(), 40, 6}));
}

TEST(StarMeasure, DemLimitsShrinkWithD) {
  EXPECT_EQ(sa::star_dem_max_points(3), 14000u);
  EXPECT_EQ(sa::star_dem_max_points(8), 80u);
  for (std::size_t d = 4; d <= 20; ++d) EXPECT_LE(sa::star_dem_max_points(d), sa::star_dem_max_points(d - 1)) << d;
  EXPECT_EQ(sa::star_dem_max_points(9), 53u);   // 53^5.5 ≤ 80^5 < 54^5.5
  EXPECT_EQ(sa::star_dem_max_points(10), 38u);  // 38^6 ≤ 80^5 < 39^6
  EXPECT_TRUE(sa::star_exact_feasible(14000, 3));
  EXPECT_FALSE(sa::star_exact_feasible(14001, 3));
  EXPECT_THROW(sa::star_dem_max_points(2), stratum::invalid_argument);
}

TEST(StarMeasure, BadInputNamesTheArgument) {
  const auto x = random_points(30, 8, 3);
  const auto wide = random_points(100, 8, 3);  // n = 100 > star_dem_max_points(8) = 80
  const std::string too_large = error_of(wide, 100, 8, {{"method", "exact"}});
  EXPECT_NE(too_large.find("invalid d = 8"), std::string::npos) << too_large;
  EXPECT_NE(too_large.find("n <= 80 at d = 8 (here n = 100)"), std::string::npos) << too_large;
  EXPECT_NE(too_large.find("method=bounds"), std::string::npos) << too_large;
  EXPECT_NE(error_of(x, 30, 8, {{"method", "fast"}}).find("invalid method = fast: must be one of auto, exact, bounds"),
            std::string::npos);
  EXPECT_NE(error_of(x, 30, 8, {{"delta", "0"}}).find("invalid delta = 0"), std::string::npos);
  EXPECT_NE(error_of(x, 30, 8, {{"delta", "abc"}}).find("invalid delta = abc"), std::string::npos);
  EXPECT_NE(error_of(x, 30, 8, {{"max_boxes", "-3"}}).find("invalid max_boxes = -3"), std::string::npos);
  EXPECT_NE(
      error_of(x, 30, 8, {{"lines", "5"}}).find("invalid measure-param = lines=5: star takes method, delta, max_boxes"),
      std::string::npos);
  const std::string budget = error_of(x, 30, 8, {{"method", "bounds"}, {"delta", "0.001"}, {"max_boxes", "100"}});
  EXPECT_NE(budget.find("invalid delta = 0.001"), std::string::npos) << budget;
  EXPECT_NE(budget.find("max_boxes = 100"), std::string::npos) << budget;
  const std::vector<double> one_point{0.5, 0.5};
  EXPECT_NE(error_of(one_point, 1, 2, {}).find("invalid n = 1"), std::string::npos);
  std::vector<double> outside = random_points(4, 2, 4);
  outside[5] = 1.5;
  EXPECT_NE(error_of(outside, 4, 2, {}).find("invalid point[2][1] = 1.5"), std::string::npos);
  // n beyond the 2D sweep's limit with method=exact names n and method=bounds.
  const std::size_t big = sa::kStarExact2dMaxPoints + 1;
  std::vector<double> many(2 * big, 0.25);
  const std::string n_error = error_of(many, big, 2, {{"method", "exact"}});
  EXPECT_NE(n_error.find("invalid n = " + std::to_string(big)), std::string::npos) << n_error;
  EXPECT_NE(n_error.find("method=bounds"), std::string::npos) << n_error;
}

}  // namespace
