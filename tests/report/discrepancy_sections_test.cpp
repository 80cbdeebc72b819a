/// The report's discrepancy sections (§10 discrepancy, §11 QMC, §12 the
/// pattern comparison), each run in quick mode through a SectionContext and
/// checked against oracles: the exact star-discrepancy sweep on regenerated
/// point sets, L2-star ≤ D* (an L2 norm never exceeds the supremum), the
/// Koksma–Hlawka bound recomputed from its parts, φ2 by integer bit
/// reversal, and the binomial rate N^(−1/2) of random points (a z-test with
/// stated α). Fixed seeds.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "section_harness.hpp"
#include "stratum/analysis/edge_discrepancy.hpp"
#include "stratum/analysis/koksma_hlawka.hpp"
#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::report {
namespace {

namespace fs = std::filesystem;

/// Runs section `id` in quick mode (seed 1, 2 threads); draws its figures when `draw`.
Section run_section(const std::string& id, std::vector<std::string> extras = {}, bool draw = false) {
  testing::TempFolder staging;
  std::vector<plot::PlotJob> plots;
  Section section = testing::run_quick_section(id, staging, plots, std::move(extras));
  for (const auto& text : section.text) EXPECT_EQ(text.find("n/a"), std::string::npos) << text;
  if (draw) {
    plot::write_plots(plots, 2);
    for (const auto& figure : section.figures) EXPECT_TRUE(fs::exists(staging.path / figure.file)) << figure.file;
  }
  return section;
}

PointSet points_of(const std::string& sampler, const std::string& randomize, std::uint64_t n, std::uint64_t seed) {
  SamplerRequest request;
  request.n = n;
  request.d = 2;
  request.seed = seed;
  request.randomize = randomize;
  return generate_points(sampler, request);
}

TEST(DiscrepancySection, PictureBoxesAndValuesMatchTheExactSweep) {
  const Section section = run_section("discrepancy", {"sobol:owen", "pmj02"}, /*draw=*/true);
  const auto& numbers = section.numbers;
  // The picture's sets, regenerated: their D* by the independent sweep.
  for (const auto& [label, sampler, randomize] :
       {std::tuple<std::string, std::string, std::string>{"random", "random", ""},
        {"hammersley:none", "hammersley", "none"}}) {
    const PointSet points = points_of(sampler, randomize, 64, 1);
    const double star = analysis::star_discrepancy_2d({points.data.get(), 64, 2});
    EXPECT_NEAR(numbers["picture"][label]["star"].get<double>(), star, 1e-13) << label;
    EXPECT_LE(numbers["picture"][label]["grid_max_abs"].get<double>(), star + 1e-15);
  }
  // sobol:owen is already compared, so only pmj02 is added.
  EXPECT_EQ(numbers["patterns"].size(), 7u);
  EXPECT_TRUE(numbers["patterns"].contains("pmj02"));
  const auto& functions = analysis::variation_test_functions();
  std::size_t checks = 0;
  for (const auto& [label, entry] : numbers["patterns"].items()) {
    const double star = entry["star"], l2 = entry["l2_star"];
    EXPECT_GT(l2, 0);
    EXPECT_LE(l2, star) << label;  // ‖Δ‖₂ ≤ sup |Δ|
    for (const auto& function : functions) {
      const auto& check = entry["koksma_hlawka"][function.name];
      EXPECT_NEAR(check["bound"].get<double>(), function.variation * star, 1e-15) << label;
      EXPECT_NEAR(check["error"].get<double>(), std::fabs(check["estimate"].get<double>() - function.integral), 1e-15);
      EXPECT_TRUE(check["holds"].get<bool>()) << label << " " << function.name;
      ++checks;
    }
  }
  EXPECT_EQ(numbers["koksma_hlawka"]["checks"].get<std::size_t>(), checks);
  EXPECT_EQ(numbers["koksma_hlawka"]["held"].get<std::size_t>(), checks);
  // Hammersley's D* at N = 256, regenerated.
  const PointSet hammersley = points_of("hammersley", "none", 256, 1);
  EXPECT_NEAR(numbers["patterns"]["hammersley:none"]["star"].get<double>(),
              analysis::star_discrepancy_2d({hammersley.data.get(), 256, 2}), 1e-13);
}

TEST(QmcSection, RadicalInverseTableAndExactCurves) {
  const Section section = run_section("qmc", {"sobol:owen"});
  const auto& numbers = section.numbers;
  ASSERT_EQ(numbers["phi2"].size(), 16u);
  for (unsigned i = 0; i < 16; ++i) {
    const unsigned reversed = ((i & 1) << 3) | ((i & 2) << 1) | ((i & 4) >> 1) | ((i & 8) >> 3);
    EXPECT_EQ(numbers["phi2"][i].get<double>(), reversed / 16.0) << i;
  }
  EXPECT_TRUE(numbers["phi2_equals_mirrored_digits"].get<bool>());
  EXPECT_EQ(section.tables.front().rows[4][2], "0.0010₂");  // the lecture's 4 = 100₂ → 0.001₂
  // The slide's worked example prints 3/8: marked as an erratum beside the right value.
  EXPECT_EQ(numbers["slide_erratum"]["slide"].get<double>(), 0.375);
  EXPECT_EQ(numbers["slide_erratum"]["correct"].get<double>(), 0.125);
  EXPECT_NE(section.tables.front().rows[4].back().find("erratum"), std::string::npos);
  EXPECT_TRUE(section.tables.front().rows[3].back().empty());
  const auto& hammersley = numbers["curves"]["hammersley:none"];
  for (std::size_t k : {0u, 5u}) {
    const auto n = static_cast<std::uint64_t>(hammersley["n"][k].get<double>());
    const PointSet points = points_of("hammersley", "none", n, 0);
    EXPECT_NEAR(hammersley["star"][k].get<double>(), analysis::star_discrepancy_2d({points.data.get(), n, 2}), 1e-13);
    EXPECT_EQ(hammersley["standard_error"][k].get<double>(), 0.0);  // deterministic: one set
  }
  EXPECT_GT(numbers["curves"]["random"]["standard_error"][0].get<double>(), 0.0);
  EXPECT_TRUE(numbers["curves"].contains("sobol:owen"));
  // D*·N/log N is bounded for Hammersley (Niederreiter 1992, Thm 3.8): over
  // a 128-fold range of N it moves by far less than N does.
  EXPECT_LT(numbers["ratio_spread"]["hammersley"].get<double>(), 4.0);
}

TEST(PatternsSection, MitchellTableExtrasAndTheRandomRate) {
  const Section section = run_section("patterns", {"sobol:owen", "jittered"});
  const auto& patterns = section.numbers["patterns"];
  EXPECT_EQ(patterns.size(), 6u);  // Mitchell's five and sobol:owen; jittered is one of the five
  ASSERT_TRUE(patterns.contains("sobol:owen"));
  std::string lowest;
  double lowest_value = INFINITY;
  for (const auto& [id, entry] : patterns.items()) {
    ASSERT_EQ(entry["cells"].size(), 3u);
    EXPECT_EQ(entry["cells"][2]["requested"].get<std::size_t>(), 1600u);
    if (entry["cells"][2]["rms"].get<double>() < lowest_value)
      lowest_value = entry["cells"][2]["rms"], lowest = entry["label"];
  }
  EXPECT_EQ(section.numbers["lowest_at_1600"].get<std::string>(), lowest);
  // Random points: E[D²] = c/N exactly, so the slope of log mean RMS on log N
  // is −1/2 up to noise. z-test with the standard error propagated from the
  // cells' standard errors (delta method); two-sided α = 1e-3, z = 3.29.
  const auto& cells = patterns["random"]["cells"];
  double mean_log_n = 0;
  for (const auto& cell : cells) mean_log_n += std::log(cell["n"].get<double>()) / 3;
  double sxx = 0;
  for (const auto& cell : cells) sxx += std::pow(std::log(cell["n"].get<double>()) - mean_log_n, 2);
  double variance = 0;
  for (const auto& cell : cells) {
    const double weight = (std::log(cell["n"].get<double>()) - mean_log_n) / sxx;
    variance += std::pow(weight * cell["rms_se"].get<double>() / cell["rms"].get<double>(), 2);
  }
  EXPECT_NEAR(patterns["random"]["slope"].get<double>(), -0.5, 3.29 * std::sqrt(variance));
}

TEST(PatternsSection, MitchellsPublishedValuesBesideOursWithTheRatio) {
  const Section section = run_section("patterns");
  const auto& published = section.numbers["mitchell_1992"];
  ASSERT_EQ(published.size(), 5u);
  EXPECT_EQ(published["zaremba"][0]["mitchell"].get<double>(), 0.0504);
  EXPECT_EQ(published["random"][2]["mitchell"].get<double>(), 0.00866);
  for (const auto& [id, cells] : published.items())
    for (std::size_t k = 0; k < 3; ++k) {
      const double ours = section.numbers["patterns"][id]["cells"][k]["rms"];
      EXPECT_EQ(cells[k]["ours"].get<double>(), ours);
      EXPECT_DOUBLE_EQ(cells[k]["ratio"].get<double>(), ours / cells[k]["mitchell"].get<double>());
    }
  // The expected RMS of random points, √(c/N), against the measured one: the
  // measured mean of per-realization RMS lies a little below (Jensen), within
  // 4 standard errors plus 5% (quick: 6 realizations).
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& cell = section.numbers["patterns"]["random"]["cells"][k];
    const double expected = section.numbers["random_expected_rms"][k]["rms"];
    EXPECT_NEAR(cell["rms"].get<double>(), expected, 4 * cell["rms_se"].get<double>() + 0.05 * expected) << k;
  }
}

