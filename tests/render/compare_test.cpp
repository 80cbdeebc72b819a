// Measuring renders against references (src/render/compare.cpp).
#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <filesystem>
#include <map>

#include "stratum/render/compare.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {
namespace {

Image flat(double value, int n = 4) {
  Image image;
  image.width = n;
  image.height = 1;
  image.rgb.assign(3 * n, value);
  return image;
}

TEST(Compare, ErrorMeasuresHaveTheirClosedForms) {
  Image a = flat(1.0), b = flat(1.0);
  EXPECT_EQ(mean_squared_error(a, b), 0.0);
  a.rgb[0] = 1.5;  // one of 12 values off by 0.5
  EXPECT_DOUBLE_EQ(mean_squared_error(a, b), 0.25 / 12);
  EXPECT_DOUBLE_EQ(relative_mean_squared_error(a, b), 0.25 / 1.01 / 12);
  EXPECT_THROW(mean_squared_error(a, flat(1.0, 5)), invalid_argument);
}

TEST(Compare, ConfigsAreParsedAndCheckedByName) {
  const auto configs = parse_configs(nlohmann::json::parse(R"([{"label": "a", "spp": 8, "light_samples": 3,
      "light_strategy": "solid-angle", "sampler": "sobol", "pixel_centers": true}])"),
                                     2, 5);
  ASSERT_EQ(configs.size(), 1u);
  EXPECT_EQ(configs[0].label, "a");
  EXPECT_EQ(configs[0].settings.sampler.spp, 8u);
  EXPECT_EQ(configs[0].settings.light_samples, 3u);
  EXPECT_TRUE(configs[0].settings.pixel_centers);
  EXPECT_EQ(configs[0].settings.threads, 2u);
  // "sampler" is a spec: its parameters and randomizer reach the pixel sampler's settings.
  const auto spec = parse_configs(nlohmann::json::parse(R"([{"sampler": "cmj(aspect=2):none"}])"), 1, 0);
  EXPECT_EQ(spec[0].settings.sampler.sampler, "cmj");
  EXPECT_EQ(spec[0].settings.sampler.params, (std::map<std::string, std::string>{{"aspect", "2"}}));
  EXPECT_EQ(spec[0].settings.sampler.randomize, "none");
  auto message = [](const char* text) {
    try {
      parse_configs(nlohmann::json::parse(text), 1, 0);
    } catch (const invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message(R"([{"colour": 1}])").find("configs[0].colour"), std::string::npos);
  EXPECT_NE(message(R"([{"spp": 0}])").find("configs[0].spp"), std::string::npos);
  EXPECT_NE(message(R"([{"integrator": "bdpt"}])").find("integrator"), std::string::npos);
  EXPECT_NE(message(R"([])").find("configs"), std::string::npos);
  EXPECT_NE(message(R"j([{"sampler": "cmj(aspect=-1)"}])j").find("invalid aspect = -1"), std::string::npos);
  EXPECT_THROW(builtin_comparison("nope", 1, 0), invalid_argument);
  for (const auto& [name, description] : builtin_comparisons())
    EXPECT_FALSE(builtin_comparison(name, 1, 0).empty()) << name;
}

Scene small_box() {
  Scene scene = cornell_box();
  scene.camera.width = scene.camera.height = 8;
  scene.camera.aperture_radius = 0;
  for (auto& shape : scene.shapes) shape.motion = {};
  return scene;
}

TEST(Compare, ReferencesAreCachedAndMoreShadowRaysLowerTheError) {
  const std::string cache = (std::filesystem::temp_directory_path() / "stratum-compare-test").string();
  std::filesystem::remove_all(cache);
  const Scene scene = small_box();
  const auto configs = builtin_comparison("shadow-rays", 1, 3);
  bool cached = true;
  const Image first = reference_image(scene, "small", configs[0].settings, 64, cache, &cached);
  EXPECT_FALSE(cached);
  const Image again = reference_image(scene, "small", configs[0].settings, 64, cache, &cached);
  EXPECT_TRUE(cached);
  ASSERT_EQ(first.rgb.size(), again.rgb.size());
  for (std::size_t i = 0; i < first.rgb.size(); ++i) EXPECT_FLOAT_EQ(float(first.rgb[i]), float(again.rgb[i]));
  // 16 shadow rays against 1 at the same eye rays: the shadow-ray variance
  // is ~16x smaller; the MSE ratio must be well above 1.
  const auto rows = compare(scene, "small", configs, 256, cache);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_GT(rows[1].mse_ratio, 4.0);
  EXPECT_DOUBLE_EQ(rows[0].mse_ratio, 1.0);
  EXPECT_GT(rows[1].seconds, 0.0);
  std::filesystem::remove_all(cache);
}

