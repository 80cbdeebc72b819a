/// §3 Importance sampling: Y = f(X)/p(X) with X ~ p is unbiased, and its
/// variance vanishes when p ∝ f. Shown five ways:
///  - the slide's example: the Cornell box's area light sampled by area, by
///    solid angle and by projected solid angle, 4 eye rays and 100 shadow
///    rays per pixel (render::builtin_comparison "light-strategy"; Ureña,
///    Fajardo, King 2013, "An area-preserving parametrization for spherical
///    rectangles");
///  - where they differ: the 300 × 300 mm light of §2 with 1 shadow ray,
///    whose walls see the light large and at grazing angles;
///  - irradiance E = ∫ L cos θ dω under a uniform sky (an environment
///    light) with uniform or cosine-weighted directions (builtin
///    "hemisphere"; Malley's method, p = cos θ/π), and the directions drawn;
///  - the zero-variance case: a white-ish floor under a constant sky, where
///    cosine sampling gives every sample the same value ρL (p ∝ L cos θ),
///    against uniform directions whose per-sample variance is ρ²L²/3;
///  - the analysis study (analysis::run_importance_study): area against
///    solid-angle sampling of a square light as its size and distance vary,
///    with predicted variances.
/// The renders are repeated over seeds, the configurations paired on each
/// (repeated_comparison.hpp): ratios come with intervals, and efficiency
/// ratios only where the times differ beyond their noise.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "render_support.hpp"
#include "repeated_comparison.hpp"
#include "sections.hpp"
#include "stratum/analysis/importance_study.hpp"
#include "stratum/registry.hpp"
#include "stratum/warp_registry.hpp"

namespace stratum::report {

namespace {

/// A diffuse floor of reflectance `albedo` seen from straight above under a
/// constant environment of radiance `sky`: every visible point sees the
/// whole, unoccluded sky.
render::Scene sky_floor_scene(int size, render::Vec3 albedo, double sky) {
  render::Scene scene;
  scene.name = "sky-floor";
  scene.camera.position = {0, 1, 0};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.up = {0, 0, 1};
  scene.camera.width = scene.camera.height = size;
  scene.materials = {{"floor", render::MaterialType::diffuse, albedo, {}}};
  render::Shape floor;
  floor.type = render::ShapeType::quad;
  floor.corner = {-10, 0, -10};
  floor.edge_u = {0, 0, 20};  // edge_u × edge_v = +y: the floor faces up
  floor.edge_v = {20, 0, 0};
  scene.shapes.push_back(floor);
  render::Light light;
  light.type = render::LightType::environment;
  light.radiance = {sky, sky, sky};
  scene.lights.push_back(light);
  render::validate_scene(scene);
  return scene;
}

/// Three spheres on a floor under a constant sky of radiance 1, seen from
/// above at a slant: the irradiance of the open floor is L·π everywhere,
/// the objects' occlusion darkens it near them.
render::ComparisonScene sky_objects_scene(int width, int height) {
  render::Scene scene;
  scene.name = "sky-spheres";
  scene.camera.position = {0, 4.5, -6.5};
  scene.camera.look_at = {0, 0.4, 0};
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_degrees = 40;
  scene.camera.width = width;
  scene.camera.height = height;
  scene.materials = {{"floor", render::MaterialType::diffuse, {0.75, 0.75, 0.75}, {}},
                     {"blue", render::MaterialType::diffuse, {0.25, 0.4, 0.8}, {}},
                     {"orange", render::MaterialType::diffuse, {0.85, 0.5, 0.2}, {}}};
  render::Shape floor;
  floor.type = render::ShapeType::quad;
  floor.corner = {-20, 0, -20};
  floor.edge_u = {0, 0, 40};  // edge_u × edge_v = +y: the floor faces up
  floor.edge_v = {40, 0, 0};
  scene.shapes.push_back(floor);
  const struct {
    render::Vec3 centre;
    double radius;
    std::size_t material;
  } balls[] = {{{-0.3, 1, 0.4}, 1, 1}, {{1.7, 0.55, -0.6}, 0.55, 2}, {{-2.0, 0.35, -1.0}, 0.35, 2}};
  for (const auto& b : balls) {
    render::Shape ball;
    ball.type = render::ShapeType::sphere;
    ball.center = b.centre;
    ball.radius = b.radius;
    ball.material = b.material;
    scene.shapes.push_back(ball);
  }
  render::Light light;
  light.type = render::LightType::environment;
  light.radiance = {1, 1, 1};
  scene.lights.push_back(light);
  render::validate_scene(scene);
  return {scene, render::scene_fingerprint(scene), ""};
}

double image_mean(const render::Image& image) {
  double sum = 0;
  for (const double v : image.rgb) sum += v;
  return sum / double(image.rgb.size());
}

nlohmann::json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json method_json(const analysis::MethodResult& m) {
  return {{"method", m.method},
          {"estimate", m.estimate},
          {"variance", m.variance},
          {"variance_stderr", number_or_null(m.variance_stderr)},
          {"predicted_variance", number_or_null(m.predicted_variance)},
          {"seconds_per_sample", m.seconds_per_sample},
          {"efficiency", number_or_null(m.efficiency)}};
}

nlohmann::json comparisons_json(const std::vector<analysis::ImportanceComparison>& list) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& c : list)
    rows.push_back({{"scene", c.scene},
                    {"size", c.size},
                    {"distance", c.distance},
                    {"exact", c.exact},
                    {"a", method_json(c.a)},
                    {"b", method_json(c.b)},
                    {"variance_ratio", number_or_null(c.variance_ratio)},
                    {"variance_ratio_stderr", number_or_null(c.variance_ratio_stderr)},
                    {"predicted_variance_ratio", number_or_null(c.predicted_variance_ratio)},
                    {"time_ratio", number_or_null(c.time_ratio)},
                    {"efficiency_ratio", number_or_null(c.efficiency_ratio)}});
  return rows;
}

