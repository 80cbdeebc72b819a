/// The report's sampling sections (§4 stratification, §6 dimension, §7 block
/// designs, §13 four views), each run in quick mode through a SectionContext
/// and checked against oracles: closed-form variances of random estimates
/// (χ² tests on the sample variances), the closed-form midpoint sums of the
/// sine product, the defining properties of the block designs, and white
/// noise's flat spectrum. Fixed seeds; every statistical check states its α.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <set>

#include "report/jittered_edge.hpp"
#include "section_harness.hpp"
#include "stratum/analysis/integrands.hpp"

namespace stratum::report {
namespace {

namespace fs = std::filesystem;

struct SectionRun {
  Section section;
  testing::TempFolder folder;
};

/// Runs section `id` in quick mode (seed 1, 2 threads) and draws its figures.
void run_section(const std::string& id, SectionRun& run, std::vector<std::string> extras = {}) {
  std::vector<plot::PlotJob> plots;
  run.section = testing::run_quick_section(id, run.folder, plots, std::move(extras));
  ASSERT_FALSE(run.section.figures.empty());
  plot::write_plots(plots, 2);
  for (const auto& figure : run.section.figures) {
    EXPECT_TRUE(fs::exists(run.folder.path / figure.file)) << figure.file;
    EXPECT_FALSE(figure.caption.empty());
  }
}

/// Two-sided χ² acceptance interval for (k · s²/σ²) with k degrees of
/// freedom at level `alpha`.
std::pair<double, double> chi_squared_interval(double k, double alpha) {
  const boost::math::chi_squared chi(k);
  return {boost::math::quantile(chi, alpha / 2), boost::math::quantile(boost::math::complement(chi, alpha / 2))};
}

/// Šidák: the per-test α that gives family α over m tests.
double sidak(double family_alpha, double m) { return 1 - std::pow(1 - family_alpha, 1 / m); }

double gaussian_exact() { return std::pow(std::sqrt(std::numbers::pi) / 2 * std::erf(1.0), 2); }
/// Var exp(−x² − y²) for uniform (x, y): (∫₀¹ e^{−2x²} dx)² − I² with ∫₀¹ e^{−2x²} = √(π/8) erf(√2).
double gaussian_variance() {
  return std::pow(std::sqrt(std::numbers::pi / 8) * std::erf(std::sqrt(2.0)), 2) - std::pow(gaussian_exact(), 2);
}

TEST(ReportSamplingSections, StratificationSlopesAndRandomVariances) {
  SectionRun run;
  run_section("stratification", run, {"cmj", "latin-square"});
  const auto& numbers = run.section.numbers;
  const unsigned runs = numbers["runs"].get<unsigned>();
  // --sampler extras: a 2D one that takes every N joins the study.
  EXPECT_TRUE(numbers.at("edge").at("samplers").contains("cmj:none"));

  // Random estimates have exactly known variances: p(1 − p)/N for the step
  // (p = 1/π) and Var f/N for the Gaussian; (R − 1) s²/σ² ~ χ²(R − 1).
  // Family α = 1e-3 over every N of both integrands (Šidák).
  const double p = 1 / std::numbers::pi;
  const std::size_t counts = numbers["counts"].size();
  const auto [low, high] = chi_squared_interval(runs - 1, sidak(1e-3, 2.0 * counts));
  for (const auto& [integrand, sigma2] : {std::pair{"edge", p * (1 - p)}, std::pair{"smooth", gaussian_variance()}})
    for (const auto& row : numbers.at(integrand).at("samplers").at("random:none").at("rows")) {
      const double n = row["n"].get<double>();
      const double statistic = (runs - 1) * row["variance"].get<double>() / (sigma2 / n);
      EXPECT_GT(statistic, low) << integrand << " N = " << n;
      EXPECT_LT(statistic, high) << integrand << " N = " << n;
    }

  // Slopes. Random: the fitted slope of log s² has a standard error of about
  // sqrt(2/(R − 1)) / sqrt(Σ(log N − mean)²) ≈ 0.045 here; ±0.25 is > 5 of
  // them (α < 1e-6). Jittered on the edge: −1.5 plus the wobble of the cut
  // cell's fraction frac(m/π) from one m to the next, hence ±0.3 (the
  // lecture's claim is the asymptotic rate). Smooth jittered: −2, and the
  // scrambled (0,2)-sequences near −3.
  const auto slope = [&](const char* integrand, const char* sampler) {
    return numbers.at(integrand).at("samplers").at(sampler).at("slope").get<double>();
  };
  EXPECT_NEAR(slope("edge", "random:none"), -1.0, 0.25);
  EXPECT_NEAR(slope("smooth", "random:none"), -1.0, 0.25);
  EXPECT_NEAR(slope("edge", "jittered:none"), -1.5, 0.3);
  EXPECT_NEAR(slope("smooth", "jittered:none"), -2.0, 0.3);
  EXPECT_LT(slope("smooth", "sobol:owen"), -2.5);
  EXPECT_LT(slope("smooth", "pmj02:none"), -2.5);
  // The slanted edge joins the study, and jittered's measured variance agrees
  // with the exact Σ a_i(1 − a_i)/N² on both edges: (R − 1) s²/σ² ~ χ²(R − 1)
  // for normal estimates, taken from N = 256 on (at least 16 cut cells, whose
  // Bernoulli sum is near normal); family α = 1e-3 over both edges (Šidák).
  ASSERT_TRUE(numbers.at("slanted_edge").at("samplers").contains("jittered:none"));
  const auto& prediction = numbers.at("jittered_prediction");
  ASSERT_EQ(prediction.size(), counts);
  std::size_t tested = 0;
  for (const auto& row : prediction) tested += row["n"].get<double>() >= 256 ? 2 : 0;
  const auto [low_p, high_p] = chi_squared_interval(runs - 1, sidak(1e-3, double(tested)));
  for (const auto& row : prediction) {
    EXPECT_GE(row["slanted_edge_cut_cells"].get<double>(), row["grid"].get<double>());  // a slanted line cuts ≥ n cells
    if (row["n"].get<double>() < 256) continue;
    for (const char* key : {"edge_measured_over_predicted", "slanted_edge_measured_over_predicted"}) {
      EXPECT_GT((runs - 1) * row[key].get<double>(), low_p) << key << " N = " << row["n"];
      EXPECT_LT((runs - 1) * row[key].get<double>(), high_p) << key << " N = " << row["n"];
    }
  }
  // The random/jittered variance ratio at the largest N: its 95% F interval
  // holds the estimate, and the true ratio (p(1 − p)/N over the exact
  // jittered variance) lies in the 99.9% F interval (α = 1e-3).
  const auto& ratio = numbers.at("edge_variance_ratio_random_over_jittered");
  EXPECT_LT(ratio["low"].get<double>(), ratio["estimate"].get<double>());
  EXPECT_GT(ratio["high"].get<double>(), ratio["estimate"].get<double>());
  {
    const double largest = numbers["counts"].back().get<double>();
    const double truth = p * (1 - p) / largest / prediction.back()["edge"].get<double>();
    const boost::math::fisher_f f(runs - 1.0, runs - 1.0);
    const double estimate = ratio["estimate"].get<double>();
    EXPECT_GT(truth, estimate / boost::math::quantile(boost::math::complement(f, 5e-4)));
    EXPECT_LT(truth, estimate / boost::math::quantile(f, 5e-4));
  }
  // The sentence quotes the measured jittered slope.
  EXPECT_NE(run.section.text[0].find(format_number(slope("edge", "jittered:none"))), std::string::npos);
  // … with its interval's level as a whole percentage ("95% interval", not "95.0%").
  EXPECT_NE(run.section.text[0].find("(95% interval "), std::string::npos) << run.section.text[0];
  for (const auto& text : run.section.text) EXPECT_EQ(text.find(".0% interval"), std::string::npos) << text;
  // latin-square makes only 3D points: validate_report_options refuses it before a report runs, and the
  // section, given it anyway, leaves it out and says so.
  EXPECT_FALSE(numbers.at("edge").at("samplers").contains("latin-square:none"));
  EXPECT_EQ(numbers.at("skipped_extras"), nlohmann::json::array({"latin-square"}));
}

// The exact jittered variance of an edge, Σ a_i(1 − a_i)/N², against a
// brute-force Monte Carlo: R independent jittered estimates (one uniform point
// per cell, std::mt19937_64, fixed seed) of the registry's own integrands
// (the step and the slanted edge-random of §4), so the half-planes are checked
// too. The sample variance s² of R = 20000 estimates has standard error
// √((m4 − s⁴)/R) (m4 the fourth central moment); |s² − exact| < 4.5 of them
// per test (two-sided α ≈ 6.8e-6), 6 tests: family α < 5e-5.
TEST(JitteredEdgeVariance, ExactFormulaAgainstBruteForceMonteCarlo) {
  const std::uint64_t slanted_seed = 10;  // section_stratification.cpp's slanted edge
  const std::vector<std::pair<HalfPlane, std::unique_ptr<const analysis::Integrand>>> edges = [&] {
    std::vector<std::pair<HalfPlane, std::unique_ptr<const analysis::Integrand>>> list;
    list.emplace_back(HalfPlane{{1 / std::numbers::pi, 0}, {1, 0}}, analysis::make_integrand("step", 2));
    list.emplace_back(random_edge_half_plane(slanted_seed),
                      analysis::make_integrand("edge-random", 2, {{"seed", {double(slanted_seed)}}}));
    return list;
  }();
  std::mt19937_64 generator(20261202);
  std::uniform_real_distribution<double> uniform(0, 1);
  const int repeats = 20000;
  for (const auto& [plane, integrand] : edges) {
    // The half-plane is the integrand's: equal areas over the square.
    EXPECT_NEAR(half_plane_area(plane, 0, 0, 1, 1), integrand->exact(), 1e-12);
    for (const std::uint64_t n : {4u, 8u, 16u}) {
      std::vector<double> estimates(repeats), points(2 * n * n), values(n * n);
      for (double& estimate : estimates) {
        for (std::uint64_t i = 0; i < n; ++i)
          for (std::uint64_t j = 0; j < n; ++j) {
            points[2 * (i * n + j)] = (double(i) + uniform(generator)) / double(n);
            points[2 * (i * n + j) + 1] = (double(j) + uniform(generator)) / double(n);
          }
        integrand->evaluate(points.data(), n * n, values.data());
        double sum = 0;
        for (const double v : values) sum += v;
        estimate = sum / double(n * n);
      }
      double mean = 0;
      for (const double e : estimates) mean += e / repeats;
      double m2 = 0, m4 = 0;
      for (const double e : estimates) m2 += (e - mean) * (e - mean) / repeats, m4 += std::pow(e - mean, 4) / repeats;
      const double s2 = m2 * repeats / (repeats - 1);
      const double standard_error = std::sqrt((m4 - m2 * m2) / repeats);
      const double exact = jittered_edge_variance(plane, n);
      EXPECT_NEAR(s2, exact, 4.5 * standard_error) << "n = " << n << ", exact " << exact;
      EXPECT_GT(cut_cells(plane, n), 0u);
    }
  }
  // The axis-aligned edge in closed form: one column of n cells, each covered
  // frac(n/π), so Var = n·a(1 − a)/n⁴; it cuts exactly n cells.
  const HalfPlane step{{1 / std::numbers::pi, 0}, {1, 0}};
  for (const std::uint64_t n : {4u, 8u, 64u, 512u}) {
    const double a = double(n) / std::numbers::pi - std::floor(double(n) / std::numbers::pi);
    EXPECT_NEAR(jittered_edge_variance(step, n), a * (1 - a) / std::pow(double(n), 3), 1e-12 / std::pow(double(n), 3));
    EXPECT_EQ(cut_cells(step, n), n);
  }
}

TEST(ReportSamplingSections, DimensionMatchesClosedFormMidpointSums) {
  SectionRun run;
  run_section("dimension", run);
  const auto& numbers = run.section.numbers;
  const double runs = numbers["runs"].get<double>();
  std::size_t cells = 0;
  for (const auto& s : numbers["dimensions"]) cells += s["n"].size();
  // MC: runs · RMSE² / (σ²/N) ~ χ²(runs) with σ² = (π²/8)^d − 1 (the mean is known exactly: 1).
  // Family α = 1e-3 over every (d, N), Šidák.
  const auto [low, high] = chi_squared_interval(runs, sidak(1e-3, static_cast<double>(cells)));
  for (const auto& s : numbers["dimensions"]) {
    const int d = s["d"].get<int>();
    const double sigma2 = std::pow(std::numbers::pi * std::numbers::pi / 8, d) - 1;
    for (std::size_t k = 0; k < s["n"].size(); ++k) {
      // The midpoint rule's sum has the closed form (π / (2m sin(π/(2m))))^d.
      const double m = s["m"][k].get<double>();
      const double sum = std::pow(std::numbers::pi / (2 * m * std::sin(std::numbers::pi / (2 * m))), d);
      EXPECT_NEAR(s["product_error"][k].get<double>(), std::fabs(sum - 1), 1e-9 * sum) << "d = " << d << " m = " << m;
      const double n = s["n"][k].get<double>();
      const double rmse = s["mc_rmse"][k].get<double>();
      EXPECT_GT(runs * rmse * rmse / (sigma2 / n), low) << "d = " << d << " N = " << n;
      EXPECT_LT(runs * rmse * rmse / (sigma2 / n), high) << "d = " << d << " N = " << n;
    }
    // The midpoint rule's order 2: slope −2/d (the h⁴ term bends it a little at small m).
    EXPECT_NEAR(s["product_slope"].get<double>(), -2.0 / d, 0.1) << "d = " << d;
  }
  // The reported crossover is the first d where MC's RMSE beats the product rule at the largest N.
  int first = 0;
  for (const auto& s : numbers["dimensions"])
    if (first == 0 && s["mc_rmse"].back().get<double>() < s["product_error"].back().get<double>())
      first = s["d"].get<int>();
  EXPECT_EQ(numbers["first_dimension_mc_wins"].get<int>(), first);
  EXPECT_GT(first, 1);  // in d = 1 the midpoint rule's N^-2 is far ahead of N^-1/2
}

TEST(ReportSamplingSections, BlockDesignsHaveTheirDefiningProperties) {
  SectionRun run;
  run_section("block-designs", run);
  const auto& patterns = run.section.numbers["patterns"];
  // Latin (N-rooks) property: one point per 1/N stratum of each axis.
  for (const char* name : {"n-rooks", "n-queens", "multi-jittered", "cmj"}) {
    EXPECT_TRUE(patterns[name]["latin"].get<bool>()) << name;
    EXPECT_EQ(patterns[name]["worst_count"].get<int>(), 1) << name;
    EXPECT_EQ(patterns[name]["empty_strata"].get<int>(), 0) << name;
  }
  // One point per √N×√N cell: jittered, multi-jittered, cmj, and every 2D projection of a Latin square's points.
  for (const char* name : {"jittered", "multi-jittered", "cmj", "latin-square (3D)"}) {
    EXPECT_EQ(patterns[name]["cell_min"].get<int>(), 1) << name;
    EXPECT_EQ(patterns[name]["cell_max"].get<int>(), 1) << name;
  }
  // N-queens: no two points on a diagonal. N-rooks, a uniformly random
  // permutation σ of N = 256: a pair at distance k shares a diagonal with
  // probability 2(N − k)/(N(N − 1)), so E[pairs] = (2N − 1)/3 = 170.3; zero
  // would make it an N-queens solution, a fraction ≈ 0.39^N ≈ 1e-105 of the
  // permutations (Simkin 2021, "The number of n-queens configurations").
  EXPECT_EQ(patterns["n-queens"]["diagonal_pairs"].get<int>(), 0);
  EXPECT_GT(patterns["n-rooks"]["diagonal_pairs"].get<int>(), 0);
  // Random points are Latin with probability N!/N^N (≈ 1e-110 for N = 256).
  EXPECT_FALSE(patterns["random"]["latin"].get<bool>());
  // Jittered: each of the 16 columns of the 16×16 grid holds 16 points uniform in its 16 strata of width 1/N;
  // they fill all of them with probability 16!/16^16 ≈ 1.1e-6, so no empty stratum on both axes ≈ 1e-190.
  EXPECT_GT(patterns["jittered"]["empty_strata"].get<int>(), 0);
  for (const auto& square : run.section.numbers["latin_squares"]) {
    EXPECT_TRUE(square["each_symbol_once_per_row_and_column"].get<bool>());
    // Brute-force recount from the symbols as printed.
    const auto& symbols = square["symbols"];
    const std::size_t m = square["m"].get<std::size_t>();
    ASSERT_EQ(symbols.size(), m);
    for (std::size_t i = 0; i < m; ++i) {
      std::set<std::string> row, column;
      for (std::size_t j = 0; j < m; ++j) {
        row.insert(symbols[i][j].get<std::string>());
        column.insert(symbols[j][i].get<std::string>());
      }
      EXPECT_EQ(row.size(), m);
      EXPECT_EQ(column.size(), m);
    }
  }
}

TEST(ReportSamplingSections, FourViewsAgreeWithWhiteNoiseAndClosedForms) {
  SectionRun run;
  run_section("four-views", run, {"fibonacci"});
  const auto& numbers = run.section.numbers;
  const auto& patterns = numbers["patterns"];
  const double n = numbers["n"].get<double>(), runs = numbers["runs"].get<double>();
  ASSERT_TRUE(patterns.contains("fibonacci"));  // the extra joins the table
  for (const char* name : {"random", "jittered", "n-rooks", "multi-jittered", "poisson-disk", "best-candidate",
                           "zaremba:cp", "hammersley", "halton", "sobol:owen", "pmj02"})
    EXPECT_TRUE(patterns.contains(name)) << name;

  // Spectrum: a uniform random set is white noise, E P(k) = 1 at k ≠ 0. The
  // low-frequency mean averages ~113 independent half-plane frequencies over
  // 4 sets, each value ~ Exp(1): standard deviation ≈ 1/√452 ≈ 0.047, so
  // ±0.25 is > 5 of them (α < 1e-6).
  EXPECT_NEAR(patterns["random"]["low_frequency_power"].get<double>(), 1.0, 0.25);
  // Variance view: a random estimate of the quarter disk (area 1/2) has
  // variance 1/(4N); (R − 1) s²/σ² ~ χ²(R − 1). Quadrature view: the random
  // RMSE² over R runs with the exact mean known: R · MSE/(σ²/N) ~ χ²(R).
  // Two tests, family α = 1e-3 (Šidák).
  const double alpha = sidak(1e-3, 2);
  const auto [low_v, high_v] = chi_squared_interval(runs - 1, alpha);
  const double variance_statistic = (runs - 1) * patterns["random"]["edge_variance"].get<double>() / (0.25 / n);
  EXPECT_GT(variance_statistic, low_v);
  EXPECT_LT(variance_statistic, high_v);
  const auto [low_r, high_r] = chi_squared_interval(runs, alpha);
  const double rmse = patterns["random"]["smooth_rmse"].get<double>();
  EXPECT_GT(runs * rmse * rmse / (gaussian_variance() / n), low_r);
  EXPECT_LT(runs * rmse * rmse / (gaussian_variance() / n), high_r);
  // Stratification lowers the variance: jittered's edge variance is Θ(N^-1.5), i.e. about 1/√N = 1/16 of
  // random's here; a factor 4 is far outside the χ² spread of both.
  EXPECT_LT(patterns["jittered"]["edge_variance"].get<double>(), patterns["random"]["edge_variance"].get<double>() / 4);
  // The periodic Poisson disk (as §10 and §12 use it) beside the plain one.
  ASSERT_TRUE(patterns.contains("poisson-disk(periodic=1)"));
  // Quadrature rules at the same N: the product midpoint rule of the separable
  // Gaussian is the square of the 1D midpoint sum (an independent oracle);
  // product Gauss–Legendre with √N = 16 nodes a side is exact to rounding on
  // it (its error bound is ~ (2^-(2·16)) · f^(32)/32!, far below 1e-14) and
  // so beats every randomized pattern's RMSE.
  const auto& quadrature = numbers["quadrature"];
  const int side = quadrature["grid"].get<int>();
  ASSERT_EQ(side * side, static_cast<int>(n));
  double one_d = 0;
  for (int i = 0; i < side; ++i) one_d += std::exp(-std::pow((i + 0.5) / side, 2)) / side;
  EXPECT_NEAR(quadrature["midpoint"]["gaussian_error"].get<double>(), std::abs(one_d * one_d - gaussian_exact()),
              1e-15);
  EXPECT_LT(quadrature["gauss_legendre"]["gaussian_error"].get<double>(), 1e-14);
  for (const auto& [name, entry] : patterns.items())
    EXPECT_LT(quadrature["gauss_legendre"]["gaussian_error"].get<double>(), entry["smooth_rmse"].get<double>()) << name;
  // On the quarter disk the rules have errors of edge size, not rounding size.
  EXPECT_GT(quadrature["gauss_legendre"]["disk_error"].get<double>(), 1e-6);
  EXPECT_GT(quadrature["midpoint"]["disk_error"].get<double>(), 1e-6);
  // The departure from the lecture is stated from the ranks.
  bool nets_ahead = true;
  for (const char* key : {"edge_variance", "star", "l2_star", "smooth_rmse"})
    for (const char* net : {"sobol:owen", "pmj02"})
      for (const char* recommended : {"jittered", "poisson-disk(periodic=1)"})
        nets_ahead = nets_ahead && patterns[net][std::string(key) + "_rank"].get<int>() <
                                       patterns[recommended][std::string(key) + "_rank"].get<int>();
  EXPECT_EQ(numbers["nets_ahead_outside_the_spectrum"].get<bool>(), nets_ahead);
  for (const auto& [name, entry] : patterns.items()) {
    EXPECT_GE(entry["mean_rank"].get<double>(), 1.0) << name;
    EXPECT_LE(entry["mean_rank"].get<double>(), double(patterns.size())) << name;
  }
  // Ranks: each column's best rank is 1 and the ranks stay within the pattern count.
  const std::size_t count = patterns.size();
  for (const char* key :
       {"low_frequency_power", "effective_nyquist", "peak_power", "edge_variance", "star", "l2_star", "smooth_rmse"}) {
    int best = 1000;
    for (const auto& [name, entry] : patterns.items()) {
      const int rank = entry[std::string(key) + "_rank"].get<int>();
      EXPECT_GE(rank, 1);
      EXPECT_LE(rank, static_cast<int>(count));
      best = std::min(best, rank);
    }
    EXPECT_EQ(best, 1) << key;
  }
}

}  // namespace
}  // namespace stratum::report
