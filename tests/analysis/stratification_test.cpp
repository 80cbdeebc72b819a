#include "stratum/analysis/stratification.hpp"

#include <gtest/gtest.h>

#include "../registry/error_of.hpp"

#include <string>
#include <vector>

#include "stratum/analysis/measures.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

PointSet points_of(const std::string& sampler, std::size_t n, unsigned d, const std::string& randomize = "none",
                   std::uint64_t seed = 1) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  request.randomize = randomize;
  return generate_points(sampler, request);
}

PointView view(const PointSet& points) { return {points.data.get(), points.n, points.d}; }

/// One column of a point set, as a 1D set.
std::vector<double> column(const PointSet& points, std::size_t j) {
  std::vector<double> x;
  for (std::size_t i = 0; i < points.n; ++i) x.push_back(points(i, j));
  return x;
}

using testing::error_of;

// Sobol' dimensions 0-1 form a (0,2)-sequence in base 2, so every 2^m prefix
// is a (0,m,2)-net, unscrambled or Owen-scrambled (Owen 1995 keeps nets).
TEST(Stratification, SobolTwoDimensionsIsAZeroNet) {
  for (unsigned m = 1; m <= 12; ++m)
    for (const std::string randomize : {"none", "owen-hash"}) {
      const PointSet sobol = points_of("sobol", std::size_t{1} << m, 2, randomize);
      const NetQuality quality = net_t_value(view(sobol), 2);
      EXPECT_EQ(quality.t, 0u) << "m " << m << " " << randomize;
      EXPECT_EQ(quality.m, m);
      if (m <= 6) {
        EXPECT_EQ(net_t_value_reference(view(sobol), 2).t, 0u);
      }
    }
}

// Sobol' in 3D is a (1,3)-sequence in base 2 (t = Σ (deg p_j − 1) = 0+0+1), so
// its 2^m prefixes have t ≤ 1; and (0,m,s)-nets in base b need s ≤ b + 1
// when m ≥ 2 (Niederreiter 1992, Cor. 4.21), so t = 1 exactly.
TEST(Stratification, SobolThreeDimensionsHasTOne) {
  for (unsigned m = 2; m <= 11; ++m) {
    const PointSet sobol = points_of("sobol", std::size_t{1} << m, 3);
    EXPECT_EQ(net_t_value(view(sobol), 2).t, 1u) << "m " << m;
    if (m <= 6) {
      EXPECT_EQ(net_t_value_reference(view(sobol), 2).t, 1u) << "m " << m;
    }
  }
}

// Hammersley (i/N, φ_2(i)) at N = 2^m is a (0,m,2)-net in base 2; Halton's
// coordinates are van der Corput sequences, (0,1)-sequences in their bases:
// base 2 for coordinate 0, base 3 for coordinate 1 (prefixes of b^m points).
TEST(Stratification, HammersleyAndHaltonProjections) {
  for (unsigned m = 1; m <= 10; ++m) {
    const PointSet hammersley = points_of("hammersley", std::size_t{1} << m, 2);
    EXPECT_EQ(net_t_value(view(hammersley), 2).t, 0u) << m;
  }
  const PointSet halton2 = points_of("halton", 1024, 2);
  const std::vector<double> x = column(halton2, 0);
  EXPECT_EQ(net_t_value(PointView{x.data(), x.size(), 1}, 2).t, 0u);
  const PointSet halton3 = points_of("halton", 729, 2);
  const std::vector<double> y = column(halton3, 1);
  EXPECT_EQ(net_t_value(PointView{y.data(), y.size(), 1}, 3).t, 0u);
  EXPECT_EQ(net_t_value_reference(PointView{y.data(), y.size(), 1}, 3).t, 0u);
  // The diagonal set (y, y): a split (d1, d2) with both parts ≥ 1 leaves the
  // off-diagonal intervals empty, so only m − t ≤ 1 passes: t = m − 1 = 5.
  std::vector<double> yy;
  for (double v : y) yy.insert(yy.end(), {v, v});
  EXPECT_EQ(net_t_value(PointView{yy.data(), y.size(), 2}, 3).t, 5u);
  EXPECT_EQ(net_t_value_reference(PointView{yy.data(), y.size(), 2}, 3).t, 5u);
}

