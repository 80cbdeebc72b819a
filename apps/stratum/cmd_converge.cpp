/// `stratum converge`: a convergence study of several samplers on one
/// integrand — RMSE, variance, seconds and efficiency per N, and the fitted
/// slope of log variance against log N — as a table, JSON or a figure.
#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/plot.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct ConvergeOptions {
  std::string integrand, samplers, counts = sa::default_counts, plot;
  bool counts_given = false;  ///< --n given: every sampler must take every count
  std::optional<std::int64_t> d;
  std::uint64_t seed = 0;
  std::int64_t runs = 32, threads = 0;
  double confidence = 0.95;                           ///< level of the slopes' confidence intervals
  std::vector<std::string> integrand_params, params;  ///< --integrand-param; -p (every sampler's)
  std::string randomize;                              ///< --randomize (every sampler's)
  bool json = false;
};

nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

nlohmann::json skipped_json(const sa::SamplerConvergence& entry) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& skip : entry.skipped) out.push_back({{"n", skip.n}, {"reason", skip.reason}});
  return out;
}

/// A number of the table, or "undefined" where it has none (an efficiency
/// at variance 0, a slope through log 0): never "inf" or "nan" as a result.
std::string cell(double value, const char* format = "{:.4e}") {
  return std::isfinite(value) ? fmt::format(fmt::runtime(format), value) : std::string("undefined");
}

nlohmann::json to_json(const sa::ConvergenceResult& result) {
  nlohmann::json samplers = nlohmann::json::array();
  for (const auto& entry : result.samplers) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : entry.rows)
      rows.push_back({{"n", row.n},
                      {"mean_error", row.mean_error},
                      {"rmse", row.rmse},
                      {"variance", row.variance},
                      {"seconds", row.seconds},
                      {"efficiency", number(row.efficiency)}});
    samplers.push_back({{"name", entry.sampler.name},
                        {"randomize", entry.sampler.randomize},
                        {"rows", rows},
                        {"fitted", entry.fitted},
                        {"slope", number(entry.slope.slope)},
                        {"slope_standard_error", number(entry.slope.slope_standard_error)},
                        {"slope_interval", {number(entry.interval.low), number(entry.interval.high)}},
                        {"slope_confidence", entry.interval.confidence},
                        {"slope_sampling_standard_error", number(entry.interval.standard_error)},
                        {"intercept", number(entry.slope.intercept)},
                        {"skipped", skipped_json(entry)}});
  }
  return {{"integrand", result.integrand},
          {"d", result.d},
          {"exact", result.exact},
          {"runs", result.runs},
          {"samplers", samplers}};
}