TEST(PatternsSection, ExpectedBinomialEdgeVarianceAgreesWithRandomLines) {
  // The quadrature over the line measure against the mean of A(1 − A) over
  // the study's own random lines: z-test, two-sided α = 1e-3 (z = 3.29).
  const double quadrature = expected_binomial_edge_variance(600);
  const std::size_t lines = 200000;
  double sum = 0, squares = 0;
  for (std::size_t i = 0; i < lines; ++i) {
    const analysis::EdgeLine line = analysis::random_isotropic_line(7, i);
    const double area = analysis::half_plane_area(std::cos(line.angle), std::sin(line.angle), line.offset);
    sum += area * (1 - area);
    squares += area * area * (1 - area) * (1 - area);
  }
  const double mean = sum / lines, se = std::sqrt((squares / lines - mean * mean) / lines);
  EXPECT_NEAR(quadrature, mean, 3.29 * se);
  EXPECT_NEAR(expected_binomial_edge_variance(300), quadrature, 1e-5);  // converged
}

TEST(EdgeDiscrepancySection, GridPatternsAgainstTheDirectEnumerationAndTheBound) {
  const Section section = run_section("edge-discrepancy", {}, /*draw=*/true);
  const auto& patterns = section.numbers["grid_patterns"];
  std::map<std::size_t, double> best, standard;
  for (const auto& p : patterns) {
    std::vector<double> xy;
    for (const auto& cell : p["cells"])
      xy.insert(xy.end(), {(cell[0].get<int>() + 0.5) / 8, (cell[1].get<int>() + 0.5) / 8});
    const std::size_t n = p["n"];
    ASSERT_EQ(xy.size(), 2 * n);
    const analysis::PointView view{xy.data(), n, 2};
    const double value = p["edge_discrepancy"];
    // The O(N³) enumeration of every candidate line is an independent oracle
    // (for 2 or more points; one sample's value is checked through its line).
    if (n >= 2) {
      EXPECT_NEAR(value, analysis::edge_discrepancy_naive(view).value, 1e-12) << p["name"];
    }
    // The reported line attains it.
    const analysis::EdgeLine line{p["line"]["angle"].get<double>(), p["line"]["offset"].get<double>()};
    // Samples exactly on the line may be counted on one side only in floating point: a lower bound.
    EXPECT_LE(analysis::line_discrepancy(view, line), value + 1e-9) << p["name"];
    EXPECT_GE(value, 0.5 / n - 1e-12) << p["name"];  // no N-sample pattern beats 1/(2N)
    EXPECT_LE(p["axis_aligned"].get<double>(), value + 1e-12);
    const std::string name = p["name"];
    if (name.find("the best N-rooks") != std::string::npos) best[n] = value;
    else if (name.find("ordered") == std::string::npos)  // the other standard patterns are N-rooks too
      standard[n] = std::min(standard.count(n) ? standard[n] : INFINITY, value);
  }
  ASSERT_EQ(best.size(), 4u);
  for (const auto& [n, value] : standard) EXPECT_LE(best[n], value + 1e-12) << n;
  // One sample: the best placement on the grid is a centre subpixel, whose
  // worst line through it cuts off the smaller part of the pixel.
  EXPECT_GT(best[1], 0.5);
  // The ordered 2×2 grid has two rows, y = 2.5/8 and 5.5/8: the horizontal
  // edge through the upper row has all 4 samples on its closed side and area
  // 5.5/8 there, an error of 2.5/8 > 1/4.
  const auto ordered = std::find_if(patterns.begin(), patterns.end(), [](const nlohmann::json& p) {
    return p["name"].get<std::string>().find("ordered") != std::string::npos;
  });
  ASSERT_NE(ordered, patterns.end());
  EXPECT_GT((*ordered)["axis_aligned"].get<double>(), 0.25);
  for (const auto& [id, cells] : section.numbers["lecture_patterns"].items())
    for (const auto& cell : cells) EXPECT_GE(cell["mean"].get<double>(), 0.5 / cell["n"].get<double>() - 1e-12) << id;
  EXPECT_FALSE(section.try_it.empty());
}

}  // namespace
}  // namespace stratum::report
