/// §8 Space-time patterns: samples complete in space but incomplete in time,
/// the 16 time slots of a pixel assigned to its 4×4 spatial strata by Cook's
/// pattern (Cook 1986, "Stochastic sampling in computer graphics") or by a
/// pan-diagonal magic square (every row, column and broken diagonal has the
/// same sum, so every line of strata has the same mean time; Rosser, Walker
/// 1939, "The algebraic theory of diabolic magic squares"). The tables come
/// from include/stratum/spacetime; the line sums are measured from them.
/// Then the motion-blurred Cornell box rendered with random, Cook and
/// magic-square time assignments (render::builtin_comparison("time-pattern")).
#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>

#include "render_support.hpp"
#include "repeated_comparison.hpp"
#include "sections.hpp"
#include "space_time_frames.hpp"
#include "stratum/spacetime/cook_pattern.hpp"
#include "stratum/spacetime/magic_square.hpp"

namespace stratum::report {

namespace {

/// The sums of a table's rows, columns, broken diagonals (cells (r, r + k))
/// and broken antidiagonals (cells (r, k − r)), indices mod m.
struct LineSums {
  std::vector<std::uint64_t> rows, columns, diagonals, antidiagonals;
};

LineSums line_sums(const SlotTable& table) {
  const std::uint32_t m = table.order;
  LineSums sums{std::vector<std::uint64_t>(m), std::vector<std::uint64_t>(m), std::vector<std::uint64_t>(m),
                std::vector<std::uint64_t>(m)};
  for (std::uint32_t k = 0; k < m; ++k)
    for (std::uint32_t r = 0; r < m; ++r) {
      sums.rows[k] += table(k, r);
      sums.columns[k] += table(r, k);
      sums.diagonals[k] += table(r, (r + k) % m);
      sums.antidiagonals[k] += table(r, (k + m - r) % m);
    }
  return sums;
}

/// The smallest slot difference between strata sharing an edge (within the
/// pixel): how far apart in time Cook's rule puts spatial neighbours.
std::uint32_t neighbour_separation(const SlotTable& table) {
  const std::uint32_t m = table.order;
  std::uint32_t smallest = table.size();
  for (std::uint32_t r = 0; r < m; ++r)
    for (std::uint32_t c = 0; c < m; ++c) {
      const auto gap = [&](std::uint32_t a, std::uint32_t b) {
        return std::uint32_t(std::abs(std::int64_t(a) - std::int64_t(b)));
      };
      if (c + 1 < m) smallest = std::min(smallest, gap(table(r, c), table(r, c + 1)));
      if (r + 1 < m) smallest = std::min(smallest, gap(table(r, c), table(r + 1, c)));
    }
  return smallest;
}

std::string join(const std::vector<std::uint64_t>& values) {
  std::string text;
  for (const auto v : values) text += (text.empty() ? "" : ", ") + std::to_string(v);
  return text;
}

bool all_equal(const std::vector<std::uint64_t>& values, std::uint64_t target) {
  return std::all_of(values.begin(), values.end(), [&](std::uint64_t v) { return v == target; });
}

/// The mean square of an error image after a 1-pixel Gaussian blur (the
/// binomial filter [1 4 6 4 1] / 16 per axis, σ = 1 pixel; edges clamped):
/// what a viewer, or a denoiser, sees of the error.
double blurred_mse(const std::vector<double>& e, int width, int height) {
  constexpr double w[5] = {1.0 / 16, 4.0 / 16, 6.0 / 16, 4.0 / 16, 1.0 / 16};
  const auto at = [](int v, int n) { return std::clamp(v, 0, n - 1); };
  std::vector<double> rows(e.size(), 0.0), both(e.size(), 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int k = -2; k <= 2; ++k)
        rows[std::size_t(y) * width + x] += w[k + 2] * e[std::size_t(y) * width + at(x + k, width)];
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double v = 0;
      for (int k = -2; k <= 2; ++k) v += w[k + 2] * rows[std::size_t(at(y + k, height)) * width + x];
      sum += v * v;
    }
  return sum / double(e.size());
}

/// The slide's spatial demand across pixels, as today's renderers meet it
/// (Ahmed & Wonka 2020, pbrt-v4's ZSobolSampler): per-pixel decorrelated
/// Owen-scrambled Sobol' against ZSobol on the penumbra scene (error over the
/// whole image), their error images and the radial power spectra of the errors.
void screen_space_error(SectionContext& context, Section& section) {
  const int side = context.quick() ? 64 : 96;  // the full report's render size (render_scale)
  render::Scene scene = render::penumbra_scene();
  scene.camera.width = scene.camera.height = side;
  const render::ComparisonScene penumbra{scene, render::scene_fingerprint(scene), ""};
  std::vector<render::CompareConfig> configs;
  for (std::uint32_t spp : {1u, 4u, 16u})
    for (const char* sampler : {"sobol", "zsobol", "sobol-bn"}) {
      render::CompareConfig config;
      const std::string name = sampler;
      config.label = fmt::format("{}, {} spp",
                                 name == "sobol"    ? "per-pixel Owen–Sobol'"
                                 : name == "zsobol" ? "ZSobol"
                                                    : "sobol-bn",
                                 spp);
      config.settings.sampler.sampler = sampler;
      config.settings.sampler.spp = spp;
      config.settings.sampler.seed = context.seed();
      config.settings.light_samples = 1;
      config.settings.threads = context.threads();
      configs.push_back(config);
    }
  const RenderedComparison comparison =
      run_comparison(penumbra, configs, context.quick() ? 256 : 1024, context.cache_dir());

  nlohmann::json panels = nlohmann::json::array(), series = nlohmann::json::array();
  Table table{
      "Where the error goes: power of the error below a quarter of Nyquist (white noise = 1), and the MSE "
      "a viewer sees (after a 1-pixel Gaussian blur)",
      {"sampler", "spp", "MSE", "low-frequency power", "MSE after blur"},
      {}};
  for (std::size_t i = 0; i < comparison.rows.size(); ++i) {
    const render::CompareRow& row = comparison.rows[i];
    // The signed luminance error as grey: 0.5 ± error (clamped when drawn).
    render::Image error = comparison.images[i];
    const std::vector<double> e = render::luminance_error(comparison.images[i], comparison.reference);
    for (std::size_t p = 0; p < e.size(); ++p)
      for (int c = 0; c < 3; ++c) error.rgb[3 * p + c] = 0.5 + e[p];
    panels.push_back(image_panel(error, fmt::format("{} (MSE {})", row.label, format_number(row.mse))));
    series.push_back({{"label", row.label}, {"x", row.error_radial_frequency}, {"y", row.error_radial_power}});
    const double blurred = blurred_mse(e, side, side);
    table.rows.push_back({row.label, std::to_string(row.samples), format_number(row.mse),
                          format_number(row.low_frequency_power), format_number(blurred)});
    section.numbers["screen_space_error"]["rows"][row.label] = {{"spp", row.samples},
                                                                {"mse", row.mse},
                                                                {"low_frequency_power", row.low_frequency_power},
                                                                {"blurred_mse", blurred}};
  }
  section.numbers["screen_space_error"]["width"] = side;
  section.numbers["screen_space_error"]["reference_spp"] = comparison.reference_spp;
  const auto& front = comparison.rows.front().error_radial_frequency;
  series.push_back(
      {{"label", "white noise"}, {"x", {front.front(), front.back()}}, {"y", {1.0, 1.0}}, {"reference", true}});
  section.figures.push_back(image_figure(
      context, panels, "screen-space-error",
      fmt::format("The error (render − reference, luminance; grey is zero) of a floor in soft shadow, {0}×{0} pixels, "
                  "at 1, 4 and 16 samples per pixel: per-pixel decorrelated Owen-scrambled Sobol' against ZSobol's "
                  "Morton-ordered, digit-permuted sequence over the whole image and sobol-bn's optimized ranks",
                  side),
      3));
  section.figures.push_back(context.plot(
      "report_lines",
      {{"panels",
        {{{"title", "Radial power spectrum of the error"},
          {"xlabel", "frequency (cycles per pixel)"},
          {"ylabel", "power (white noise = 1)"},
          {"xlog", false},
          {"ylog", true},
          {"series", series}}}}},
      "error-spectra",
      "The errors' power by frequency, normalized so that white noise is 1: ZSobol and sobol-bn move the error's power "
      "out of the low frequencies a viewer (or a denoiser) sees, into the high ones"));
  section.tables.push_back(std::move(table));
  const auto& rows = comparison.rows;
  section.text.push_back(fmt::format(
      "The slide asks samples in space to have a blue-noise spectrum. The assignments above do it inside a pixel; "
      "today's renderers do it across pixels, so that the error itself is blue noise on the screen. On a floor in "
      "soft shadow, at 1 sample per pixel, the error of per-pixel decorrelated Owen–Sobol' has low-frequency power "
      "{} (white), ZSobol's {} and sobol-bn's {}, at MSE {}, {} and {}; at 4 samples per pixel {}, {} and {}; at 16 "
      "{}, {} and {}. The same error, moved to the frequencies the eye and a denoiser filter out: after a 1-pixel "
      "blur the MSE at 1 spp is {}, {} and {}. A pixel's neighbours in ZSobol's Morton order take the next blocks of "
      "one sequence, so a 2×2 block of pixels holds one stratified set — nearby in space, far apart in the "
      "sequence, the spatial form of Cook's rule; sobol-bn starts from that order and swaps the blocks within each "
      "2×2 block where an optimizer finds the blurred error of test integrands smaller (docs/blue-noise.md).",
      format_number(rows[0].low_frequency_power), format_number(rows[1].low_frequency_power),
      format_number(rows[2].low_frequency_power), format_number(rows[0].mse), format_number(rows[1].mse),
      format_number(rows[2].mse), format_number(rows[3].low_frequency_power),
      format_number(rows[4].low_frequency_power), format_number(rows[5].low_frequency_power),
      format_number(rows[6].low_frequency_power), format_number(rows[7].low_frequency_power),
      format_number(rows[8].low_frequency_power),
      format_number(section.numbers["screen_space_error"]["rows"][rows[0].label]["blurred_mse"].get<double>()),
      format_number(section.numbers["screen_space_error"]["rows"][rows[1].label]["blurred_mse"].get<double>()),
      format_number(section.numbers["screen_space_error"]["rows"][rows[2].label]["blurred_mse"].get<double>())));
}

/// The field of view of the close-up of the moving sphere.
constexpr double close_up_fov = 14;

/// The Cornell box seen through a narrow lens aimed at the moving sphere
/// (centre x 420 → 370 mm while the shutter is open, radius 70), so that the
/// sphere, its motion and its shadow fill the frame.
render::ComparisonScene close_up(const RenderScale& scale) {
  render::ComparisonScene result = render::comparison_scene("", true, scale.width, scale.height);
  result.scene.camera.look_at = {395, 70, 130};
  result.scene.camera.fov_degrees = close_up_fov;
  result.scene.name += "-close-up";
  result.key = render::scene_fingerprint(result.scene);
  return result;
}

/// A time-assignment comparison over seeds and the pixels where time matters.
struct TimeAssignments {
  RepeatedComparison comparison;
  std::vector<bool> moving;  ///< per pixel: its value depends on the assignment
  std::size_t pixels = 0, moving_count = 0;
  std::vector<std::vector<double>> region_mse;  ///< [configuration][seed], over `moving`
  std::vector<RowStatistics> whole, local;
};

TimeAssignments measure_time_assignments(const render::ComparisonScene& scene,
                                         const std::vector<render::CompareConfig>& configs,
                                         const render::CompareOptions& options, unsigned repeats) {
  TimeAssignments result;
  result.comparison = run_repeated_comparison(scene, configs, options, repeats);
  const RepeatedComparison& comparison = result.comparison;
  // The pixels whose value depends on the time assignment: where the renders
  // of a seed differ (the assignments change only the samples' times, so
  // elsewhere the images agree and the error is common to all), in any seed.
  result.pixels = std::size_t(comparison.reference.width) * std::size_t(comparison.reference.height);
  result.moving.assign(result.pixels, false);
  for (const auto& images : comparison.images)
    for (std::size_t p = 0; p < result.pixels; ++p)
      for (std::size_t i = 1; i < images.size() && !result.moving[p]; ++i)
        for (int c = 0; c < 3; ++c)
          result.moving[p] = result.moving[p] || images[i].rgb[3 * p + c] != images[0].rgb[3 * p + c];
  result.moving_count = std::size_t(std::count(result.moving.begin(), result.moving.end(), true));
  result.region_mse.resize(configs.size());
  for (const auto& images : comparison.images)
    for (std::size_t i = 0; i < images.size(); ++i)
      result.region_mse[i].push_back(masked_mean_squared_error(images[i], comparison.reference, result.moving));
  result.whole = row_statistics(comparison, comparison.mse);
  result.local = row_statistics(comparison, result.region_mse);
  return result;
}

/// The reference, the first seed's renders and the mask of time-dependent pixels.
nlohmann::json time_assignment_panels(const TimeAssignments& run, const std::vector<render::CompareConfig>& configs) {
  const RepeatedComparison& comparison = run.comparison;
  nlohmann::json panels = nlohmann::json::array();
  panels.push_back(image_panel(comparison.reference, fmt::format("reference ({} spp)", comparison.reference_spp)));
  for (std::size_t i = 0; i < configs.size(); ++i)
    panels.push_back(image_panel(comparison.images[0][i],
                                 fmt::format("{}\nMSE {}", configs[i].label, format_number(comparison.mse[i][0]))));
  nlohmann::json mask = image_panel(comparison.reference, "pixels that depend on time");
  for (std::size_t p = 0; p < run.pixels; ++p)
    for (int c = 0; c < 3; ++c) mask["rgb"][3 * p + c] = run.moving[p] ? 1.0 : 0.0;
  panels.push_back(mask);
  return panels;
}

nlohmann::json time_assignment_numbers(const TimeAssignments& run, const std::vector<render::CompareConfig>& configs) {
  const RepeatedComparison& comparison = run.comparison;
  nlohmann::json numbers = repeated_numbers(comparison, run.whole);
  numbers["time_dependent_pixels"] = run.moving_count;
  numbers["pixels"] = run.pixels;
  for (std::size_t i = 0; i < configs.size(); ++i) {
    auto& row = numbers["rows"][configs[i].label];
    row["time_dependent_mse_per_seed"] = run.region_mse[i];
    row["time_dependent_mse_mean"] = run.local[i].mse.mean;
    row["time_dependent_mse_standard_error"] = run.local[i].mse.standard_error;
    row["time_dependent_mse_ratio"] = interval_json(run.local[i].mse_ratio);
  }
  return numbers;
}

/// The close-up drawn at the pictures' size (256×256 in the full report),
/// first seed: the reference and the three assignments, the window where
/// they disagree most outlined and enlarged, and each render's error as a
/// heat map. Returns its numbers.
nlohmann::json motion_picture(SectionContext& context, Section& section,
                              const std::vector<render::CompareConfig>& configs) {
  const RenderScale scale = picture_scale(context);
  const RenderedComparison run = run_comparison(close_up(scale), configs, scale.reference_spp, context.cache_dir());
  const std::size_t pixels = std::size_t(scale.width) * scale.height;
  // Where the assignments disagree most: where the sphere and its shadow
  // move (there a sample's time decides what it sees).
  std::vector<double> disagreement(pixels, 0.0);
  for (std::size_t i = 1; i < run.images.size(); ++i) {
    const std::vector<double> difference = absolute_difference(run.images[i], run.images[0]);
    for (std::size_t p = 0; p < pixels; ++p) disagreement[p] += difference[p];
  }
  const Crop edge = heaviest_window(disagreement, scale.width, scale.height, 0.25, "where they differ most");
  section.figures.push_back(image_figure(
      context, comparison_grid(run, {edge}), "motion-picture",
      fmt::format(
          "The close-up of the moving sphere at {}×{} pixels, {} samples per pixel (first seed): the "
          "reference, random time, Cook's pattern and the magic square; below, the window where the assignments "
          "disagree most, enlarged, and each render's error",
          scale.width, scale.height, configs.front().settings.sampler.spp),
      4));
  std::string mse_text;
  for (std::size_t i = 0; i < run.rows.size(); ++i)
    mse_text += (i == 0                     ? ""
                 : i + 1 == run.rows.size() ? " and "
                                            : ", ") +
                fmt::format("{} for {}", format_number(run.rows[i].mse), configs[i].label);
  section.text.push_back(fmt::format(
      "Drawn at {}×{} pixels (first seed), the close-up's MSE is {}: the three renders differ only where the "
      "sphere and its shadow move (most in the window outlined), and the tables measure them there over the seeds.",
      scale.width, scale.height, mse_text));
  nlohmann::json numbers = comparison_numbers(run);
  const PixelBox box = crop_pixels(edge, scale.width, scale.height);
  numbers["crop"] = {box.x, box.y, box.width, box.height};
  return numbers;
}

}  // namespace

