/// `stratum study importance`: importance sampling measured (LECTURE.md §3) —
/// irradiance under a uniform sky and a rectangular light by uniform vs
/// cosine-weighted hemisphere directions, and a light sampled by area vs by
/// solid angle as its size and distance vary: variances, their ratio and the
/// efficiency ratio, as a table, JSON or a figure.
#include <fmt/core.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/plot.hpp"
#include "stratum/analysis/importance_study.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct ImportanceOptions {
  std::int64_t runs = 16, samples = 4096, threads = 0;
  std::vector<double> sizes{0.25, 1, 4}, distances{0.25, 1, 4};
  std::uint64_t seed = 0;
  std::string plot;
  bool json = false;
};

nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

nlohmann::json to_json(const sa::MethodResult& m) {
  return {{"method", m.method},
          {"estimate", m.estimate},
          {"estimate_stderr", number(m.estimate_stderr)},
          {"variance", m.variance},
          {"variance_stderr", number(m.variance_stderr)},
          {"predicted_variance", number(m.predicted_variance)},
          {"seconds_per_sample", m.seconds_per_sample},
          {"efficiency", number(m.efficiency)}};
}

nlohmann::json to_json(const std::vector<sa::ImportanceComparison>& list) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& c : list)
    rows.push_back({{"scene", c.scene},
                    {"size", c.size},
                    {"distance", c.distance},
                    {"exact", c.exact},
                    {"a", to_json(c.a)},
                    {"b", to_json(c.b)},
                    {"variance_ratio", number(c.variance_ratio)},
                    {"variance_ratio_stderr", number(c.variance_ratio_stderr)},
                    {"predicted_variance_ratio", number(c.predicted_variance_ratio)},
                    {"time_ratio", number(c.time_ratio)},
                    {"efficiency_ratio", number(c.efficiency_ratio)}});
  return rows;
}

void print_table(const std::vector<sa::ImportanceComparison>& list) {
  fmt::print("{:>6} {:>6} {:>6} {:>11} {:>11} {:>11} {:>11} {:>11} {:>16} {:>9} {:>10}\n", "scene", "size", "dist",
             "exact", "mean a", "var a", "mean b", "var b", "var ratio", "(theory)", "eff ratio");
  for (const auto& c : list)
    fmt::print("{:>6} {:>6.3g} {:>6.3g} {:>11.5g} {:>11.5g} {:>11.4e} {:>11.5g} {:>11.4e} {:>16} {:>9.4g} {:>10.4g}\n",
               c.scene, c.size, c.distance, c.exact, c.a.estimate, c.a.variance, c.b.estimate, c.b.variance,
               fmt::format("{:.4g}±{:.2g}", c.variance_ratio, c.variance_ratio_stderr), c.predicted_variance_ratio,
               c.efficiency_ratio);
}

void run_importance(const ImportanceOptions& o) {
  const auto figure = plot::prepare_plot("plot", o.plot);  // checked before the work
  require(o.runs >= 2 && o.runs <= 100000, "runs", o.runs, "must be in [2, 100000] (a standard error needs 2 runs)");
  require(o.samples >= 2 && o.samples <= (std::int64_t{1} << 30), "samples", o.samples, "must be in [2, 2^30]");
  sa::ImportanceStudyRequest request;
  request.runs = static_cast<unsigned>(o.runs);
  request.samples = static_cast<std::uint64_t>(o.samples);
  request.sizes = o.sizes;
  request.distances = o.distances;
  request.seed = o.seed;
  request.threads = static_cast<unsigned>(o.threads);
  const sa::ImportanceStudy study = sa::run_importance_study(request);
  const nlohmann::json data = {{"runs", study.runs},
                               {"samples", study.samples},
                               {"hemisphere", to_json(study.hemisphere)},
                               {"light", to_json(study.light)}};
  if (figure) plot::write_plot("importance", data, *figure);
  if (o.json) return fmt::print("{}\n", data.dump(2));
  fmt::print("irradiance at a point (normal +z), {} runs x {} samples per method; variances per sample\n", study.runs,
             study.samples);
  fmt::print("ratios favour b: var ratio = var a / var b, eff ratio = (1/(var b t b)) / (1/(var a t a))\n");
  fmt::print("\n(a) hemisphere: a = uniform (p = 1/2pi), b = cosine (p = cos/pi); light: square centred above\n");
  print_table(study.hemisphere);
  fmt::print("\n(b) square light centred above: a = by area (p = r^2/(A cos_l)), b = by solid angle (p = 1/Omega)\n");
  print_table(study.light);
}
}  // namespace

void add_study_importance_command(CLI::App& study) {
  auto o = std::make_shared<ImportanceOptions>();
  auto* command =
      study.add_subcommand("importance", "Importance sampling: cosine vs uniform, solid angle vs area (§3)");
  command->add_option("--runs", o->runs, "independent replicates per method")->capture_default_str();
  command->add_option("--samples", o->samples, "samples per replicate")->capture_default_str();
  command->add_option("--sizes", o->sizes, "light sides for study (b)")->delimiter(',')->capture_default_str();
  command->add_option("--distances", o->distances, "light heights for study (b)")
      ->delimiter(',')
      ->capture_default_str();
  add_seed_option(*command, o->seed, "seed of the random numbers");
  add_threads_option(*command, o->threads, "threads (results other than timings do not depend on it)");
  command->add_flag("--json", o->json, "print JSON");
  command->add_option("--plot", o->plot, "write a figure of the variance and efficiency ratios (PNG)");
  command->callback([o] { run_importance(*o); });
}

}  // namespace stratum::cli
