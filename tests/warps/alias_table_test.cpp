#include "stratum/warps/alias_table.hpp"

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

const std::vector<double> weights = {1, 0, 3, 2, 0.5, 7, 0.01, 4, 4, 0, 12, 0.25};

TEST(WarpAliasTable, PmfIsExactlyTheNormalizedWeights) {
  const AliasTable<double> table(weights);
  double sum = 0;
  for (double w : weights) sum += w;
  for (std::size_t i = 0; i < weights.size(); ++i) EXPECT_EQ(table.pmf(i), weights[i] / sum) << i;
}

// The table itself: the measure of u giving index i, own kept part plus the
// alias parts pointing at i, is p_i (to rounding) — exact, no sampling.
TEST(WarpAliasTable, TableProbabilitiesEqualThePmf) {
  for (const auto& w : {weights, std::vector<double>{1}, std::vector<double>{0, 5}, std::vector<double>(1000, 1.0)}) {
    const AliasTable<double> table(w);
    const std::size_t n = table.size();
    std::vector<double> mass(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      ASSERT_GE(table.keep(j), 0.0);
      ASSERT_LE(table.keep(j), 1.0);
      mass[j] += table.keep(j) / n;
      mass[table.alias(j)] += (1 - table.keep(j)) / n;
    }
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(mass[i], table.pmf(i), 1e-14) << i;
  }
}

/// The registry's continuous form x = (index + leftover)/n.
double as_point(const AliasTable<double>& table, double u) {
  const auto s = table.sample(u);
  return (static_cast<double>(s.index) + s.leftover) / static_cast<double>(table.size());
}

// χ² of the index frequencies (one bin per index) and, on 4 bins per index,
// of the leftover's uniformity given the index; two members of the χ² family
// (tests/warps/chi2.hpp: Šidák at family α = 0.01).
class WarpAliasTableChi2 : public testing::Chi2Fixture<> {
 protected:
  testing::Chi2Result chi2(long bins_per_index, std::uint64_t seed) const {
    const double n = static_cast<double>(weights.size());
    const testing::PdfFn pdf = [&](const double* p) {
      return table.pmf(std::min(weights.size() - 1, static_cast<std::size_t>(p[0] * n))) * n;
    };
    testing::Chi2Options options;
    options.input_dim = 1;
    options.subdivisions = 1;  // the density is constant on each bin
    options.seed = seed;
    const auto sample = [&](const double* u, double* out) { out[0] = as_point(table, u[0]); };
    return testing::chi2_test(sample, pdf, testing::Domain::interval(0, 1, bins_per_index * weights.size()), options);
  }
  const AliasTable<double> table{weights};
};

TEST_F(WarpAliasTableChi2, IndexFrequencies) { testing::expect_chi2(chi2(1, 1)); }
TEST_F(WarpAliasTableChi2, LeftoverUniformGivenIndex) { testing::expect_chi2(chi2(4, 2)); }

TEST(WarpAliasTable, InverseRoundTripBothWays) {
  const AliasTable<double> table(weights);
  for (std::uint64_t k = 0; k < 20000; ++k) {
    const double u = uniform01(5, k, 0);
    const auto s = table.sample(u);
    ASSERT_GT(table.pmf(s.index), 0.0);
    ASSERT_NEAR(table.invert(s.index, s.leftover), u, 1e-14) << k;  // a bijection, not only a right inverse
    const double r = uniform01(6, k, 0);
    for (std::size_t i : {std::size_t(2), std::size_t(5), std::size_t(6), std::size_t(10)}) {
      const auto again = table.sample(table.invert(i, r));
      ASSERT_EQ(again.index, i) << k;
      ASSERT_NEAR(again.leftover, r, 1e-12) << k;
    }
  }
}

