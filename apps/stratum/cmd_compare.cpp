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
#include "stratum/render/render_job.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {

/// The command line's job (checked by run_compare_job alone) and how to print it.
struct CompareCommand {
  render::CompareJob job;
  std::string configs_path;
  bool json = false, list = false;
};

void run_compare(CompareCommand& o) {
  if (o.list) {
    for (const auto& [name, description] : render::builtin_comparisons()) fmt::print("{:16} {}\n", name, description);
    return;
  }
  render::CompareJob& job = o.job;
  if (!o.configs_path.empty()) {
    // A regular file only (a FIFO would hang), size capped; the library parses it (nesting capped).
    job.configs = io::read_regular_file("configs", o.configs_path, std::uint64_t{1} << 26);
    job.configs_origin = o.configs_path;
  }
  const render::CompareJobResult result = render::run_compare_job(job);
  const render::RepeatedCompare& repeated = result.repeated;
  const std::string& note = result.scene_note;
  const double confidence = result.confidence;
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
      if (job.repeats > 1) {  // the statistics over the repeats (docs/render.md)
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
    std::cout << nlohmann::json{{"scene", result.scene_name},
                                {"reference_spp", job.reference_spp},
                                {"equal_time", job.options.equal_time},
                                {"scene_note", note},
                                {"repeats", job.repeats},
                                {"confidence", job.repeats > 1 ? nlohmann::json(confidence) : nullptr},
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
  if (job.repeats > 1) {
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
        job.repeats);
  }
  fmt::print("({}; ratios against the first row; efficiency = 1 / (MSE x seconds); reference: {} spp, cached in {})\n",
             job.options.equal_time > 0 ? fmt::format("equal time: {} s each", job.options.equal_time)
                                        : std::string("equal samples"),
             job.reference_spp, job.options.cache_dir);
  if (!job.options.variance_dir.empty()) fmt::print("(variance images in {})\n", job.options.variance_dir);
  if (!note.empty()) fmt::print("(scene: {})\n", note);
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareCommand>();
  auto* command = app.add_subcommand("compare", "Measure render configurations against a converged reference");
  render::CompareJob& job = o->job;
  command->add_option("scene", job.scene, "JSON scene (default: the built-in Cornell box)");
  command->add_option("--builtin", job.builtin, "a built-in comparison (see --list; default shadow-rays)");
  command->add_option("--configs", o->configs_path, "JSON file: an array of configurations (docs/render.md)");
  command->add_flag("--list", o->list, "list the built-in comparisons");
  command->add_option("--reference-spp", job.reference_spp, "samples per pixel of the reference")
      ->capture_default_str();
  command->add_option("--cache", job.options.cache_dir, "folder of cached references")->capture_default_str();
  command->add_option("--equal-time", job.options.equal_time,
                      "seconds per configuration: independent passes until then (0: equal samples)");
  command->add_option("--variance-dir", job.options.variance_dir,
                      "write each configuration's variance image there (EXR)");
  command->add_option("--width", job.width, "image width")->capture_default_str();
  command->add_option("--height", job.height, "image height")->capture_default_str();
  add_threads_option(*command, job.threads, "threads");
  add_seed_option(*command, job.seed, "seed of the configurations (repeat k > 0: hash(seed, k))");
  command
      ->add_option("--repeats", job.repeats,
                   "render every configuration with this many seeds, paired, for intervals on the ratios (1..1000)")
      ->capture_default_str();
  command->add_option("--confidence", job.confidence,
                      "level of the ratios' intervals with --repeats 2 or more (default 0.95)");
  command->add_flag("--json", o->json, "JSON output");
  command->callback([o] { run_compare(*o); });
}

}  // namespace stratum::cli
#endif
