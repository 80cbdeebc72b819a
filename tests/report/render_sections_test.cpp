/// The report's render sections (§1 camera, §2 variance, §3 importance, §8
/// space-time, §9 path tracing), each run in quick mode through a
/// SectionContext with its own reference cache, and checked against oracles:
/// closed forms (ρ²L²/3 and 0 for uniform and cosine irradiance under a
/// constant sky, the magic sum m(m²−1)/2, the sphere's projected motion),
/// the lecture's published 4×4 tables, the unbiasedness of the renders
/// (E[MSE] = variance of the image's mean + the reference's), and that each
/// picture shows its effect where it should (sharpness in the plane of
/// focus, the motion's difference inside the swept band, penumbra variance).
/// Fixed seeds; statistical tolerances stated where used.
#include <gtest/gtest.h>

#include <map>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>

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
/// Checked on the first seed of a repeated comparison (repeated_comparison.hpp),
/// whose rows hold per-seed lists.
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

TEST(ReportRenderSections, CameraDepthOfFieldAndMotionBlurEachOnTheirOwn) {
  const Section section = run_section("camera");
  const auto& n = section.numbers;
  const render::Scene box = render::cornell_box();
  ASSERT_EQ(n["width"], 64);  // the quick report's camera renders (blur circles of a few pixels)
  EXPECT_EQ(n["spp"], 16);
  EXPECT_GT(n["aperture_radius"].get<double>(), 0);
  EXPECT_GT(n["far_focus_distance"].get<double>(), n["near_focus_distance"].get<double>());
  // Depth of field, by the sharpness statistic in each crop (the images are
  // deterministic for the fixed seed; measured 1.65x and 1.21x at 64 pixels,
  // 4.2x and 2.0x at 256): focused on the sphere, the sphere's edge is
  // sharper than with the focus on the back wall, and the back corner blurrier.
  const auto& dof = n["depth_of_field"];
  const double near_at_near = dof["near_focus"]["sharpness_near"], far_at_near = dof["far_focus"]["sharpness_near"];
  const double near_at_far = dof["near_focus"]["sharpness_far"], far_at_far = dof["far_focus"]["sharpness_far"];
  EXPECT_GT(near_at_near, 1.2 * far_at_near);
  EXPECT_GT(far_at_far, 1.1 * near_at_far);
  // In its plane of focus the lens keeps the pinhole's sharpness (within 25%).
  EXPECT_NEAR(near_at_near / dof["pinhole"]["sharpness_near"].get<double>(), 1.0, 0.25);
  EXPECT_NEAR(far_at_far / dof["pinhole"]["sharpness_far"].get<double>(), 1.0, 0.25);
  // Motion blur: the sphere's image moves by motion / depth / tan(fov/2) × half the width
  // (the motion is along the camera's horizontal axis), and the moving render
  // differs from the still one in the band its silhouette sweeps, not elsewhere.
  const auto& blur = n["motion_blur"];
  const double depth = 130 - box.camera.position.z;  // the sphere's centre is at z = 130
  const double half_tan = std::tan(box.camera.fov_degrees * std::numbers::pi / 360);
  EXPECT_NEAR(blur["swept_pixels"].get<double>(), n["motion_mm"].get<double>() / depth / half_tan * 32, 1e-9);
  EXPECT_NEAR(blur["sphere_radius_pixels"].get<double>(), 70 / depth / half_tan * 32, 1e-9);
  EXPECT_GT(blur["mean_difference_inside"].get<double>(), 5 * blur["mean_difference_outside"].get<double>());
  EXPECT_GT(blur["band_pixels"].get<int>(), 0);
  EXPECT_LT(blur["band_pixels"].get<int>(), 64 * 64 / 4);
}