// The map u -> (index, leftover) preserves measure: it cuts [0,1) into at
// most 2n parts (each bin's kept and alias part) and translates each part to
// its place in quantile space (cumulative pmf, an independent prefix sum). So
// a stratum of u inside one part maps to an interval of the same probability.
// (The translations are not multiples of a grid's cell, so a jittered grid's
// images are equal-probability intervals, just not the grid's cells.)
TEST(WarpAliasTable, MapIsAPiecewiseTranslationInQuantileSpace) {
  const AliasTable<double> table(weights);
  std::vector<double> cumulative(weights.size() + 1, 0.0);
  for (std::size_t i = 0; i < weights.size(); ++i) cumulative[i + 1] = cumulative[i] + table.pmf(i);
  const auto quantile = [&](double u) {
    const auto s = table.sample(u);
    return cumulative[s.index] + s.leftover * table.pmf(s.index);
  };
  int parts = 0;
  for (std::size_t j = 0; j < weights.size(); ++j) parts += (table.keep(j) > 0) + (table.keep(j) < 1);
  EXPECT_LE(parts, 2 * static_cast<int>(weights.size()));
  // Strata of width 1/1024: all but those holding a part's end keep their width.
  const int n = 1024;
  int kept = 0;
  for (int j = 0; j < n; ++j) {
    const double a = static_cast<double>(j) / n, b = (j + 0.999) / n;
    if (std::abs(quantile(b) - quantile(a) - (b - a)) < 1e-12) ++kept;
  }
  EXPECT_GE(kept, n - parts);
  EXPECT_LT(kept, n);  // the alias method does permute: some strata do straddle part ends
}

TEST(WarpAliasTable, FloatAgreesWithDouble) {
  const std::vector<float> weights_float(weights.begin(), weights.end());
  const AliasTable<float> table_float(weights_float);
  const AliasTable<double> table(weights);
  int same = 0;
  for (std::uint64_t k = 0; k < 5000; ++k) {
    const double u = uniform01(9, k, 0);
    const auto s = table.sample(u);
    const auto sf = table_float.sample(static_cast<float>(u));
    if (sf.index != s.index) continue;
    ++same;
    ASSERT_NEAR(sf.leftover, s.leftover, 1e-4) << k;
  }
  EXPECT_GE(same, 4990);  // only u within float rounding of a part boundary may differ
}

std::string error_of(const WarpParams& params) {
  try {
    make_warp("alias", params);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WarpAliasTable, BadInput) {
  const std::string negative = error_of({{"values", {1, -0.5}}});
  EXPECT_NE(negative.find("invalid values[1] = -0.5: must be a finite real in [0, inf)"), std::string::npos)
      << negative;
  EXPECT_NE(error_of({{"values", {0, 0, 0}}}).find("invalid values = (all 3 values zero)"), std::string::npos);
  EXPECT_NE(error_of({{"values", {}}}).find("invalid values = (0 values): must be 1 or more finite reals"),
            std::string::npos);
  EXPECT_NE(error_of({{"values", {1, NAN}}}).find("invalid values[1] = nan: must be a finite real"), std::string::npos);
  EXPECT_NE(error_of({}).find("invalid values = (missing)"), std::string::npos);
  const std::string core = [] {
    try {
      AliasTable<double> table(std::vector<double>{2, -1});
    } catch (const invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  EXPECT_NE(core.find("invalid weights[1] = -1"), std::string::npos) << core;
}

// The registry's `alias`: x = (index + leftover)/n, pdf = pmf·n, and the
// inverse recovers u; floor(n·x) is the index.
TEST(WarpAliasTable, RegistryEntry) {
  const auto warp = make_warp("alias", {{"values", weights}});
  const AliasTable<double> table(weights);
  std::vector<double> u(1000);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = uniform01(11, k, 0);
  const auto x = warp_sample(*warp, u.data(), u.size());
  const auto pdf = warp_pdf(*warp, x.data(), x.size());
  const auto back = warp_invert(*warp, x.data(), x.size());
  for (std::size_t k = 0; k < u.size(); ++k) {
    const auto s = table.sample(u[k]);
    ASSERT_EQ(static_cast<std::size_t>(x[k] * weights.size()), s.index) << k;
    ASSERT_EQ(pdf[k], table.pmf(s.index) * weights.size()) << k;
    ASSERT_NEAR(back[k], u[k], 1e-13) << k;
  }
  const double outside[2] = {-0.5, 1.5};
  const auto zero = warp_pdf(*warp, outside, 2);
  EXPECT_EQ(zero[0], 0.0);
  EXPECT_EQ(zero[1], 0.0);
}

}  // namespace
}  // namespace stratum