/// A repeated comparison with its statistics (against the first configuration).
struct Measured {
  RepeatedComparison run;
  std::vector<RowStatistics> rows;
};

Measured measure(const render::ComparisonScene& scene, const std::vector<render::CompareConfig>& configs,
                 std::uint32_t reference_spp, const std::string& cache_dir, unsigned repeats) {
  render::CompareOptions options;
  options.reference_spp = reference_spp;
  options.cache_dir = cache_dir;
  Measured result{run_repeated_comparison(scene, configs, options, repeats), {}};
  result.rows = row_statistics(result.run, result.run.mse);
  return result;
}

/// "its MSE is 3.1× (95% CI 2.9–3.3) smaller" and the time clause of row `c`.
std::string mse_and_time(const Measured& m, std::size_t c) {
  return fmt::format("its MSE is {} smaller, and it {}", format_factor(m.rows.at(c).mse_ratio),
                     time_and_efficiency_text(m.rows.at(c), m.run.labels.at(0) + " sampling"));
}

}  // namespace

Section importance_section(SectionContext& context) {
  Section section = context.start();
  const RenderScale scale = picture_scale(context);
  const auto box = render::comparison_scene("", false, scale.width, scale.height);

  // The slide's example: the box's light sampled by area and by projected
  // solid angle (p ∝ cos θ dω), 4 eye rays × 100 shadow rays, with solid
  // angle between them.
  auto light_configs = render::builtin_comparison("light-strategy", context.threads(), context.seed());
  render::CompareConfig projected = light_configs.back();
  projected.label = "projected solid angle";
  projected.settings.light_strategy = "projected-solid-angle";
  light_configs.push_back(projected);
  // Seeds: the slide's renders (400 light samples per pixel) cost most.
  const unsigned light_repeats = context.quick() ? 3 : 3, repeats = context.quick() ? 3 : 6;
  const Measured light = measure(box, light_configs, scale.reference_spp, context.cache_dir(), light_repeats);
  section.figures.push_back(image_figure(
      context, repeated_grid(light.run, {}), "light-strategy",
      fmt::format("As on the slide: direct lighting, {}×{} pixels, {} eye rays × {} shadow rays per pixel, the light "
                  "sampled by area, by solid angle and by projected solid angle (first seed); below, each render's "
                  "error on one colour scale",
                  scale.width, scale.height, light.run.samples.front().front(),
                  light_configs.front().settings.light_samples),
      4));
  section.tables.push_back(repeated_table(
      light.run, light.rows,
      fmt::format("Area, solid-angle and projected-solid-angle light sampling against a {}-spp reference ({})",
                  light.run.reference_spp, interval_method(light_repeats))));
  section.numbers["light_strategy"] = repeated_numbers(light.run, light.rows);

  // Where they differ: the 300 × 300 mm light (the soft-shadow scene of §2),
  // 1 shadow ray per eye ray, so that each render shows its own estimator's
  // noise; the walls just under the light see it large and at grazing angles.
  const auto large = large_light_box(scale.width, scale.height);
  std::vector<render::CompareConfig> few;
  for (const auto& config : light_configs) {
    if (config.label == "solid angle") continue;
    render::CompareConfig one = config;
    one.settings.light_samples = 1;
    few.push_back(one);
  }
  const Measured close = measure(large, few, scale.few_samples_reference_spp, context.cache_dir(), repeats);
  const Crop upper_wall{0.0, 0.06, 0.3, 0.3, "wall under the light"};
  section.figures.push_back(image_figure(
      context, repeated_grid(close.run, {upper_wall}), "light-strategy-large",
      fmt::format("Where they differ: the 300 × 300 mm light of §2, {} eye rays × 1 shadow ray per pixel, area and "
                  "projected-solid-angle sampling (first seed); the red wall just under the light enlarged, and each "
                  "render's error",
                  close.run.samples.front().front()),
      3));
  section.tables.push_back(
      repeated_table(close.run, close.rows,
                     fmt::format("The large light, 1 shadow ray per eye ray, against a {}-spp reference ({})",
                                 close.run.reference_spp, interval_method(repeats))));
  section.numbers["light_strategy_large"] = repeated_numbers(close.run, close.rows);
  // The wall under the light: each seed's MSE over the crop.
  std::vector<RowStatistics> wall_rows;
  {
    const PixelBox wall = crop_pixels(upper_wall, scale.width, scale.height);
    const std::vector<bool> mask = box_mask(wall, scale.width, scale.height);
    std::vector<std::vector<double>> wall_mse(few.size());
    for (const auto& images : close.run.images)
      for (std::size_t c = 0; c < images.size(); ++c)
        wall_mse[c].push_back(masked_mean_squared_error(images[c], close.run.reference, mask));
    wall_rows = row_statistics(close.run, wall_mse);
    for (std::size_t c = 0; c < few.size(); ++c)
      section.numbers["light_strategy_large"]["wall"][close.run.labels[c]] = {
          {"mse_per_seed", wall_mse[c]},
          {"mse_mean", wall_rows[c].mse.mean},
          {"mse_ratio", interval_json(wall_rows[c].mse_ratio)},
          {"sample_variance", region_error(close.run.images[0][c], close.run.reference, wall).sample_variance}};
    section.numbers["light_strategy_large"]["wall"]["box"] = {wall.x, wall.y, wall.width, wall.height};
  }

  // Irradiance under a sky: cosine-weighted directions follow the cosine of
  // the integrand, and only the objects' occlusion is left to vary.
  const auto sky_scene = sky_objects_scene(scale.width, scale.height);
  const auto hemisphere_configs = render::builtin_comparison("hemisphere", context.threads(), context.seed());
  std::vector<render::CompareConfig> sky_configs;
  for (render::CompareConfig config : hemisphere_configs) {
    config.settings.light_samples = 4;
    sky_configs.push_back(config);
  }
  const Measured hemisphere =
      measure(sky_scene, sky_configs, scale.few_samples_reference_spp, context.cache_dir(), repeats);
  section.figures.push_back(image_figure(
      context, repeated_grid(hemisphere.run, {}), "hemisphere",
      fmt::format("Irradiance under a uniform sky (an environment light of radiance 1), {}×{} pixels, {} eye rays × "
                  "{} directions per pixel: uniform and cosine-weighted hemisphere directions (first seed), and each "
                  "render's error",
                  scale.width, scale.height, hemisphere.run.samples.front().front(),
                  sky_configs.front().settings.light_samples),
      3));
  section.tables.push_back(
      repeated_table(hemisphere.run, hemisphere.rows,
                     fmt::format("Uniform vs cosine-weighted irradiance under the sky against a {}-spp reference ({})",
                                 hemisphere.run.reference_spp, interval_method(repeats))));
  section.numbers["hemisphere"] = repeated_numbers(hemisphere.run, hemisphere.rows);

  // The directions themselves: a jittered 16×16 grid through each warp.
  {
    SamplerRequest request;
    const std::size_t n = 256;
    request.n = n;
    request.d = 2;
    request.seed = context.seed();
    const PointSet grid = generate_points("jittered", request);
    nlohmann::json panels = nlohmann::json::array();
    for (const auto& [name, label] :
         {std::pair{"hemisphere-uniform", "uniform"}, std::pair{"hemisphere-cosine", "cosine-weighted"}}) {
      const auto warp = make_warp(name, WarpParams{});
      const auto d = warp_sample(*warp, grid.data.get(), n);
      std::vector<double> x(n), y(n), z(n);
      double mean_cos = 0;
      for (std::size_t k = 0; k < n; ++k)
        x[k] = d[3 * k], y[k] = d[3 * k + 1], z[k] = d[3 * k + 2], mean_cos += z[k] / n;
      panels.push_back({{"title", fmt::format("{}, seen from above", label)}, {"x", x}, {"y", y}, {"disk", true}});
      panels.push_back(
          {{"title", fmt::format("{}, from the side", label)}, {"x", x}, {"y", z}, {"disk", true}, {"side", true}});
      section.numbers["directions"][label] = {{"mean_cos_theta", mean_cos}};
    }
    section.figures.push_back(context.plot(
        "report_points", {{"columns", 4}, {"size", 2.6}, {"panels", panels}}, "directions",
        "256 directions from a jittered grid: uniform on the hemisphere (seen from above they crowd towards the "
        "horizon) and cosine-weighted (seen from above they are uniform over the disk: Malley's method lifts a "
        "uniform disk point to the hemisphere), and the same from the side"));
  }

  // The zero-variance case: one direction per eye ray, so that each pixel's
  // variance is that of single samples.
  const render::Vec3 albedo{0.8, 0.6, 0.4};
  const double sky = 1;
  const int floor_size = context.quick() ? 16 : 64;
  const render::Scene floor_scene = sky_floor_scene(floor_size, albedo, sky);
  nlohmann::json floor_panels = nlohmann::json::array();
  Table floor_table{"A floor (reflectance ρ = (0.8, 0.6, 0.4)) under a constant sky L = 1, one direction per eye ray",
                    {"directions", "samples", "mean pixel value", "per-sample variance (measured)",
                     "per-sample variance (closed form)", "largest pixel variance"},
                    {}};
  const double rho_squared = (albedo.x * albedo.x + albedo.y * albedo.y + albedo.z * albedo.z) / 3;
  for (const std::string strategy : {"uniform", "cosine"}) {
    render::RenderSettings settings;
    settings.integrator = "irradiance";
    settings.hemisphere = strategy;
    settings.light_samples = 1;
    settings.sampler.sampler = "random";
    settings.sampler.spp = context.quick() ? 16 : 64;
    settings.sampler.seed = context.seed();
    settings.threads = context.threads();
    const render::Image image = render::render(floor_scene, settings);
    const double variance = mean_sample_variance(image);
    const double largest = *std::max_element(image.variance.begin(), image.variance.end()) * image.samples;
    // Uniform: Y = 2ρL cos θ with cos θ ~ U(0, 1), variance ρ²L²/3; cosine: Y = ρL.
    const double predicted = strategy == "uniform" ? rho_squared * sky * sky / 3 : 0;
    const std::uint64_t samples = std::uint64_t(image.width) * image.height * image.samples;
    floor_table.rows.push_back({strategy, std::to_string(samples), format_number(image_mean(image), 4),
                                format_number(variance), format_number(predicted), format_number(largest)});
    section.numbers["zero_variance"][strategy] = {{"samples", samples},
                                                  {"mean", image_mean(image)},
                                                  {"sample_variance", variance},
                                                  {"predicted_variance", predicted},
                                                  {"largest_pixel_variance", largest}};
    floor_panels.push_back(
        image_panel(image, fmt::format("{} directions\nvariance {}", strategy, format_number(variance))));
  }
  section.numbers["zero_variance"]["expected_mean"] = (albedo.x + albedo.y + albedo.z) / 3 * sky;
  section.figures.push_back(image_figure(
      context, floor_panels, "zero-variance",
      "The floor under a constant sky, one hemisphere direction per eye ray: uniform directions (noisy) and "
      "cosine-weighted ones (p ∝ cos θ ∝ the integrand)",
      2));
  section.tables.push_back(std::move(floor_table));

  // The analysis study: one receiver, a square light of several sizes.
  analysis::ImportanceStudyRequest request;
  request.runs = context.quick() ? 4 : 16;
  request.samples = context.quick() ? 512 : 4096;
  request.sizes = context.quick() ? std::vector<double>{0.25, 1, 4} : std::vector<double>{0.125, 0.25, 0.5, 1, 2, 4, 8};
  request.distances = context.quick() ? std::vector<double>{1} : std::vector<double>{0.5, 2};
  request.seed = context.seed();
  request.threads = context.threads();
  const analysis::ImportanceStudy study = analysis::run_importance_study(request);
  const nlohmann::json study_data = {{"runs", study.runs},
                                     {"samples", study.samples},
                                     {"hemisphere", comparisons_json(study.hemisphere)},
                                     {"light", comparisons_json(study.light)}};
  section.figures.push_back(context.plot(
      "importance", study_data, "study",
      fmt::format("Irradiance from a square light above a receiver, {} runs × {} samples: variance and efficiency of "
                  "solid-angle against area sampling as the light's size over its distance grows",
                  study.runs, study.samples)));
  section.numbers["study"] = study_data;

  const RowStatistics& solid = light.rows.at(1);
  // The study's variance ratio (area / solid angle) at its smallest and largest light size over distance.
  const analysis::ImportanceComparison* smallest = nullptr;
  const analysis::ImportanceComparison* largest = nullptr;
  for (const auto& c : study.light) {
    if (!smallest || c.size / c.distance < smallest->size / smallest->distance) smallest = &c;
    if (!largest || c.size / c.distance > largest->size / largest->distance) largest = &c;
  }
  double lowest_ratio = std::numeric_limits<double>::infinity();
  for (const auto& c : study.light) lowest_ratio = std::min(lowest_ratio, c.variance_ratio);
  section.numbers["study_lowest_variance_ratio"] = lowest_ratio;
  const auto& zero = section.numbers["zero_variance"];
  section.text.push_back(fmt::format(
      "Drawing X from p and averaging f(X)/p(X) is unbiased for any p > 0 where f ≠ 0; the variance depends on how "
      "well p follows f. With {} eye rays and {} shadow rays per pixel, over {} seeds, the MSE of area sampling of "
      "the light is {} that of solid-angle sampling, and solid angle {}.",
      light.run.samples.front().front(), light_configs.front().settings.light_samples, light_repeats,
      format_factor(solid.mse_ratio), time_and_efficiency_text(solid, "area sampling")));
  const RowStatistics& large_projected = close.rows.at(1);
  section.text.push_back(fmt::format(
      "The slide's comparison is with projected solid angle (p ∝ cos θ dω, which also follows the cosine at the "
      "receiver): with {} shadow rays {}; and the two pictures look alike: with 400 light samples per pixel both "
      "have converged far enough that their difference hides under the noise that remains.",
      light_configs.front().settings.light_samples, mse_and_time(light, 2)));
  section.text.push_back(fmt::format(
      "Why the box's gain is so much smaller than the study's below: the study measures one unoccluded square "
      "light centred above the receiver, where all that varies over the light is the geometric factor "
      "cos θ cos θ_light / r²; solid-angle sampling cancels all of it but cos θ, and the variance ratio (area / "
      "solid angle) is {} at size/distance {} and {} at {} (at small sizes both variances are tiny beside E², but "
      "their ratio stays large). In the box much of the error is visibility: in a penumbra, or on a face that sees "
      "part of the light below its horizon (the top of the tall block's front face), whether a shadow ray reaches "
      "the light varies whichever way the point on the light is drawn. That shared error is what the heat maps "
      "show left under both solid-angle strategies, and it is why the box's ratio is {} where the study's is at "
      "least {}.",
      format_number(smallest->variance_ratio), format_number(smallest->size / smallest->distance),
      format_number(largest->variance_ratio), format_number(largest->size / largest->distance),
      format_interval(solid.mse_ratio), format_number(lowest_ratio)));
  section.text.push_back(fmt::format(
      "Grow the light to 300 × 300 mm and take 1 shadow ray per eye ray, and the walls just under it see the light "
      "large, close and at grazing angles, where the geometric factor varies most: there area sampling's MSE is "
      "{} that of projected solid angle ({} over the whole image, {} seeds), the study's large-light end seen in "
      "the box.",
      format_factor(wall_rows.at(1).mse_ratio), format_factor(large_projected.mse_ratio), repeats));
  section.text.push_back(fmt::format(
      "Irradiance E = ∫ L cos θ dω under a uniform sky: cosine-weighted directions (p = cos θ/π) cancel the cosine, "
      "so on the open floor every sample gives the same value and only the spheres' occlusion is left to vary. "
      "The MSE with uniform directions is {} that with cosine-weighted ones, and cosine-weighted sampling {}.",
      format_factor(hemisphere.rows.at(1).mse_ratio), time_and_efficiency_text(hemisphere.rows.at(1), "uniform")));
  section.text.push_back(fmt::format(
      "Under a constant sky the integrand L ρ/π cos θ is proportional to the cosine density, so in exact arithmetic "
      "every cosine-weighted sample equals ρL: over {} samples the measured per-sample variance is {} with "
      "cosine-weighted directions (the largest of any "
      "pixel {}) against {} with uniform ones (closed form ρ²L²/3 = {}); the mean pixel values are {} and {} "
      "(exact {}).",
      zero["cosine"]["samples"].get<std::uint64_t>(), format_number(zero["cosine"]["sample_variance"]),
      format_number(zero["cosine"]["largest_pixel_variance"]), format_number(zero["uniform"]["sample_variance"]),
      format_number(zero["uniform"]["predicted_variance"]), format_number(zero["cosine"]["mean"], 4),
      format_number(zero["uniform"]["mean"], 4), format_number(zero["expected_mean"], 4)));
  section.text.push_back(fmt::format(
      "Intervals: {}{}.", interval_method(repeats),
      light_repeats == repeats
          ? std::string()
          : fmt::format(" ({} seeds for the slide's renders of 400 light samples per pixel)", light_repeats)));
  section.try_it = {"stratum compare --builtin light-strategy --width 64 --height 64",
                    "stratum compare --builtin hemisphere --width 64 --height 64",
                    "stratum study importance --plot importance.png"};
  return section;
}

}  // namespace stratum::report
