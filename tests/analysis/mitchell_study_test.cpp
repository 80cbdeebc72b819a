// Tests of Mitchell's comparison of patterns (mitchell_study.hpp): the cells
// are the random-edge discrepancies of registry point sets, the random
// pattern matches its closed-form mean square, and the lecture's ordering
// (jittered and Poisson disk beat random and N-rooks) holds significantly.
#include "stratum/analysis/mitchell_study.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>

#include "stratum/analysis/edge_discrepancy.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::analysis {
namespace {

constexpr double pi = 3.14159265358979323846;

MitchellStudyOptions small_study() {
  MitchellStudyOptions options;
  options.counts = {16, 256};
  options.realizations = 30;
  options.lines = 2000;
  options.seed = 0;
  options.spectrum_count = 16;
  return options;
}

const MitchellStudy& study() {
  static const MitchellStudy result = run_mitchell_study(small_study());
  return result;
}

TEST(MitchellStudy, CellsAreRandomEdgeDiscrepanciesOfRegistryPatterns) {
  ASSERT_EQ(study().cells.size(), 10u);
  for (const auto& pattern : mitchell_patterns())
    for (std::size_t n : {16u, 256u}) {
      const MitchellCell& cell = study().cell(pattern.sampler, n);
      EXPECT_EQ(cell.n, n);  // all five samplers take 16 and 256 points
      ASSERT_EQ(cell.rms_values.size(), 30u);
      for (std::size_t r : {0u, 29u}) {
        SamplerRequest request;
        request.n = n;
        request.d = 2;
        request.seed = hash64(0, r);
        request.params = pattern.params;
        const PointSet points = generate_points(pattern.sampler, request);
        const auto direct = random_edge_discrepancy({points.data.get(), points.n, 2}, 2000, hash64(0, r, 1));
        EXPECT_EQ(cell.rms_values[r], direct.rms) << pattern.sampler << " " << n << " " << r;
      }
      EXPECT_GT(cell.rms.error, 0);
      EXPECT_LE(cell.mean.mean, cell.rms.mean);
    }
  EXPECT_TRUE(study().notes.empty());
}

TEST(MitchellStudy, DeterministicForAnyThreadCount) {
  auto options = small_study();
  options.counts = {16};
  options.realizations = 5;
  options.threads = 1;
  const auto one = run_mitchell_study(options);
  options.threads = 3;
  const auto three = run_mitchell_study(options);
  for (std::size_t c = 0; c < one.cells.size(); ++c) EXPECT_EQ(one.cells[c].rms_values, three.cells[c].rms_values);
  for (std::size_t s = 0; s < one.spectra.size(); ++s) EXPECT_EQ(one.spectra[s].power, three.spectra[s].power);
}

/// E[A(1 − A)] over the motion-invariant measure of lines hitting the square
/// (midpoint rule in θ; 5-point Gauss–Legendre in p between the corner
/// projections, where A is one quadratic, so exact in p).
double mean_binomial_variance_factor() {
  static const double node[5] = {0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const double weight[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                   0.2369268850561891};
  double total = 0, measure = 0;
  const int directions = 4000;
  for (int k = 0; k < directions; ++k) {
    const double angle = pi * (k + 0.5) / directions, nx = std::cos(angle), ny = std::sin(angle);
    double breaks[4] = {0, nx, ny, nx + ny};
    std::sort(breaks, breaks + 4);
    for (int b = 0; b < 3; ++b) {
      const double half = 0.5 * (breaks[b + 1] - breaks[b]), centre = 0.5 * (breaks[b + 1] + breaks[b]);
      for (int g = 0; g < 5; ++g) {
        const double area = half_plane_area(nx, ny, centre + half * node[g]);
        total += half * weight[g] * area * (1 - area);
      }
    }
    measure += breaks[3] - breaks[0];
  }
  return total / measure;
}

TEST(MitchellStudy, RandomPatternMatchesTheBinomialMeanSquare) {
  // For N independent uniform points and any line, N·fraction is binomial
  // (N, A), so E[D²] = E[A(1 − A)]/N exactly. The mean over realizations of
  // RMS² estimates it; |error| ≤ z·s/√K with z = 3.29 (two-sided α = 1e-3
  // per count, Šidák over 2 counts ≈ 5e-4 → z = 3.48).
  const double factor = mean_binomial_variance_factor();
  for (std::size_t n : {16u, 256u}) {
    const auto& values = study().cell("random", n).rms_values;
    double sum = 0, squares = 0;
    for (double v : values) sum += v * v, squares += v * v * v * v;
    const double k = static_cast<double>(values.size()), mean = sum / k;
    const double sd = std::sqrt((squares - k * mean * mean) / (k - 1));
    EXPECT_NEAR(mean, factor / static_cast<double>(n), 3.48 * sd / std::sqrt(k)) << n;
  }
}

TEST(MitchellStudy, JitteredAndPoissonDiskBeatRandomAndNRooks) {
  // Mitchell (1992) and LECTURE.md §12: jittered and Poisson-disk patterns
  // beat random and N-rooks, and Zaremba's set is lowest. One-sided z-tests
  // of "better < worse" with Welch's standard error; family-wise α = 1e-3
  // over the 8 tests below, Šidák-corrected: α' = 1 − (1 − 1e-3)^(1/8) ≈
  // 1.25e-4 per test. The patterns share their random lines (common random
  // numbers), which makes the independent-samples standard error
  // conservative. At N = 16 Poisson disk and N-rooks are within their
  // errors (0.051 ± 0.002 against 0.048 ± 0.001 with K = 40, L = 10^4), so
  // that pair is compared at N = 256 only; N = 16 uses K = 150 realizations,
  // enough for jittered against N-rooks (a 6% difference).
  auto options = small_study();
  options.counts = {16};
  options.realizations = 150;
  const MitchellStudy sixteen = run_mitchell_study(options);
  const double per_test = 1 - std::pow(1 - 1e-3, 1.0 / 8);
  const double z_critical = boost::math::quantile(boost::math::normal(), 1 - per_test);
  auto expect_better = [&](const MitchellStudy& s, const char* better, const char* worse, std::size_t n) {
    const auto& b = s.cell(better, n).rms;
    const auto& w = s.cell(worse, n).rms;
    const double z = (w.mean - b.mean) / std::hypot(w.error, b.error);
    EXPECT_GT(z, z_critical) << better << " vs " << worse << " at N = " << n;
  };
  expect_better(sixteen, "jittered", "random", 16);
  expect_better(sixteen, "jittered", "n-rooks", 16);
  expect_better(sixteen, "poisson-disk", "random", 16);
  for (const char* better : {"jittered", "poisson-disk"})
    for (const char* worse : {"random", "n-rooks"}) expect_better(study(), better, worse, 256);
  expect_better(study(), "zaremba", "jittered", 256);
}

TEST(MitchellStudy, SpectraShowBlueNoiseAgainstWhiteNoise) {
  ASSERT_EQ(study().spectra.size(), 5u);
  auto spectrum = [](const std::string& pattern) {
    for (const auto& s : study().spectra)
      if (s.pattern == pattern) return s;
    throw invalid_argument("pattern", pattern, "missing");
  };
  const auto random = spectrum("random"), jittered = spectrum("jittered"), poisson = spectrum("poisson-disk");
  EXPECT_EQ(random.n, 16u);
  ASSERT_FALSE(random.power.empty());
  EXPECT_NEAR(random.frequency[0], 1.0 / 4, 1e-12);  // ring 1 at frequency 1/√16
  // White noise averages 1 (30 realizations, ring 1 holds 8 frequencies); blue noise is far below it at low frequency.
  double mean = 0;
  for (double p : random.power) mean += p;
  EXPECT_NEAR(mean / static_cast<double>(random.power.size()), 1.0, 0.15);
  EXPECT_LT(jittered.power[0], 0.5 * random.power[0]);
  EXPECT_LT(poisson.power[0], 0.5 * random.power[0]);
}

TEST(MitchellStudy, SubstitutesTheNearestValidCountAndRejectsBadOptions) {
  MitchellStudyOptions options;
  options.counts = {15};
  options.realizations = 2;
  options.lines = 100;
  const auto study = run_mitchell_study(options);
  EXPECT_EQ(study.cell("jittered", 15).n, 16u);  // 16 = 4² is nearer than 9
  EXPECT_EQ(study.cell("random", 15).n, 15u);
  ASSERT_EQ(study.notes.size(), 1u);
  EXPECT_NE(study.notes[0].find("jittered: 16 points instead of 15"), std::string::npos);
  EXPECT_NE(mitchell_table(study).find("Zaremba"), std::string::npos);
  auto error_of = [](MitchellStudyOptions bad) {
    try {
      run_mitchell_study(bad);
    } catch (const invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  auto bad = options;
  bad.lines = 0;
  EXPECT_NE(error_of(bad).find("invalid lines = 0"), std::string::npos);
  bad = options;
  bad.realizations = 0;
  EXPECT_NE(error_of(bad).find("invalid realizations = 0"), std::string::npos);
  bad = options;
  bad.counts = {1};
  EXPECT_NE(error_of(bad).find("invalid counts = 1"), std::string::npos);
  bad.counts = {};
  EXPECT_NE(error_of(bad).find("invalid counts"), std::string::npos);
}

TEST(MitchellStudy, ExtraPatternsRunThroughTheSameStudy) {
  MitchellStudyOptions options;
  options.counts = {16, 100};
  options.realizations = 3;
  options.lines = 500;
  options.seed = 7;
  options.spectrum_count = 16;
  const MitchellStudy plain = run_mitchell_study(options);
  options.extra_patterns = {{"Sobol (Owen)", "sobol", {}, "owen"}, {"Halton", "halton", {}, "none"}};
  const MitchellStudy extended = run_mitchell_study(options);
  ASSERT_EQ(extended.patterns.size(), 7u);
  ASSERT_EQ(extended.cells.size(), 14u);
  ASSERT_EQ(extended.spectra.size(), 7u);
  // Mitchell's five are untouched by the extras.
  for (std::size_t c = 0; c < plain.cells.size(); ++c) {
    EXPECT_EQ(extended.cells[c].pattern, plain.cells[c].pattern);
    EXPECT_EQ(extended.cells[c].rms_values, plain.cells[c].rms_values);
  }
  for (std::size_t s = 0; s < plain.spectra.size(); ++s) EXPECT_EQ(extended.spectra[s].power, plain.spectra[s].power);
  // The extras' cells are the random-edge discrepancies of their registry sets.
  for (const auto& pattern : options.extra_patterns) {
    const std::string id = mitchell_pattern_id(pattern);
    EXPECT_EQ(id, pattern.sampler + ":" + pattern.randomize);
    for (std::size_t n : options.counts) {
      const MitchellCell& cell = extended.cell(id, n);
      for (std::size_t r = 0; r < 3; ++r) {
        SamplerRequest request;
        request.n = cell.n;
        request.d = 2;
        request.seed = hash64(7, r);
        request.randomize = pattern.randomize;
        const PointSet points = generate_points(pattern.sampler, request);
        const auto direct = random_edge_discrepancy({points.data.get(), points.n, 2}, 500, hash64(7, r, 1));
        EXPECT_EQ(cell.rms_values[r], direct.rms) << id << " " << n << " " << r;
      }
    }
  }
  EXPECT_EQ(extended.spectra[5].pattern, "sobol:owen");
  EXPECT_EQ(extended.spectra[6].pattern, "halton:none");
  EXPECT_NE(mitchell_table(extended).find("Sobol (Owen)"), std::string::npos);
  EXPECT_EQ(mitchell_table(plain).find("Sobol (Owen)"), std::string::npos);
}

TEST(MitchellStudy, RejectsDuplicateUnknownAndUnrandomizableExtras) {
  MitchellStudyOptions options;
  options.counts = {16};
  options.realizations = 1;
  options.lines = 10;
  auto message = [&](std::vector<MitchellPattern> extras) {
    auto bad = options;
    bad.extra_patterns = std::move(extras);
    try {
      run_mitchell_study(bad);
    } catch (const invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({{"again", "jittered", {}, ""}}).find("invalid extra_patterns = jittered"), std::string::npos);
  EXPECT_NE(message({{"a", "sobol", {}, ""}, {"b", "sobol", {}, ""}}).find("invalid extra_patterns = sobol"),
            std::string::npos);
  EXPECT_NE(message({{"r", "random", {}, "no-such"}}).find("invalid extra_patterns = random:no-such"),
            std::string::npos);
  EXPECT_FALSE(message({{"?", "no-such-sampler", {}, ""}}).empty());
}

}  // namespace
}  // namespace stratum::analysis