TEST(Compare, EqualTimeGivesEveryConfigurationTheBudgetAndCheapOnesMoreSamples) {
  const std::string cache = (std::filesystem::temp_directory_path() / "stratum-compare-equal-time").string();
  std::filesystem::remove_all(cache);
  Scene scene = small_box();
  scene.camera.width = scene.camera.height = 16;
  auto configs = builtin_comparison("shadow-rays", 1, 3);
  configs[1].settings.light_samples = 64;  // ~16x the cost of a pass of configs[0] (measured: 1.1 ms vs 18 ms)
  CompareOptions options;
  options.reference_spp = 16;
  options.cache_dir = cache;
  options.equal_time = 0.25;  // long enough that a descheduled quantum cannot undo a 16x cost ratio
  options.variance_dir = cache + "/variance";
  const auto rows = compare(scene, scene_fingerprint(scene), configs, options);
  ASSERT_EQ(rows.size(), 2u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    // Passes continue until the budget is spent: never less than it.
    EXPECT_GE(rows[i].seconds, options.equal_time);
    EXPECT_GE(rows[i].passes, 1u);
    EXPECT_EQ(rows[i].samples, rows[i].passes * configs[i].settings.sampler.spp);
    EXPECT_TRUE(std::filesystem::exists(rows[i].variance_path)) << rows[i].variance_path;
  }
  // The same wall time buys the cheap configuration more passes.
  EXPECT_GT(rows[0].samples, rows[1].samples);
  std::filesystem::remove_all(cache);
}

TEST(Compare, OneEqualTimePassIsTheEqualSampleRender) {
  const Scene scene = small_box();
  RenderSettings s = builtin_comparison("pixel-samplers", 1, 7)[1].settings;  // jittered
  s.sampler.spp = 4;
  std::uint32_t passes = 0;
  const Accelerator accelerator(scene);
  const Image once = render_equal_time(accelerator, s, 1e-9, &passes);
  const Image plain = render(scene, s);
  EXPECT_EQ(passes, 1u);
  EXPECT_EQ(once.samples, 4u);
  EXPECT_EQ(once.rgb, plain.rgb);
  EXPECT_EQ(once.variance, plain.variance);
  EXPECT_THROW(render_equal_time(accelerator, s, -1), invalid_argument);
  EXPECT_THROW(render_equal_time(accelerator, s, std::nan("")), invalid_argument);
}

/// Owen-scrambled Sobol' continues one sequence across equal-time passes:
/// the result is the render at the spp it reached (QMC keeps its rate).
TEST(Compare, EqualTimeContinuesAQmcSequence) {
  const Scene scene = small_box();
  RenderSettings s = builtin_comparison("pixel-samplers", 1, 7)[2].settings;  // sobol owen-hash
  s.sampler.spp = 4;
  s.light_samples = 2;
  std::uint32_t passes = 0;
  const Image timed = render_equal_time(Accelerator(scene), s, 0.02, &passes);
  ASSERT_LE(timed.samples, 4096u);  // one set (at 8x8 a pass takes well under a millisecond)
  EXPECT_EQ(timed.samples, 4 * passes);
  s.sampler.spp = timed.samples;
  const Image plain = render(scene, s);
  ASSERT_EQ(timed.rgb.size(), plain.rgb.size());
  for (std::size_t i = 0; i < plain.rgb.size(); ++i) {
    EXPECT_NEAR(timed.rgb[i], plain.rgb[i], 1e-12 * (1 + plain.rgb[i]));
    EXPECT_NEAR(timed.variance[i], plain.variance[i], 1e-12 * (1 + plain.variance[i]));
  }
}

/// A diffuse plane of albedo rho filling the view under a constant sky of
/// radiance 1: seen through any pixel, irradiance with uniform hemisphere
/// directions gives Y = rho/pi · cos θ / (1/2π) = 2 rho cos θ with cos θ
/// uniform on [0, 1): E[Y] = rho, V[Y] = rho²/3 (LECTURE.md §3), the same in
/// every pixel, and the camera never sees the sky.
Scene uniform_plane(double rho) {
  Scene scene;
  scene.camera.position = {0, 1, 0};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.up = {0, 0, 1};
  scene.camera.fov_degrees = 40;
  scene.camera.width = scene.camera.height = 8;
  scene.materials = {{"grey", MaterialType::diffuse, {rho, rho, rho}, {}}};
  Shape plane;
  plane.type = ShapeType::quad;
  plane.corner = {-100, 0, 100};
  plane.edge_u = {200, 0, 0};
  plane.edge_v = {0, 0, -200};
  scene.shapes.push_back(plane);
  scene.lights.push_back(Light{LightType::environment, 0, {}, {}, {1, 1, 1}});
  validate_scene(scene);
  return scene;
}