TEST(ReportRenderSections, VarianceSixteenShadowRaysCutTheMse) {
  const Section section = run_section("variance");
  const auto& n = section.numbers;
  const unsigned repeats = n["repeats"].get<unsigned>();
  EXPECT_GE(repeats, 3u);
  for (const char* label : {"1 shadow ray", "16 shadow rays"}) {
    expect_unbiased_first_seed(n, label);
    expect_repeated_row(n["rows"][label], repeats, label);
  }
  // 16 independent rays divide the variance by 16, stratified ones by more;
  // with the fixed seeds the MSE ratio's whole interval must lie above 4.
  const auto& sixteen = n["rows"]["16 shadow rays"];
  EXPECT_GT(sixteen["mse_ratio"]["low"].get<double>(), 4);
  EXPECT_EQ(n["rows"]["1 shadow ray"]["spp_per_seed"], sixteen["spp_per_seed"]);
  // 16 shadow rays per eye ray cost more than 1: the efficiency ratio is
  // quoted only where the time interval says so, and then it is the MSE
  // ratio over the time ratio (per seed, hence of the geometric means).
  if (sixteen["time_resolved"].get<bool>()) {
    EXPECT_NEAR(sixteen["efficiency_ratio"]["estimate"].get<double>(),
                sixteen["mse_ratio"]["estimate"].get<double>() / sixteen["time_ratio"]["estimate"].get<double>(),
                1e-9 * sixteen["mse_ratio"]["estimate"].get<double>());
  }
  // The same inside the penumbra: the per-sample variance of a 16-ray
  // estimate is at most 1/16 of a 1-ray one's in expectation; over the
  // crop's pixels the measured ratio must exceed 4, and so must every
  // seed's MSE ratio.
  const auto& penumbra = n["penumbra"];
  EXPECT_GT(penumbra["1 shadow ray"]["sample_variance"].get<double>(),
            4 * penumbra["16 shadow rays"]["sample_variance"].get<double>());
  ASSERT_EQ(penumbra["1 shadow ray"]["mse_per_seed"].size(), repeats);
  for (unsigned k = 0; k < repeats; ++k)
    EXPECT_GT(penumbra["1 shadow ray"]["mse_per_seed"][k].get<double>(),
              4 * penumbra["16 shadow rays"]["mse_per_seed"][k].get<double>())
        << k;
  const auto& local = penumbra["16 shadow rays"]["mse_ratio"];
  EXPECT_LE(local["low"].get<double>(), local["estimate"].get<double>());
  EXPECT_GE(local["high"].get<double>(), local["estimate"].get<double>());
  EXPECT_GT(penumbra["16 shadow rays"]["sample_variance"].get<double>(), 0);  // a penumbra, not a lit or dark floor
  EXPECT_GT(penumbra["box"][2].get<int>(), 0);
  // The sentences quote ratios with their intervals, and an efficiency only
  // as the table does.
  EXPECT_NE(section.text[1].find("95% CI"), std::string::npos) << section.text[1];
  EXPECT_NE(
      section.text[2].find(sixteen["time_resolved"].get<bool>() ? "so its efficiency" : "within the timing noise"),
      std::string::npos)
      << section.text[2];
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
  for (const char* comparison : {"light_strategy", "light_strategy_large", "hemisphere"}) {
    const auto& numbers = section.numbers[comparison];
    const unsigned repeats = numbers["repeats"].get<unsigned>();
    EXPECT_GE(repeats, 3u) << comparison;
    for (const auto& [label, row] : numbers["rows"].items()) {
      expect_unbiased_first_seed(numbers, label);
      expect_repeated_row(row, repeats, label);
    }
  }
  // The large light with 1 shadow ray: on the wall under the light, area
  // sampling's MSE is several times projected solid angle's in every seed
  // (measured about 10x at 32 pixels, 290x at 256; the check asks for 3x),
  // and over the image the ratio's interval lies above 2.
  const auto& large = section.numbers["light_strategy_large"];
  const auto& wall = large["wall"];
  ASSERT_EQ(wall["area"]["mse_per_seed"].size(), large["repeats"].get<std::size_t>());
  for (std::size_t k = 0; k < wall["area"]["mse_per_seed"].size(); ++k)
    EXPECT_GT(wall["area"]["mse_per_seed"][k].get<double>(),
              3 * wall["projected solid angle"]["mse_per_seed"][k].get<double>())
        << k;
  EXPECT_GT(large["rows"]["projected solid angle"]["mse_ratio"]["low"].get<double>(), 2);
  // Under the sky, cosine-weighted directions beat uniform ones.
  EXPECT_GT(section.numbers["hemisphere"]["rows"]["cosine"]["mse_ratio"]["low"].get<double>(), 2);
  // Every sentence that quotes an MSE or efficiency ratio of the renders
  // gives its interval; none quotes an efficiency the times do not resolve.
  for (std::size_t t : {0, 1, 2, 3, 4}) EXPECT_NE(section.text[t].find("95% CI"), std::string::npos) << section.text[t];
  // The directions drawn: E[cos θ] is 1/2 for uniform directions and 2/3 for
  // cosine-weighted ones; 256 jittered directions are within 5 i.i.d.
  // standard errors (sqrt(1/12/256) and sqrt(1/18/256); jittered sampling
  // of these smooth functions does better).
  const auto& directions = section.numbers["directions"];
  EXPECT_NEAR(directions["uniform"]["mean_cos_theta"].get<double>(), 0.5, 5 * std::sqrt(1.0 / 12 / 256));
  EXPECT_NEAR(directions["cosine-weighted"]["mean_cos_theta"].get<double>(), 2.0 / 3, 5 * std::sqrt(1.0 / 18 / 256));
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
  EXPECT_GT(pixels, 0);        // the sphere moves
  EXPECT_LT(pixels, 32 * 32);  // the walls do not
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
                row["mse_per_seed"][k].get<double>() * 32 * 32 * (1 + 1e-12))
          << label;
  }
  // Elsewhere the renders agree: the whole-image sums of squared error differ
  // only by the time-dependent pixels' (same film, lens and light samples).
  const auto& rows = blur["rows"];
  for (unsigned k = 0; k < repeats; ++k) {
    const double whole_gap =
        (rows["cook"]["mse_per_seed"][k].get<double>() - rows["random time"]["mse_per_seed"][k].get<double>()) * 32 *
        32;
    const double local_gap = (rows["cook"]["time_dependent_mse_per_seed"][k].get<double>() -
                              rows["random time"]["time_dependent_mse_per_seed"][k].get<double>()) *
                             pixels;
    EXPECT_NEAR(whole_gap, local_gap, 1e-9) << k;
  }
  // Where the error goes: three pixel samplers at 1, 4 and 16 spp, each with
  // its error's low-frequency power and its MSE after the 1-pixel blur (below
  // the MSE: the blur averages neighbouring errors, which are not all equal).
  const auto& screen = section.numbers["screen_space_error"]["rows"];
  EXPECT_EQ(screen.size(), 9u);
  std::map<std::uint64_t, int> per_spp;
  for (const auto& [label, row] : screen.items()) {
    ++per_spp[row["spp"].get<std::uint64_t>()];
    EXPECT_GT(row["blurred_mse"].get<double>(), 0) << label;
    EXPECT_LT(row["blurred_mse"].get<double>(), row["mse"].get<double>()) << label;
    EXPECT_GT(row["low_frequency_power"].get<double>(), 0) << label;
  }
  EXPECT_EQ(per_spp, (std::map<std::uint64_t, int>{{1, 3}, {4, 3}, {16, 3}}));
  // The close-up: the sphere fills the frame, so a far larger share of its
  // pixels depends on time than of the whole box's.
  const auto& close = section.numbers["motion_close_up"];
  EXPECT_EQ(close["pixels"], 32 * 32);
  EXPECT_GT(close["time_dependent_pixels"].get<double>(), 3.0 * pixels);
  for (const auto& [label, row] : close["rows"].items()) {
    expect_repeated_row(row, repeats, label);
    expect_unbiased_first_seed(close, label, true);
  }
  // The close-up drawn for the eye: the three assignments and the window
  // where they differ most, inside the image.
  const auto& picture = section.numbers["motion_picture"];
  EXPECT_EQ(picture["rows"].size(), 3u);
  const auto crop = picture["crop"].get<std::vector<int>>();
  ASSERT_EQ(crop.size(), 4u);
  EXPECT_EQ(crop[2], 8);  // a quarter of 32
  EXPECT_TRUE(crop[0] >= 0 && crop[1] >= 0 && crop[0] + crop[2] <= 32 && crop[1] + crop[3] <= 32);
  // In time (16 frames at 1 spp, 32×32, quick): random's frames are
  // independent (temporal power ~1 at the one bin below 1/8, sd ~0.06; lag-1
  // correlation -1/16 from the centring), frames that continue each pixel's
  // sequence cancel (measured sobol-bn 0.43 at this size): asserted < 0.7,
  // lag-1 < -0.05, and 4 frames averaged well below 4 independent frames.
  const auto& frames = section.numbers["frames_error"];
  EXPECT_EQ(frames["frames"], 16);
  const auto& random = frames["rows"]["random"];
  EXPECT_NEAR(random["low_frequency_power"].get<double>(), 1.0, 0.3);
  EXPECT_NEAR(random["lag1_correlation"].get<double>(), -1.0 / 16, 0.15);
  const double random_ratio =
      random["averaged_4_frames_mse"].get<double>() / random["independent_4_frames_mse"].get<double>();
  EXPECT_GT(random_ratio, 0.75);
  EXPECT_LT(random_ratio, 1.33);
  for (const char* name : {"sobol", "zsobol", "sobol-bn", "pmj02-bn"}) {
    const auto& row = frames["rows"][name];
    EXPECT_LT(row["low_frequency_power"].get<double>(), 0.7) << name;
    EXPECT_LT(row["lag1_correlation"].get<double>(), -0.05) << name;
    EXPECT_EQ(row["power"].size(), 8u) << name;
    EXPECT_LT(row["averaged_4_frames_mse"].get<double>(), 0.75 * row["independent_4_frames_mse"].get<double>()) << name;
    EXPECT_LT(row["averaged_4_frames_mse"].get<double>(), 1.5 * row["one_frame_4_spp_mse"].get<double>()) << name;
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
  // The picture (the pictures' size, first seed): both shapes at equal rays,
  // and the complete one given the incomplete render's time, in whole passes
  // of its 4 eye rays; the figure is drawn.
  const auto& picture = n["picture"];
  EXPECT_EQ(picture["width"], 32);  // quick
  EXPECT_EQ(picture["rows"]["complete 4x16"]["spp"], 4);
  EXPECT_EQ(picture["rows"]["incomplete 64x1"]["spp"], 64);
  EXPECT_DOUBLE_EQ(picture["equal_time_seconds"].get<double>(),
                   picture["rows"]["incomplete 64x1"]["seconds"].get<double>());
  const auto& at_time = picture["complete_at_equal_time"]["complete 4x16 per pass"];
  EXPECT_EQ(at_time["spp"].get<unsigned>() % 4, 0u);
  EXPECT_GE(at_time["seconds"].get<double>(), picture["equal_time_seconds"].get<double>());
  EXPECT_TRUE(std::any_of(section.figures.begin(), section.figures.end(), [](const Figure& figure) {
    return figure.file == "figures/path-tracing-complete-incomplete-picture.png";
  }));
}

}  // namespace
}  // namespace stratum::report
