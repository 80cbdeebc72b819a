/// `stratum compare [SCENE] (--builtin NAME | --configs FILE)`: renders each
/// configuration, at equal samples or equal time, and measures it against a
/// cached converged reference.
#ifdef STRATUM_HAS_RENDER
#include <fmt/core.h>

#include <cmath>
#include <optional>

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/io/json.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/render/compare_repeated.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {

struct CompareCommand {
  std::string scene, configs, builtin = "shadow-rays";
  render::CompareOptions run;
  std::int64_t reference_spp = 1024, width = 64, height = 64, repeats = 1;
  std::optional<double> confidence;
  unsigned threads = 0;
  std::uint64_t seed = default_seed;
  bool json = false, list = false;
};

nlohmann::json read_json(const std::string& path) {
  // A regular file only (a FIFO would hang), nesting capped (io::parse_json).
  return io::parse_json(io::read_regular_file("configs", path, std::uint64_t{1} << 26), "configs", path);
}

void run_compare(CompareCommand& o) {
  if (o.list) {
    for (const auto& [name, description] : render::builtin_comparisons()) fmt::print("{:16} {}\n", name, description);
    return;
  }
  require(o.reference_spp >= 1 && o.reference_spp <= (1 << 24), "reference-spp", o.reference_spp,
          "must be in [1, 2^24]");
  require(o.width >= 1 && o.width <= 16384, "width", o.width, "must be in [1, 16384]");
  require(o.height >= 1 && o.height <= 16384, "height", o.height, "must be in [1, 16384]");
  require(o.repeats >= 1 && o.repeats <= 1000, "repeats", o.repeats, "must be in [1, 1000]");
  if (o.confidence && o.repeats < 2)
    throw invalid_argument("confidence", fmt::format("{}", *o.confidence),
                           "applies with --repeats 2 or more (intervals over the repeats' seeds)");
  const double confidence = o.confidence.value_or(0.95);
  require(confidence > 0 && confidence < 1, "confidence", confidence, "must be in (0, 1)");
  o.run.reference_spp = std::uint32_t(o.reference_spp);
  const auto configs = o.configs.empty() ? render::builtin_comparison(o.builtin, o.threads, o.seed)
                                         : render::parse_configs(read_json(o.configs), o.threads, o.seed);
  // Motion only for the time-pattern comparison: each isolates its own integral.
  const bool keep_motion = o.configs.empty() && o.builtin == "time-pattern";
  const auto [scene, key, note] = render::comparison_scene(o.scene, keep_motion, int(o.width), int(o.height));
  const render::RepeatedCompare repeated =
      render::compare_repeated(scene, key, configs, o.run, unsigned(o.repeats), confidence);
  const auto& rows = repeated.summary;
  const auto interval = [](const analysis::RatioInterval& i) { return nlohmann::json::array({i.low, i.high}); };
  if (o.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& r : rows) {
      out.push_back({{"label", r.label},
                     {"spp", r.samples},
                     {"passes", r.passes},
                     {"mse", r.mse},
                     {"relative_mse", r.relative_mse},
                     {"seconds", r.seconds},
                     {"efficiency", r.efficiency},
                     {"mse_ratio", r.mse_ratio},
                     {"efficiency_ratio", r.efficiency_ratio}});
      if (!r.variance_path.empty()) out.back()["variance"] = r.variance_path;
      // The error's spectrum (docs/render.md): null where there is none (tiny or perfect images).
      auto& row = out.back();
      row["low_frequency_power"] =
          std::isfinite(r.low_frequency_power) ? nlohmann::json(r.low_frequency_power) : nullptr;
      nlohmann::json power = nlohmann::json::array();
      for (double p : r.error_radial_power) power.push_back(std::isfinite(p) ? nlohmann::json(p) : nullptr);
      row["error_spectrum"] = {{"frequency", r.error_radial_frequency}, {"power", power}};
      if (o.repeats > 1) {  // the statistics over the repeats (docs/render.md)
        const std::size_t c = out.size() - 1;
        const render::RepeatedStatistics& st = repeated.statistics[c];
        row["mse_per_seed"] = repeated.mse[c];
        row["seconds_per_seed"] = repeated.seconds[c];
        row["mse_standard_error"] = st.mse.standard_error;
        row["mse_ratio_interval"] = interval(st.mse_ratio);
        row["time_ratio"] = st.time_ratio.estimate;
        row["time_ratio_interval"] = interval(st.time_ratio);
        row["efficiency_ratio_interval"] = interval(st.efficiency_ratio);
        row["time_resolved"] = st.time_resolved;
      }
    }
    std::cout << nlohmann::json{{"scene", scene.name},
                                {"reference_spp", o.reference_spp},
                                {"equal_time", o.run.equal_time},
                                {"scene_note", note},
                                {"repeats", o.repeats},
                                {"confidence", o.repeats > 1 ? nlohmann::json(confidence) : nullptr},
                                {"rows", out}}
                     .dump(2)
              << "\n";
    return;
  }
  fmt::print("{:18} {:>7} {:>11} {:>11} {:>9} {:>11} {:>9} {:>9} {:>8}\n", "config", "spp", "MSE", "relMSE", "seconds",
             "efficiency", "MSE x", "eff. x", "low-f");
  for (const auto& r : rows)
    fmt::print("{:18} {:>7} {:>11.4e} {:>11.4e} {:>9.3f} {:>11.4e} {:>9.2f} {:>9.2f} {:>8}\n", r.label, r.samples,
               r.mse, r.relative_mse, r.seconds, r.efficiency, r.mse_ratio, r.efficiency_ratio,
               std::isfinite(r.low_frequency_power) ? fmt::format("{:.3f}", r.low_frequency_power) : std::string("-"));
  fmt::print("(low-f: the error's power below a quarter of Nyquist, white noise = 1, blue noise < 1)\n");
  if (o.repeats > 1) {
    const std::string level = fmt::format("{:g}% CI", 100 * confidence);
    fmt::print("\n{:18} {:>22} {:>24} {:>24} {:>24}\n", "config", "MSE (mean ± s.e.)", "MSE x (" + level + ")",
               "time x (" + level + ")", "eff. x (" + level + ")");
    const auto ratio = [](const analysis::RatioInterval& i) {
      return fmt::format("{:.3g} ({:.3g}–{:.3g})", i.estimate, i.low, i.high);
    };
    for (std::size_t c = 0; c < rows.size(); ++c) {
      const render::RepeatedStatistics& st = repeated.statistics[c];
      fmt::print("{:18} {:>22} {:>24} {:>24} {:>24}\n", rows[c].label,
                 fmt::format("{:.4e} ± {:.2e}", st.mse.mean, st.mse.standard_error), ratio(st.mse_ratio),
                 ratio(st.time_ratio),
                 c == 0             ? std::string("1 (baseline)")
                 : st.time_resolved ? ratio(st.efficiency_ratio)
                                    : fmt::format("times equal ±{:.2g}%", analysis::noise_percent(st.time_ratio)));
    }
    fmt::print(
        "({} seeds, every configuration rendered with each (paired): MSE and relMSE are means, seconds medians, "
        "ratios geometric means with Student-t intervals on their logs; an efficiency ratio is given only where "
        "the times differ beyond their noise)\n",
        o.repeats);
  }
  fmt::print(
      "({}; ratios against the first row; efficiency = 1 / (MSE x seconds); reference: {} spp, cached in {})\n",
      o.run.equal_time > 0 ? fmt::format("equal time: {} s each", o.run.equal_time) : std::string("equal samples"),
      o.reference_spp, o.run.cache_dir);
  if (!o.run.variance_dir.empty()) fmt::print("(variance images in {})\n", o.run.variance_dir);
  if (!note.empty()) fmt::print("(scene: {})\n", note);
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareCommand>();
  auto* command = app.add_subcommand("compare", "Measure render configurations against a converged reference");
  command->add_option("scene", o->scene, "JSON scene (default: the built-in Cornell box)");
  command->add_option("--builtin", o->builtin, "a built-in comparison (see --list)")->capture_default_str();
  command->add_option("--configs", o->configs, "JSON file: an array of configurations (docs/render.md)");
  command->add_flag("--list", o->list, "list the built-in comparisons");
  command->add_option("--reference-spp", o->reference_spp, "samples per pixel of the reference")->capture_default_str();
  command->add_option("--cache", o->run.cache_dir, "folder of cached references")->capture_default_str();
  command->add_option("--equal-time", o->run.equal_time,
                      "seconds per configuration: independent passes until then (0: equal samples)");
  command->add_option("--variance-dir", o->run.variance_dir, "write each configuration's variance image there (EXR)");
  command->add_option("--width", o->width, "image width")->capture_default_str();
  command->add_option("--height", o->height, "image height")->capture_default_str();
  add_threads_option(*command, o->threads, "threads");
  add_seed_option(*command, o->seed, "seed of the configurations (repeat k > 0: hash(seed, k))");
  command
      ->add_option("--repeats", o->repeats,
                   "render every configuration with this many seeds, paired, for intervals on the ratios (1..1000)")
      ->capture_default_str();
  command->add_option("--confidence", o->confidence,
                      "level of the ratios' intervals with --repeats 2 or more (default 0.95)");
  command->add_flag("--json", o->json, "JSON output");
  command->callback([o] { run_compare(*o); });
}

}  // namespace stratum::cli
#endif
