/// The report's render sections (§1 camera, §2 variance, §3 importance, §8
/// space-time, §9 path tracing), each run in quick mode through a
/// SectionContext with its own reference cache, and checked against oracles:
/// closed forms (ρ²L²/3 and 0 for uniform and cosine irradiance under a
/// constant sky, the magic sum m(m²−1)/2), the lecture's published 4×4 tables,
/// and the unbiasedness of the renders (E[MSE] = variance of the image's mean
/// + the reference's). Fixed seeds; statistical tolerances stated where used.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

#include "section_harness.hpp"
#include "stratum/render/scene.hpp"

namespace stratum::report {
namespace {

namespace fs = std::filesystem;

/// Runs section `id` in quick mode (seed 1, 2 threads, a fresh reference
/// cache) and checks what every section must have.
Section run_section(const std::string& id) {
  testing::TempFolder staging;
  std::vector<plot::PlotJob> plots;
  Section section = testing::run_quick_section(id, staging, plots);
  EXPECT_GE(section.text.size(), 2u);
  // Every figure is a queued plot (renders are tiled by report_images.py).
  EXPECT_EQ(plots.size(), section.figures.size());
  for (const auto& figure : section.figures) EXPECT_EQ(figure.file.rfind("figures/" + id + "-", 0), 0u) << figure.file;
  for (const auto& text : section.text) EXPECT_EQ(text.find("nan"), std::string::npos) << text;
  return section;
}

/// An unbiased render's MSE against an independent reference has
/// expectation (image variance of the mean) + (reference variance of the
/// mean). With thousands of pixel values and a fixed seed, the measured MSE
/// must fall between half the image's variance and twice the sum (the
/// reference's variance is that of a QMC render taken as if random, an
/// overestimate, hence no tighter lower bound). For stratified pixel samples
/// (`stratified`) the image's variance is also an i.i.d. estimate, an upper
/// bound of the true one (jittered sampling never does worse than random),
/// so only the upper bound applies.
void expect_unbiased_mse(const nlohmann::json& comparison, const std::string& label, bool stratified = false) {
  const auto& row = comparison["rows"][label];
  const double image_variance = row["sample_variance"].get<double>() / row["spp"].get<double>();
  const double mse = row["mse"].get<double>();
  if (!stratified) {
    EXPECT_GT(mse, 0.5 * image_variance) << label;
  }
  EXPECT_LT(mse, 2 * (image_variance + comparison["reference_variance"].get<double>())) << label;
  EXPECT_NEAR(row["efficiency"].get<double>() * mse * row["seconds"].get<double>(), 1.0, 1e-9) << label;
}

/// expect_unbiased_mse for the first seed of a repeated comparison
/// (repeated_comparison.hpp), whose rows hold per-seed lists.
void expect_unbiased_first_seed(const nlohmann::json& comparison, const std::string& label, bool stratified = false) {
  const auto& row = comparison["rows"][label];
  const double image_variance = row["sample_variance"].get<double>() / row["spp_per_seed"][0].get<double>();
  const double mse = row["mse_per_seed"][0].get<double>();
  if (!stratified) {
    EXPECT_GT(mse, 0.5 * image_variance) << label;
  }
  EXPECT_LT(mse, 2 * (image_variance + comparison["reference_variance"].get<double>())) << label;
}

/// A row of a repeated comparison: one MSE and time per seed, their
/// summaries, intervals that hold their estimates, and an efficiency ratio
/// only where the time ratio's interval excludes 1.
void expect_repeated_row(const nlohmann::json& row, unsigned repeats, const std::string& label) {
  ASSERT_EQ(row["mse_per_seed"].size(), repeats) << label;
  ASSERT_EQ(row["seconds_per_seed"].size(), repeats) << label;
  double sum = 0;
  for (const auto& v : row["mse_per_seed"]) sum += v.get<double>();
  EXPECT_NEAR(row["mse_mean"].get<double>(), sum / repeats, 1e-12 * sum) << label;
  for (const char* key : {"mse_ratio", "time_ratio", "efficiency_ratio_unresolved"}) {
    const auto& interval = row[key];
    EXPECT_EQ(interval["count"], repeats) << label << " " << key;
    EXPECT_LE(interval["low"].get<double>(), interval["estimate"].get<double>()) << label << " " << key;
    EXPECT_GE(interval["high"].get<double>(), interval["estimate"].get<double>()) << label << " " << key;
  }
  const auto& time = row["time_ratio"];
  const bool resolved = time["low"].get<double>() > 1 || time["high"].get<double>() < 1;
  EXPECT_EQ(row["time_resolved"].get<bool>(), resolved) << label;
  EXPECT_EQ(row["efficiency_ratio"].is_null(), !resolved) << label;
}

TEST(ReportRenderSections, CameraRendersTheLensAndMotionSceneAndAPinhole) {
  const Section section = run_section("camera");
  const auto& n = section.numbers;
  const render::Scene box = render::cornell_box();
  EXPECT_EQ(n["width"], 32);
  EXPECT_EQ(n["spp"], 16);
  EXPECT_EQ(n["aperture_radius"].get<double>(), box.camera.aperture_radius);
  EXPECT_GT(n["aperture_radius"].get<double>(), 0);
  EXPECT_GT(n["motion_mm"].get<double>(), 0);
  for (const char* render : {"lens", "pinhole"}) {
    const double seconds = n[render]["seconds"].get<double>();
    EXPECT_GT(seconds, 0);
    EXPECT_NEAR(n[render]["rays_per_second"].get<double>() * seconds, 32.0 * 32 * 16, 1e-6);
  }
}

TEST(ReportRenderSections, VarianceSixteenShadowRaysCutTheMse) {
  const Section section = run_section("variance");
  const auto& n = section.numbers;
  expect_unbiased_mse(n, "1 shadow ray");
  expect_unbiased_mse(n, "16 shadow rays");
  // 16 independent rays divide the variance by 16, stratified ones by more;
  // with the fixed seed the measured MSE ratio must be well above 4.
  EXPECT_GT(n["rows"]["16 shadow rays"]["mse_ratio"].get<double>(), 4);
  EXPECT_EQ(n["rows"]["1 shadow ray"]["spp"], n["rows"]["16 shadow rays"]["spp"]);
}

TEST(ReportRenderSections, ImportanceZeroVarianceAndClosedForms) {
  const Section section = run_section("importance");
  const auto& zero = section.numbers["zero_variance"];
  const double samples = zero["cosine"]["samples"].get<double>();
  ASSERT_GE(samples, 1000);
  // ρ = (0.8, 0.6, 0.4), L = 1: mean ρL = 0.6; cosine-weighted samples all
  // equal ρL, so the variance is rounding only: the renderer's running
  // Σy² − (Σy)²/N loses about ε·ρ² (≈ 1e-16) to cancellation; 1e-12 leaves
  // room for that and none for a real spread (uniform sampling gives 0.13).
  EXPECT_NEAR(zero["expected_mean"].get<double>(), 0.6, 1e-12);
  EXPECT_NEAR(zero["cosine"]["mean"].get<double>(), 0.6, 1e-12);
  EXPECT_LT(zero["cosine"]["sample_variance"].get<double>(), 1e-12);
  EXPECT_LT(zero["cosine"]["largest_pixel_variance"].get<double>(), 1e-12);
  // Uniform: Y = 2ρL·U, U ~ U(0,1); per-sample variance mean(ρ²)/3 = 0.12889;
  // the relative standard deviation of a variance estimate from K samples is
  // sqrt((μ4/σ⁴ − 1)/K) = sqrt(0.8/K) (μ4/σ⁴ = 9/5 for a uniform); 5σ
  // (α ≈ 6e-7 two-sided) for each of the two checks.
  const double predicted = (0.64 + 0.36 + 0.16) / 9;
  EXPECT_NEAR(zero["uniform"]["predicted_variance"].get<double>(), predicted, 1e-12);
  EXPECT_NEAR(zero["uniform"]["sample_variance"].get<double>(), predicted, 5 * predicted * std::sqrt(0.8 / samples));
  // Mean: sd = mean(ρ)·L·sqrt(1/3)/√K.
  EXPECT_NEAR(zero["uniform"]["mean"].get<double>(), 0.6, 5 * 0.6 * std::sqrt(1.0 / 3 / samples));
  for (const char* comparison : {"light_strategy", "hemisphere"})
    for (const auto& [label, row] : section.numbers[comparison]["rows"].items())
      expect_unbiased_mse(section.numbers[comparison], label);
  // The analysis study's sky: cosine sampling is the zero-variance estimator.
  const auto& sky = section.numbers["study"]["hemisphere"][0];
  EXPECT_EQ(sky["scene"], "sky");
  EXPECT_LT(sky["b"]["variance"].get<double>(), 1e-20);
  EXPECT_GT(sky["a"]["variance"].get<double>(), 0);
}

TEST(ReportRenderSections, SpaceTimeTablesAndMotionBlur) {
  const Section section = run_section("space-time");
  const auto& tables = section.numbers["tables"];
  // The lecture's slide (LECTURE.md §8), rows top to bottom.
  const std::vector<std::uint64_t> cook{6, 10, 2, 13, 3, 14, 12, 8, 15, 0, 7, 11, 5, 9, 4, 1};
  const std::vector<std::uint64_t> magic{15, 8, 5, 2, 4, 3, 14, 9, 10, 13, 0, 7, 1, 6, 11, 12};
  EXPECT_EQ(tables["Cook pattern"]["slots"].get<std::vector<std::uint64_t>>(), cook);
  EXPECT_EQ(tables["pan-diagonal magic square"]["slots"].get<std::vector<std::uint64_t>>(), magic);
  EXPECT_EQ(section.numbers["magic_sum"], 4 * (16 - 1) / 2);
  // Brute force from the slide: every line of the magic square sums to 30.
  for (int k = 0; k < 4; ++k) {
    std::uint64_t row = 0, column = 0, diagonal = 0, antidiagonal = 0, cook_row = 0;
    for (int r = 0; r < 4; ++r) {
      row += magic[4 * k + r], column += magic[4 * r + k];
      diagonal += magic[4 * r + (r + k) % 4], antidiagonal += magic[4 * r + (k + 4 - r) % 4];
      cook_row += cook[4 * k + r];
    }
    const auto& m = tables["pan-diagonal magic square"];
    EXPECT_EQ(m["row_sums"][k], row);
    EXPECT_EQ(m["column_sums"][k], column);
    EXPECT_EQ(m["diagonal_sums"][k], diagonal);
    EXPECT_EQ(m["antidiagonal_sums"][k], antidiagonal);
    EXPECT_EQ(row, 30u);
    EXPECT_EQ(diagonal, 30u);
    EXPECT_EQ(antidiagonal, 30u);
    EXPECT_EQ(tables["Cook pattern"]["row_sums"][k], cook_row);
  }
  EXPECT_TRUE(tables["pan-diagonal magic square"]["pandiagonal_magic"].get<bool>());
  EXPECT_FALSE(tables["Cook pattern"]["pandiagonal_magic"].get<bool>());  // row sums 31, 37, 33, 19
  EXPECT_EQ(tables["Cook pattern"]["neighbour_separation"], 2);           // cook_separation(4)
  const auto& blur = section.numbers["motion_blur"];
  const int pixels = blur["time_dependent_pixels"].get<int>();
  EXPECT_GT(pixels, 0);                // the sphere moves
  EXPECT_LT(pixels, 32 * 32);          // the walls do not
  const unsigned repeats = blur["repeats"].get<unsigned>();
  EXPECT_GE(repeats, 3u);
  for (const auto& [label, row] : blur["rows"].items()) {
    EXPECT_EQ(row["spp_per_seed"][0], 16) << label;
    expect_unbiased_first_seed(blur, label, true);  // space-time patterns: jittered in x, y and t
    expect_repeated_row(row, repeats, label);
    const auto& local = row["time_dependent_mse_ratio"];
    EXPECT_LE(local["low"].get<double>(), local["estimate"].get<double>()) << label;
    EXPECT_GE(local["high"].get<double>(), local["estimate"].get<double>()) << label;
    // The time-dependent pixels hold less error than the whole image's sum.
    for (unsigned k = 0; k < repeats; ++k)
      EXPECT_LE(row["time_dependent_mse_per_seed"][k].get<double>() * pixels,
                row["mse_per_seed"][k].get<double>() * 32 * 32 * (1 + 1e-12)) << label;
  }
  // Elsewhere the renders agree: the whole-image sums of squared error differ
  // only by the time-dependent pixels' (same film, lens and light samples).
  const auto& rows = blur["rows"];
  for (unsigned k = 0; k < repeats; ++k) {
    const double whole_gap = (rows["cook"]["mse_per_seed"][k].get<double>() -
                              rows["random time"]["mse_per_seed"][k].get<double>()) * 32 * 32;
    const double local_gap = (rows["cook"]["time_dependent_mse_per_seed"][k].get<double>() -
                              rows["random time"]["time_dependent_mse_per_seed"][k].get<double>()) * pixels;
    EXPECT_NEAR(whole_gap, local_gap, 1e-9) << k;
  }
  // The close-up: the sphere fills the frame, so a far larger share of its
  // pixels depends on time than of the whole box's.
  const auto& close = section.numbers["motion_close_up"];
  EXPECT_EQ(close["pixels"], 32 * 32);
  EXPECT_GT(close["time_dependent_pixels"].get<double>(), 3.0 * pixels);
  for (const auto& [label, row] : close["rows"].items()) {
    expect_repeated_row(row, repeats, label);
    expect_unbiased_first_seed(close, label, true);
  }
}

TEST(ReportRenderSections, PathTracingAtEqualRaysAndAtEqualTime) {
  const Section section = run_section("path-tracing");
  const auto& n = section.numbers;
  EXPECT_EQ(n["shadow_rays_per_pixel"]["complete 4x16"], 64);
  EXPECT_EQ(n["shadow_rays_per_pixel"]["incomplete 64x1"], 64);
  const auto& rays = n["equal_rays"];
  const unsigned repeats = rays["repeats"].get<unsigned>();
  EXPECT_GE(repeats, 3u);
  for (unsigned k = 0; k < repeats; ++k) {
    EXPECT_EQ(rays["rows"]["complete 4x16"]["spp_per_seed"][k], 4);
    EXPECT_EQ(rays["rows"]["incomplete 64x1"]["spp_per_seed"][k], 64);
  }
  expect_unbiased_first_seed(rays, "complete 4x16");
  expect_unbiased_first_seed(rays, "incomplete 64x1");
  for (const auto& [label, row] : rays["rows"].items()) expect_repeated_row(row, repeats, label);
  // Equal time: every render ran at least the budget (the pass that reaches
  // it finishes), and the budget is the incomplete render's median at equal rays.
  const auto& timed = n["equal_time"];
  const double budget = timed["equal_time_seconds"].get<double>();
  EXPECT_DOUBLE_EQ(budget, rays["rows"]["incomplete 64x1"]["seconds_median"].get<double>());
  for (const auto& [label, row] : timed["rows"].items()) {
    expect_repeated_row(row, repeats, label);
    for (const auto& seconds : row["seconds_per_seed"]) EXPECT_GE(seconds.get<double>(), budget) << label;
    for (const auto& spp : row["spp_per_seed"]) EXPECT_EQ(spp.get<unsigned>() % 4, 0u) << label;  // whole passes
  }
  // The headline names the equal-time winner, from the efficiency interval
  // when the times are resolved, else from the MSE interval.
  const auto& incomplete = timed["rows"]["incomplete 4x1 per pass"];
  const bool resolved = incomplete["time_resolved"].get<bool>();
  EXPECT_EQ(n["equal_time_decided_by"], resolved ? "efficiency_ratio" : "mse_ratio");
  const auto& ratio = resolved ? incomplete["efficiency_ratio"] : incomplete["mse_ratio"];
  const std::string winner = n["equal_time_winner"].get<std::string>();
  EXPECT_EQ(winner, ratio["low"].get<double>() > 1    ? "incomplete"
                    : ratio["high"].get<double>() < 1 ? "complete"
                                                      : "neither");
  EXPECT_EQ(section.text.front().rfind("At equal time, ", 0), 0u) << section.text.front();
}

}  // namespace
}  // namespace stratum::report