// Fast counting against enumeration of every elementary interval, on sets
// with every t from 0 to m: random sets, nets, nets with one point moved.
TEST(Stratification, FastMatchesEnumeration) {
  for (unsigned d = 1; d <= 4; ++d)
    for (unsigned m = 1; m <= 6; ++m)
      for (std::uint64_t seed = 0; seed < 3; ++seed) {
        const std::size_t n = std::size_t{1} << m;
        PointSet random = points_of("random", n, d, "", seed);
        EXPECT_EQ(net_t_value(view(random), 2).t, net_t_value_reference(view(random), 2).t);
        PointSet sobol = points_of("sobol", n, d, "owen-hash", seed);
        EXPECT_EQ(net_t_value(view(sobol), 2).t, net_t_value_reference(view(sobol), 2).t);
        sobol.data[(seed % n) * d] = 0.999 - sobol.data[(seed % n) * d] * 0.5;  // move one point
        EXPECT_EQ(net_t_value(view(sobol), 2).t, net_t_value_reference(view(sobol), 2).t) << d << " " << m;
      }
  // Base 3 with random points and N = 27, 81.
  for (std::size_t n : {27u, 81u}) {
    const PointSet random = points_of("random", n, 2, "", 5);
    EXPECT_EQ(net_t_value(view(random), 3).t, net_t_value_reference(view(random), 3).t);
  }
}

// A random set is no net below t = m: with t = m − 1 each of the b intervals
// of width 1/b of one axis would need exactly b^(m−1) points, which 64 i.i.d.
// uniform points satisfy with probability 64!/(32!² 2^64) ≈ 0.1 per axis, for
// both axes and the other splits at once far less; these seeds are checked.
TEST(Stratification, RandomSetHasTEqualToM) {
  for (std::uint64_t seed = 0; seed < 5; ++seed) {
    const PointSet random = points_of("random", 64, 2, "", seed);
    EXPECT_EQ(net_t_value(view(random), 2).t, 6u);
  }
}

TEST(Stratification, LatinProperty) {
  for (unsigned d : {1u, 2u, 3u})
    for (std::size_t n : {7u, 16u, 100u}) {
      const PointSet rooks = points_of("n-rooks", n, d, "", 3);
      const LatinCheck check = latin_check(view(rooks));
      EXPECT_TRUE(check.latin) << d << " " << n;
      EXPECT_EQ(check.worst_count, 1u);
      EXPECT_EQ(check.empty_strata, 0u);
    }
  EXPECT_TRUE(latin_check(view(points_of("multi-jittered", 16, 2, "", 4))).latin);
  EXPECT_TRUE(latin_check(view(points_of("hammersley", 64, 2))).latin);
  // Random: Latin with probability N!/N^N (1e-42 for N = 100).
  const LatinCheck random = latin_check(view(points_of("random", 100, 2, "", 9)));
  EXPECT_FALSE(random.latin);
  EXPECT_GT(random.worst_count, 1u);
  // m×m grid of centres: each occupied stratum (width 1/m²) holds m points.
  const PointSet grid = points_of("grid", 25, 2);
  const LatinCheck g = latin_check(view(grid));
  EXPECT_FALSE(g.latin);
  EXPECT_EQ(g.worst_count, 5u);
  EXPECT_EQ(g.empty_strata, 2u * (25 - 5));
}

TEST(Stratification, MeasuresAndBadInput) {
  const PointSet sobol = points_of("sobol", 256, 2);
  const MeasureResult t = compute_measure("t-value", view(sobol), {});
  EXPECT_EQ(t.value, 0);
  EXPECT_EQ(t.extras.at("m"), 8);
  const PointSet sobol3 = points_of("sobol", 243, 3);
  EXPECT_NE(error_of([&] { compute_measure("t-value", view(sobol3), {}); }).find("invalid n = 243"), std::string::npos);
  EXPECT_EQ(compute_measure("t-value", view(sobol3), {{{"base", "3"}}, 1}).extras.at("m"), 5);
  EXPECT_NE(error_of([&] {
              compute_measure("t-value", view(sobol), {{{"base", "1"}}, 1});
            }).find("invalid base = 1"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              compute_measure("t-value", view(sobol), {{{"base", "x2"}}, 1});
            }).find("invalid base = x2"),
            std::string::npos);
  EXPECT_NE(error_of([&] { net_t_value(view(sobol), 0); }).find("invalid base = 0"), std::string::npos);
  const PointSet rooks = points_of("n-rooks", 10, 2, "", 1);
  const MeasureResult latin = compute_measure("latin", view(rooks), {});
  EXPECT_EQ(latin.value, 1);
  EXPECT_EQ(latin.extras.at("worst_count"), 1);
  // Too much work for an exact t-value: the message says what to reduce.
  const PointSet big = points_of("random", std::size_t{1} << 14, 12, "", 1);
  EXPECT_NE(error_of([&] { net_t_value(view(big), 2); }).find("use fewer points or dimensions"), std::string::npos);
}

}  // namespace
}  // namespace stratum::analysis
