/// `stratum compare [SCENE] (--builtin NAME | --configs FILE)`: renders each
/// configuration, at equal samples or equal time, and measures it against a
/// cached converged reference.
#ifdef STRATUM_HAS_RENDER
#include <fmt/core.h>

#include <cmath>

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/io/json.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {

struct CompareCommand {
  std::string scene, configs, builtin = "shadow-rays";
  render::CompareOptions run;
  std::int64_t reference_spp = 1024, width = 64, height = 64;
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
  require(o.reference_spp >= 1 && o.reference_spp <= (1 << 24), "reference-spp", o.reference_spp, "must be in [1, 2^24]");
  require(o.width >= 1 && o.width <= 16384, "width", o.width, "must be in [1, 16384]");
  require(o.height >= 1 && o.height <= 16384, "height", o.height, "must be in [1, 16384]");
  o.run.reference_spp = std::uint32_t(o.reference_spp);
  const auto configs = o.configs.empty() ? render::builtin_comparison(o.builtin, o.threads, o.seed)
                                         : render::parse_configs(read_json(o.configs), o.threads, o.seed);
  // Motion only for the time-pattern comparison: each isolates its own integral.
  const bool keep_motion = o.configs.empty() && o.builtin == "time-pattern";
  const auto [scene, key, note] = render::comparison_scene(o.scene, keep_motion, int(o.width), int(o.height));
  const auto rows = render::compare(scene, key, configs, o.run);
  if (o.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& r : rows) {
      out.push_back({{"label", r.label}, {"spp", r.samples}, {"passes", r.passes}, {"mse", r.mse},
                     {"relative_mse", r.relative_mse}, {"seconds", r.seconds}, {"efficiency", r.efficiency},
                     {"mse_ratio", r.mse_ratio}, {"efficiency_ratio", r.efficiency_ratio}});
      if (!r.variance_path.empty()) out.back()["variance"] = r.variance_path;
      // The error's spectrum (docs/render.md): null where there is none (tiny or perfect images).
      auto& row = out.back();
      row["low_frequency_power"] = std::isfinite(r.low_frequency_power) ? nlohmann::json(r.low_frequency_power) : nullptr;
      nlohmann::json power = nlohmann::json::array();
      for (double p : r.error_radial_power) power.push_back(std::isfinite(p) ? nlohmann::json(p) : nullptr);
      row["error_spectrum"] = {{"frequency", r.error_radial_frequency}, {"power", power}};
    }
    std::cout << nlohmann::json{{"scene", scene.name}, {"reference_spp", o.reference_spp}, {"equal_time", o.run.equal_time},
                                {"scene_note", note}, {"rows", out}}.dump(2)
              << "\n";
    return;
  }
  fmt::print("{:18} {:>7} {:>11} {:>11} {:>9} {:>11} {:>9} {:>9} {:>8}\n", "config", "spp", "MSE", "relMSE", "seconds",
             "efficiency", "MSE x", "eff. x", "low-f");
  for (const auto& r : rows)
    fmt::print("{:18} {:>7} {:>11.4e} {:>11.4e} {:>9.3f} {:>11.4e} {:>9.2f} {:>9.2f} {:>8}\n", r.label, r.samples, r.mse,
               r.relative_mse, r.seconds, r.efficiency, r.mse_ratio, r.efficiency_ratio,
               std::isfinite(r.low_frequency_power) ? fmt::format("{:.3f}", r.low_frequency_power) : std::string("-"));
  fmt::print("(low-f: the error's power below a quarter of Nyquist, white noise = 1, blue noise < 1)\n");
  fmt::print("({}; ratios against the first row; efficiency = 1 / (MSE x seconds); reference: {} spp, cached in {})\n",
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
  add_seed_option(*command, o->seed, "seed of the configurations");
  command->add_flag("--json", o->json, "JSON output");
  command->callback([o] { run_compare(*o); });
}

}  // namespace stratum::cli
#endif
