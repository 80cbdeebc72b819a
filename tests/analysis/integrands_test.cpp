// Tests of the integrand registry: every exact integral against independent
// oracles — tensor Gauss–Legendre quadrature (split at the kinks and jumps),
// a dense midpoint grid for the indicators, the alternating-sum closed form
// of the corner peak, and randomized QMC over every entry — plus bad input.
#include "stratum/analysis/integrands.hpp"

#include <gtest/gtest.h>

#include "../registry/error_of.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "stratum/estimators/running_stats.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

using testing::error_of;

/// Tensor Gauss–Legendre (40 nodes) over [0,1]^d, each axis split at the
/// given breakpoints so that kinks and jumps fall on panel edges.
double tensor_gauss(const Integrand& f, const std::vector<std::vector<double>>& breaks) {
  using rule = boost::math::quadrature::gauss<double, 40>;
  const std::size_t d = f.dimension();
  std::vector<std::vector<double>> nodes(d), weights(d);
  for (std::size_t j = 0; j < d; ++j) {
    std::vector<double> edges{0};
    for (double b : breaks[j])
      if (b > 0 && b < 1) edges.push_back(b);
    edges.push_back(1);
    for (std::size_t p = 0; p + 1 < edges.size(); ++p) {
      const double half = (edges[p + 1] - edges[p]) / 2, mid = (edges[p + 1] + edges[p]) / 2;
      for (std::size_t k = 0; k < rule::abscissa().size(); ++k)
        for (int sign : {-1, 1}) {
          if (rule::abscissa()[k] == 0 && sign == 1) continue;
          nodes[j].push_back(mid + sign * half * rule::abscissa()[k]);
          weights[j].push_back(half * rule::weights()[k]);
        }
    }
  }
  std::vector<std::size_t> index(d, 0);
  std::vector<double> point(d);
  double total = 0;
  while (true) {
    double w = 1;
    for (std::size_t j = 0; j < d; ++j) {
      point[j] = nodes[j][index[j]];
      w *= weights[j][index[j]];
    }
    double value = 0;
    f.evaluate(point.data(), 1, &value);
    total += w * value;
    std::size_t j = 0;
    while (j < d && ++index[j] == nodes[j].size()) index[j++] = 0;
    if (j == d) break;
  }
  return total;
}

TEST(Integrands, GenzExactAgainstTensorGaussLegendre) {
  // Non-default, unequal parameters so a transposed index would show.
  for (unsigned d : {1u, 2u, 3u}) {
    IntegrandParams params{{"a", std::vector<double>{3.0, 7.0, 2.0}}, {"u", std::vector<double>{0.3, 0.6, 0.8}}};
    params["a"].resize(d);
    params["u"].resize(d);
    std::vector<std::vector<double>> at_u(d);
    for (unsigned j = 0; j < d; ++j) at_u[j] = {params["u"][j]};
    for (const char* name : {"genz-oscillatory", "genz-product-peak", "genz-corner-peak", "genz-gaussian",
                             "genz-continuous", "genz-discontinuous"}) {
      const auto f = make_integrand(name, d, params);
      const double quadrature = tensor_gauss(*f, at_u);
      EXPECT_NEAR(f->exact(), quadrature, 1e-11 * std::max(1.0, std::abs(quadrature))) << name << " d=" << d;
    }
  }
}

TEST(Integrands, PlanarSmoothExactAgainstGaussLegendre) {
  for (const char* name : {"gaussian", "bilinear"}) {
    const auto f = make_integrand(name, 2);
    EXPECT_NEAR(f->exact(), tensor_gauss(*f, {{}, {}}), 1e-14) << name;
  }
  EXPECT_DOUBLE_EQ(make_integrand("bilinear", 2)->exact(), 0.25);
}