/// The variance image (variance of each pixel's mean, LECTURE.md §2:
/// V[mean of N] = V[Y]/N) against two oracles on the uniform plane, whose
/// P = 64 pixels are independent and identically distributed (random
/// sampler): (1) the sample variance of each pixel across R independent
/// renders (other seeds), by a paired t-test over pixels of
/// d_p = empirical_p − mean variance image_p; (2) the closed form
/// rho²/(3 N M) (N eye rays, M hemisphere rays each), by a t-test of the
/// pixels' mean variance image. Two tests, Šidák: α = 0.001 overall,
/// 1 − (1 − 0.001)^(1/2) each, two-sided. Power: test (1) must reject a
/// variance image that forgot the 1/N (the variance of one eye-ray sample).
TEST(Compare, VarianceImageMatchesIndependentRendersAndTheClosedForm) {
  constexpr double rho = 0.5;
  const Scene scene = uniform_plane(rho);
  RenderSettings s;
  s.integrator = "irradiance";
  s.hemisphere = "uniform";
  s.light_samples = 2;
  s.sampler.sampler = "random";
  s.sampler.spp = 4;
  constexpr int renders = 32, pixels = 64;
  std::vector<double> sum(pixels), sum2(pixels), mean_variance(pixels);
  for (int r = 0; r < renders; ++r) {
    s.sampler.seed = 1000 + r;
    const Image image = render(scene, s);
    for (int p = 0; p < pixels; ++p) {  // channel 0: the grey channels are equal
      sum[p] += image.rgb[3 * p];
      sum2[p] += image.rgb[3 * p] * image.rgb[3 * p];
      mean_variance[p] += image.variance[3 * p] / renders;
    }
  }
  auto t_statistic = [](const std::vector<double>& x, double mu) {
    double mean = 0, square = 0;
    for (double v : x) mean += v / double(x.size());
    for (double v : x) square += (v - mean) * (v - mean) / double(x.size() - 1);
    return (mean - mu) / std::sqrt(square / double(x.size()));
  };
  auto paired = [&](double scale) {
    std::vector<double> d(pixels);
    for (int p = 0; p < pixels; ++p) {
      const double m = sum[p] / renders;
      d[p] = (sum2[p] - renders * m * m) / (renders - 1) - scale * mean_variance[p];
    }
    return t_statistic(d, 0);
  };
  const double alpha = 1 - std::pow(1 - 0.001, 1.0 / 2);
  const double critical = boost::math::quantile(boost::math::students_t(pixels - 1), 1 - alpha / 2);
  EXPECT_LT(std::abs(paired(1.0)), critical);
  EXPECT_LT(std::abs(t_statistic(mean_variance, rho * rho / (3.0 * s.sampler.spp * s.light_samples))), critical);
  EXPECT_GT(std::abs(paired(double(s.sampler.spp))), critical);  // power: the variance of one sample, not of the mean
}

TEST(Compare, FingerprintsFollowTheSceneAndComparisonScenesAreChecked) {
  const Scene a = small_box();
  Scene b = a;
  EXPECT_EQ(scene_fingerprint(a), scene_fingerprint(b));
  b.camera.width = 9;
  EXPECT_NE(scene_fingerprint(a), scene_fingerprint(b));
  b = a;
  b.materials[0].reflectance = {0.5, 0.5, 0.51};
  EXPECT_NE(scene_fingerprint(a), scene_fingerprint(b));
  const auto moving = comparison_scene("", true, 8, 6), still = comparison_scene("", false, 8, 6);
  EXPECT_EQ(moving.scene.camera.width, 8);
  EXPECT_EQ(moving.scene.camera.height, 6);
  EXPECT_EQ(moving.scene.camera.aperture_radius, 0);
  EXPECT_NE(moving.key, still.key);
  EXPECT_THROW(comparison_scene("", false, 0, 6), invalid_argument);
  EXPECT_THROW(comparison_scene("/no/such/scene.json", false, 8, 6), invalid_argument);
  EXPECT_THROW(check_variance_path("variance", "v.png"), invalid_argument);
  CompareOptions bad;
  bad.equal_time = -1;
  EXPECT_THROW(compare(a, "a", builtin_comparison("shadow-rays", 1, 0), bad), invalid_argument);
}

}  // namespace
}  // namespace stratum::render