Section space_time_section(SectionContext& context) {
  Section section = context.start();
  constexpr std::uint32_t order = 4;
  const std::uint64_t target = magic_sum(order);
  const std::pair<std::string, SlotTable> tables[] = {{"Cook pattern", cook_slots(order)},
                                                      {"pan-diagonal magic square", pandiagonal_magic_square(order)}};

  nlohmann::json panels = nlohmann::json::array();
  Table sums_table{fmt::format("Line sums of the 4×4 tables, measured (a magic sum is m(m²−1)/2 = {})", target),
                   {"table", "rows", "columns", "broken diagonals", "broken antidiagonals", "all = magic sum",
                    "smallest slot gap between edge neighbours"},
                   {}};
  std::vector<bool> magic_flags;
  for (const auto& [name, table] : tables) {
    panels.push_back({{"title", name}, {"order", table.order}, {"slots", table.slots}});
    const LineSums sums = line_sums(table);
    const bool magic = all_equal(sums.rows, target) && all_equal(sums.columns, target) &&
                       all_equal(sums.diagonals, target) && all_equal(sums.antidiagonals, target);
    magic_flags.push_back(magic);
    const std::uint32_t separation = neighbour_separation(table);
    sums_table.rows.push_back({name, join(sums.rows), join(sums.columns), join(sums.diagonals),
                               join(sums.antidiagonals), magic ? "yes" : "no", std::to_string(separation)});
    section.numbers["tables"][name] = {{"slots", table.slots},
                                       {"row_sums", sums.rows},
                                       {"column_sums", sums.columns},
                                       {"diagonal_sums", sums.diagonals},
                                       {"antidiagonal_sums", sums.antidiagonals},
                                       {"pandiagonal_magic", magic},
                                       {"neighbour_separation", separation}};
  }
  section.numbers["magic_sum"] = target;
  section.figures.push_back(context.plot(
      "report_slot_tables", {{"panels", panels}}, "slot-tables",
      "Time slot (0–15) of each of the 16 spatial strata of a pixel, rows top to bottom as on the slide; row and "
      "column sums outside the grid"));
  section.tables.push_back(std::move(sums_table));

  // Motion blur with each assignment, over several seeds (paired: every
  // assignment of a repeat shares the film, lens and light samples): the
  // whole Cornell box, and a close-up where the sphere fills the frame.
  const RenderScale scale = render_scale(context);
  const auto configs = render::builtin_comparison("time-pattern", context.threads(), context.seed());
  render::CompareOptions options;
  options.reference_spp = scale.reference_spp;
  options.cache_dir = context.cache_dir();
  const unsigned repeats = context.quick() ? 4 : 8;
  const TimeAssignments box = measure_time_assignments(render::comparison_scene("", true, scale.width, scale.height),
                                                       configs, options, repeats);
  const TimeAssignments close = measure_time_assignments(close_up(scale), configs, options, repeats);
  const auto& comparison = box.comparison;
  const auto& whole = box.whole;
  const auto& local = box.local;
  const std::size_t pixels = box.pixels, moving_count = box.moving_count;

  section.figures.push_back(image_figure(
      context, time_assignment_panels(box, configs), "motion-blur",
      fmt::format("The Cornell box with a moving sphere, {}×{} pixels, {} samples per pixel: the reference, then time "
                  "assigned to the 4×4 strata at random, by Cook's pattern and by the magic square (first seed), and "
                  "in white the {} pixels whose value depends on the time assignment",
                  scale.width, scale.height, configs.front().settings.sampler.spp, moving_count)));
  section.figures.push_back(image_figure(
      context, time_assignment_panels(close, configs), "motion-close-up",
      fmt::format("A close-up of the moving sphere (a {}° field of view), where {} of the {} pixels depend on the time "
                  "assignment (white in the last panel)",
                  format_number(close_up_fov), close.moving_count, close.pixels)));
  const std::string method = interval_method(repeats);
  section.tables.push_back(repeated_table(
      comparison, whole,
      fmt::format("Motion blur against a {}-spp reference, whole image ({})", comparison.reference_spp, method)));
  Table region{
      fmt::format("MSE over the pixels whose value depends on the time assignment: {} of {} in the box, {} "
                  "of {} in the close-up ({} seeds, 95% t intervals on log ratios)",
                  moving_count, pixels, close.moving_count, close.pixels, repeats),
      {"time assignment", "box: MSE on those pixels (mean ± s.e.)", "box: ratio random/this (95% CI)",
       "close-up: MSE on those pixels", "close-up: ratio random/this (95% CI)", "close-up: whole-image ratio (95% CI)"},
      {}};
  for (std::size_t i = 0; i < configs.size(); ++i)
    region.rows.push_back(
        {configs[i].label, format_number(local[i].mse.mean) + " ± " + format_number(local[i].mse.standard_error, 2),
         i == 0 ? "1 (baseline)" : format_interval(local[i].mse_ratio),
         format_number(close.local[i].mse.mean) + " ± " + format_number(close.local[i].mse.standard_error, 2),
         i == 0 ? "1 (baseline)" : format_interval(close.local[i].mse_ratio),
         i == 0 ? "1 (baseline)" : format_interval(close.whole[i].mse_ratio)});
  section.tables.push_back(std::move(region));
  section.numbers["motion_blur"] = time_assignment_numbers(box, configs);
  section.numbers["motion_close_up"] = time_assignment_numbers(close, configs);
  section.numbers["motion_close_up"]["fov_degrees"] = close_up_fov;
  section.numbers["motion_picture"] = motion_picture(context, section, configs);

  const auto& cook = section.numbers["tables"]["Cook pattern"];
  section.text.push_back(fmt::format(
      "Each pixel's 16 samples are complete in space (one per 4×4 stratum) and incomplete in time (one per time "
      "slot); the tables say which slot each stratum takes. Measured from the tables, every row, column and broken "
      "diagonal of the magic square sums to {} ({}), while Cook's pattern {} (row sums {}) but keeps edge neighbours "
      "at least {} slots apart.",
      target, magic_flags[1] ? "pan-diagonal magic" : "not magic", magic_flags[0] ? "also does" : "does not",
      join(cook["row_sums"].get<std::vector<std::uint64_t>>()), cook["neighbour_separation"].get<std::uint32_t>()));
  std::string whole_text, local_text;
  for (std::size_t i = 1; i < configs.size(); ++i) {
    const std::string separator = i == 1 ? "" : " and ";
    whole_text += separator + fmt::format("{} for {}", format_interval(whole[i].mse_ratio), configs[i].label);
    local_text += separator + fmt::format("{} for {}", format_interval(local[i].mse_ratio), configs[i].label);
  }
  std::string timing;
  for (std::size_t i = 1; i < configs.size(); ++i)
    timing += (i == 1 ? "" : "; ") + fmt::format("{} {}", configs[i].label, efficiency_text(whole[i]));
  section.text.push_back(fmt::format(
      "Rendered with {} samples per pixel against a {}-spp reference over {} seeds, the whole-image MSE of random "
      "time is {} ± {}, and the ratio random/this is {}; {} of the {} pixels depend on the time assignment, and "
      "over those alone the ratio is {}.",
      configs.front().settings.sampler.spp, comparison.reference_spp, repeats, format_number(whole[0].mse.mean),
      format_number(whole[0].mse.standard_error, 2), whole_text, moving_count, pixels, local_text));
  std::string close_text;
  for (std::size_t i = 1; i < configs.size(); ++i)
    close_text +=
        (i == 1 ? "" : " and ") + fmt::format("{} for {}", format_interval(close.local[i].mse_ratio), configs[i].label);
  section.text.push_back(fmt::format(
      "In a close-up where the moving sphere fills the frame, {} of the {} pixels depend on time, and the ratio "
      "random/this over them is {}.",
      close.moving_count, close.pixels, close_text));
  section.text.push_back(fmt::format(
      "Every assignment traces the same number of rays, so the efficiency ratio should equal the MSE ratio; it is "
      "quoted only where the paired time ratio's interval excludes 1 ({}). Intervals: {}.",
      timing, method));
  screen_space_error(context, section);
  frames_error(context, section);
  section.try_it = {
      "stratum compare --builtin time-pattern --width 64 --height 64",
      "stratum render scenes/penumbra.json --sampler zsobol --spp 1 --exr z.exr && stratum render "
      "scenes/penumbra.json --reference --exr ref.exr && stratum spectrum --image z.exr --reference ref.exr",
      "for k in $(seq 0 15); do stratum render scenes/penumbra.json --sampler sobol-bn --spp 1 --frame $k --exr "
      "f$k.exr; done && stratum spectrum --frames f{0..15}.exr"};
  return section;
}

}  // namespace stratum::report