TEST(Integrands, CornerPeakMatchesAlternatingSum) {
  // (1/(d! Π a)) Σ_{v∈{0,1}^d} (−1)^|v| / (1 + a·v), in long double: an
  // independent closed form, accurate while d is small.
  for (unsigned d = 1; d <= 8; ++d) {
    std::vector<double> a(d);
    for (unsigned j = 0; j < d; ++j) a[j] = 1.5 + j;
    long double sum = 0, scale = 1;
    for (unsigned j = 0; j < d; ++j) scale *= (j + 1) * a[j];
    for (unsigned mask = 0; mask < (1u << d); ++mask) {
      long double dot = 1;
      int bits = 0;
      for (unsigned j = 0; j < d; ++j)
        if (mask >> j & 1) dot += a[j], ++bits;
      sum += (bits % 2 ? -1.0L : 1.0L) / dot;
    }
    const double expected = static_cast<double>(sum / scale);
    EXPECT_NEAR(make_integrand("genz-corner-peak", d, {{"a", a}})->exact(), expected, 1e-12 * expected) << d;
  }
}

TEST(Integrands, IndicatorsAgainstDenseGrid) {
  // Midpoint rule on a 2048² grid: only cells the edge crosses can be wrong,
  // at most (edge length)·2048·2 cells of area 2048⁻², so the error is below
  // 4·√2/2048 ≈ 0.0028 for any of these edges (length ≤ √2 + 1/4·2π·0.8).
  constexpr int m = 2048;
  std::vector<double> points(2 * m * m), values(m * m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      points[2 * (i * m + j)] = (i + 0.5) / m;
      points[2 * (i * m + j) + 1] = (j + 0.5) / m;
    }
  auto grid_integral = [&](const Integrand& f) {
    f.evaluate(points.data(), m * m, values.data());
    double sum = 0;
    for (double v : values) sum += v;
    return sum / (double(m) * m);
  };
  EXPECT_EQ(make_integrand("disk", 2)->exact(), 0.5);
  EXPECT_EQ(make_integrand("triangle", 2)->exact(), 0.5);
  EXPECT_DOUBLE_EQ(make_integrand("step", 2)->exact(), 1 / std::numbers::pi);
  for (const char* name : {"disk", "triangle", "step"}) {
    const auto f = make_integrand(name, 2);
    EXPECT_NEAR(grid_integral(*f), f->exact(), 4 * std::sqrt(2.0) / m) << name;
  }
  for (double seed = 0; seed < 12; ++seed) {
    const auto f = make_integrand("edge-random", 2, {{"seed", {seed}}});
    EXPECT_NEAR(grid_integral(*f), f->exact(), 4 * std::sqrt(2.0) / m) << "edge-random seed " << seed;
    EXPECT_GE(f->exact(), 0.0);
    EXPECT_LE(f->exact(), 1.0);
  }
  EXPECT_NE(make_integrand("edge-random", 2, {{"seed", {1}}})->exact(),
            make_integrand("edge-random", 2, {{"seed", {2}}})->exact());
}

TEST(Integrands, EveryEntryAgainstRandomizedQmc) {
  // 16 Owen-scrambled Sobol replicates of 2^12 points each: a t-test of
  // exact() against their mean, Šidák-corrected to family α = 0.01 over every
  // (integrand, d) case. Catches an exact value that is off for any parameter path.
  struct Case {
    std::string name;
    unsigned d;
  };
  std::vector<Case> cases;
  for (const auto& info : integrands())
    for (unsigned d : {info.min_dim, info.default_dim, std::min(info.max_dim, 5u)})
      if (d >= info.min_dim && d <= info.max_dim &&
          (cases.empty() || cases.back().name != info.name || cases.back().d != d))
        cases.push_back({info.name, d});
  const double alpha = 1 - std::pow(1 - 0.01, 1.0 / cases.size());
  for (const auto& c : cases) {
    const auto f = make_integrand(c.name, c.d);
    estimators::RunningStats replicates;
    for (std::uint64_t k = 0; k < 16; ++k) {
      SamplerRequest request;
      request.n = 4096;
      request.d = c.d;
      request.seed = 77 + k;
      request.randomize = "owen";
      const PointSet points = generate_points("sobol", request);
      const auto values = evaluate_integrand(*f, points.data.get(), points.n);
      double sum = 0;
      for (double v : values) sum += v;
      replicates.add(sum / points.n);
    }
    const double t = boost::math::quantile(boost::math::complement(boost::math::students_t(15), alpha / 2));
    EXPECT_LT(std::abs(replicates.mean() - f->exact()), t * replicates.standard_error() + 1e-15)
        << c.name << " d=" << c.d << ": QMC " << replicates.mean() << " vs exact " << f->exact();
  }
}