void run_converge(const ConvergeOptions& o) {
  const auto figure = plot::prepare_plot("plot", o.plot);  // checked before the work
  require(!o.samplers.empty(), "samplers", "(missing)",
          "give --samplers A,B,... (each a spec NAME[(KEY=VALUE,...)][:RANDOMIZER], docs/samplers.md)");
  require(!o.d || (*o.d >= 1 && *o.d <= std::numeric_limits<unsigned>::max()), "d", o.d.value_or(0),
          "must be a positive integer");
  require(o.runs >= 2 && o.runs <= 1000000, "runs", o.runs, "must be in [2, 1000000] (a variance needs 2 runs)");
  sa::ConvergenceRequest request;
  request.integrand.name = o.integrand;
  request.integrand.d = static_cast<unsigned>(o.d.value_or(0));
  request.integrand.params =
      sa::parse_integrand_params(o.integrand, parse_key_values("integrand-param", o.integrand_params));
  for (const auto& item : split_sampler_list(o.samplers)) {
    const SamplerSpec spec = combine_sampler_options(item, o.params, o.randomize);
    request.samplers.push_back({spec.name, spec.randomize, spec.params});
  }
  request.counts = sa::parse_counts(o.counts);
  request.runs = static_cast<unsigned>(o.runs);
  request.seed = o.seed;
  request.threads = static_cast<unsigned>(o.threads);
  request.skip_refused_counts = !o.counts_given;
  request.confidence = o.confidence;
  const sa::ConvergenceResult result = sa::run_convergence(request);
  const nlohmann::json data = to_json(result);
  if (figure) plot::write_plot("converge", data, *figure);
  if (o.json) return fmt::print("{}\n", data.dump(2));
  fmt::print("integrand {} (d = {}), exact {:.17g}, {} runs per N\n", result.integrand, result.d, result.exact,
             result.runs);
  for (const auto& entry : result.samplers) {
    if (!std::isfinite(entry.slope.slope))
      fmt::print("\n{}:{}  slope of log {} vs log N: undefined (the {} is 0 or not finite at some N)\n",
                 entry.sampler.name, entry.sampler.randomize, entry.fitted, entry.fitted);
    else if (entry.fitted == "variance")
      fmt::print(
          "\n{}:{}  slope of log variance vs log N: {:.3f}, {:g}% interval [{:.3f}, {:.3f}] (jackknife SE {:.3f}; "
          "residual SE of the fit {:.3f})\n",
          entry.sampler.name, entry.sampler.randomize, entry.slope.slope, 100 * entry.interval.confidence,
          entry.interval.low, entry.interval.high, entry.interval.standard_error, entry.slope.slope_standard_error);
    else
      fmt::print(
          "\n{}:{}  slope of log {} vs log N: {:.3f} ± {:.3f} (residual SE; the runs do not differ, so there "
          "is no sampling interval)\n",
          entry.sampler.name, entry.sampler.randomize, entry.fitted, entry.slope.slope,
          entry.slope.slope_standard_error);
    if (!entry.skipped.empty()) {
      std::string counts;
      for (const auto& skip : entry.skipped) counts += (counts.empty() ? "" : ",") + std::to_string(skip.n);
      fmt::print("skipped N = {} of the default --n (this sampler refuses them: {})\n", counts,
                 entry.skipped.front().reason);
    }
    fmt::print("{:>10} {:>12} {:>12} {:>12} {:>12} {:>12}\n", "N", "mean error", "RMSE", "variance", "seconds",
               "efficiency");
    for (const auto& row : entry.rows)
      fmt::print("{:>10} {:>12} {:>12} {:>12} {:>12} {:>12}\n", row.n, cell(row.mean_error), cell(row.rmse),
                 cell(row.variance), cell(row.seconds), cell(row.efficiency));
  }
}
}  // namespace

void add_converge_command(CLI::App& app) {
  auto o = std::make_shared<ConvergeOptions>();
  auto* command = app.add_subcommand("converge", "Convergence study: error and variance vs N for several samplers");
  command->add_option("--integrand", o->integrand, "integrand name (see `stratum integrate --list`)")->required();
  command
      ->add_option("--samplers", o->samplers,
                   "sampler specs A,B,... each NAME[(KEY=VALUE,...)][:RANDOMIZER] (docs/samplers.md); the list "
                   "splits on commas outside parentheses")
      ->required();
  auto* counts = command
                     ->add_option("--n", o->counts,
                                  "A:B (powers of two), A:B:F (times F) or a comma list; with the default, each "
                                  "sampler skips the counts it refuses (e.g. non-squares for 2D jittered) and "
                                  "says so")
                     ->capture_default_str();
  command->add_option("-d", o->d, "dimension (default: the integrand's)");
  command->add_option("--runs", o->runs, "independent randomizations per N")->capture_default_str();
  add_seed_option(*command, o->seed, "seed; run r of sampler s at N uses hash(seed, s, N, r)");
  add_threads_option(*command, o->threads, "threads (results do not depend on it)");
  command
      ->add_option("--confidence", o->confidence,
                   "level of each slope's confidence interval, in (0, 1) (jackknife over the runs, Student-t: "
                   "docs/samplers.md)")
      ->capture_default_str();
  command->add_option("-p,--param", o->params,
                      "sampler parameter KEY=VALUE for every sampler of --samplers (repeatable)");
  command->add_option("--randomize", o->randomize,
                      "randomizer for every sampler of --samplers (or give NAME:RANDOMIZER)");
  command->add_option("--integrand-param", o->integrand_params, "integrand parameter KEY=V1,V2,... (repeatable)");
  add_spec_footer(*command);
  command->add_flag("--json", o->json, "print JSON");
  command->add_option("--plot", o->plot, "write a log-log figure of variance vs N (PNG)");
  command->callback([o, counts] {
    o->counts_given = counts->count() > 0;
    run_converge(*o);
  });
}

}  // namespace stratum::cli