TEST(Integrands, RegistryIsConsistent) {
  std::vector<std::string> names;
  for (const auto& info : integrands()) {
    names.push_back(info.name);
    EXPECT_FALSE(info.description.empty()) << info.name;
    EXPECT_LE(info.min_dim, info.default_dim) << info.name;
    EXPECT_LE(info.default_dim, info.max_dim) << info.name;
    EXPECT_EQ(make_integrand(info.name, 0)->dimension(), info.default_dim) << info.name;
  }
  for (const char* expected :
       {"disk", "triangle", "step", "gaussian", "bilinear", "edge-random", "genz-oscillatory", "genz-product-peak",
        "genz-corner-peak", "genz-gaussian", "genz-continuous", "genz-discontinuous"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

TEST(Integrands, BadInput) {
  EXPECT_NE(error_of([] { make_integrand("nosuch", 2); }).find("invalid integrand = nosuch: valid integrands are disk"),
            std::string::npos);
  EXPECT_NE(error_of([] { make_integrand("disk", 3); }).find("invalid d = 3"), std::string::npos);
  EXPECT_NE(error_of([] { make_integrand("genz-corner-peak", 51); }).find("invalid d = 51"), std::string::npos);
  EXPECT_NE(error_of([] {
              make_integrand("disk", 2, {{"a", {1}}});
            }).find("invalid integrand-param = a=1: disk takes no"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              make_integrand("genz-gaussian", 3, {{"a", {1, 2}}});
            }).find("invalid a = 2 numbers: needs 1 number or d = 3"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              make_integrand("genz-gaussian", 2, {{"a", {-1}}});
            }).find("invalid a[0] = -1: must be a finite real in (0, inf)"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              make_integrand("genz-gaussian", 2, {{"u", {1.5}}});
            }).find("invalid u[0] = 1.5: must be a finite real in [0, 1]"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              make_integrand("genz-oscillatory", 2, {{"a", {NAN}}});
            }).find("invalid a[0] = nan"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              make_integrand("edge-random", 2, {{"seed", {1.5}}});
            }).find("invalid seed = 1.5"),
            std::string::npos);
  const auto parse = [](const char* text) { return parse_integrand_params("genz-oscillatory", {{"a", text}}).at("a"); };
  EXPECT_NE(error_of([&] { parse("1,x"); }).find("invalid a[1] = x"), std::string::npos);
  EXPECT_NE(error_of([&] { parse(""); }).find("invalid a = ''"), std::string::npos);
  EXPECT_NE(
      error_of([&] { parse("1e999"); }).find("invalid a[0] = 1e999: must be a finite real (a takes 1 to 1024 reals)"),
      std::string::npos);
  EXPECT_EQ(parse("1,2.5,-3"), (std::vector<double>{1, 2.5, -3}));
  EXPECT_NE(error_of([] {
              parse_integrand_params("genz-oscillatory", {{"b", "1"}});
            }).find("invalid integrand-param = b=1: genz-oscillatory takes a, u"),
            std::string::npos);
  const auto f = make_integrand("bilinear", 2);
  const std::vector<double> bad{0.5, 0.5, 0.2, NAN};
  EXPECT_NE(error_of([&] { evaluate_integrand(*f, bad.data(), 2); }).find("invalid point[1][1] = nan"),
            std::string::npos);
  const std::vector<double> outside{0.5, 1.5};
  EXPECT_NE(error_of([&] { evaluate_integrand(*f, outside.data(), 1); }).find("point[0][1]"), std::string::npos);
}

}  // namespace
}  // namespace stratum::analysis
