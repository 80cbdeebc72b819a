/// `stratum integrate`: estimate a registry integrand with any registry
/// sampler, with its standard error, exact value and error; `--list` prints
/// the integrands (name, dimensions, parameters, description).
#include <fmt/core.h>
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "schema_json.hpp"
#include "sampler_options.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/integrate_tolerance.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct IntegrateOptions {
  std::string integrand;
  SamplerOptions sampler{"random"};
  std::optional<std::int64_t> n, d;
  std::int64_t runs = 1, threads = 0;
  double confidence = 0.95;
  std::optional<double> abs_tol, rel_tol;
  std::optional<std::int64_t> max_n;
  std::vector<std::string> integrand_params;
  bool json = false, list = false;
};

void print_integrands(bool json) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& info : sa::integrands()) {
    const nlohmann::json params = params_json(info.params);
    std::string param_text;
    for (const auto& p : info.params) param_text += fmt::format(" {}={}", p.name, p.default_value);
    out.push_back({{"name", info.name},
                   {"description", info.description},
                   {"min_dim", info.min_dim},
                   {"max_dim", info.max_dim},
                   {"default_dim", info.default_dim},
                   {"properties", info.properties},
                   {"params", params}});
    if (!json)
      fmt::print("{:<20} d {:>2}-{:<4} {}{}\n", info.name, info.min_dim, info.max_dim, info.description,
                 param_text.empty() ? "" : " (defaults:" + param_text + ")");
  }
  if (json) fmt::print("{}\n", nlohmann::json{{"integrands", out}}.dump(2));
}

/// A number for JSON, null when not finite (no standard error, or efficiency +inf).
nlohmann::json finite(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

void run_integrate(const IntegrateOptions& o) {
  if (o.list) return print_integrands(o.json);
  require(!o.integrand.empty(), "integrand", "(missing)", "give --integrand NAME (see `stratum integrate --list`)");
  require(o.n.has_value(), "n", "(missing)", "give -n N");
  require(*o.n >= 1, "n", *o.n, "must be a positive integer");
  require(!o.d || (*o.d >= 1 && *o.d <= std::numeric_limits<unsigned>::max()), "d", o.d.value_or(0),
          "must be a positive integer");
  require(o.runs >= 1 && o.runs <= 1000000, "runs", o.runs, "must be in [1, 1000000]");
  sa::IntegrationRequest request;
  request.integrand = {
      o.integrand, static_cast<unsigned>(o.d.value_or(0)),
      sa::parse_integrand_params(o.integrand, parse_key_values("integrand-param", o.integrand_params))};
  const SamplerSpec spec = o.sampler.spec();
  request.sampler = {spec.name, spec.randomize, spec.params};
  request.n = static_cast<std::uint64_t>(*o.n);
  request.runs = static_cast<unsigned>(o.runs);
  request.seed = o.sampler.seed;
  request.threads = static_cast<unsigned>(o.threads);
  request.confidence = o.confidence;
  require(!o.max_n || *o.max_n >= 1, "max-n", o.max_n.value_or(0), "must be a positive integer");
  sa::ToleranceOptions options{o.abs_tol, o.rel_tol, {}};
  if (o.max_n) options.max_n = static_cast<std::uint64_t>(*o.max_n);
  const bool to_tolerance = options.any();
  const sa::ToleranceResult tolerance = sa::integrate_with(request, options);
  const sa::IntegrationResult& r = tolerance.result;
  nlohmann::json steps = nlohmann::json::array();
  std::string step_counts;
  for (const auto& step : tolerance.steps) {
    steps.push_back({{"n", step.n},
                     {"estimate", step.estimate},
                     {"half_width", step.half_width},
                     {"target", step.target},
                     {"seconds", step.seconds}});
    step_counts += (step_counts.empty() ? "" : ", ") + std::to_string(step.n);
  }
  if (o.json) {
    nlohmann::json out = {{"integrand", r.integrand},
                          {"sampler", r.sampler},
                          {"randomize", r.randomize},
                          {"d", r.d},
                          {"n", r.n},
                          {"runs", r.runs},
                          {"seed", o.sampler.seed},
                          {"estimate", r.estimate},
                          {"standard_error", std::isfinite(r.standard_error) ? nlohmann::json(r.standard_error)
                                                                             : nlohmann::json(nullptr)},
                          {"standard_error_kind", r.standard_error_kind},
                          {"exact", r.exact},
                          {"error", r.error},
                          {"seconds", r.seconds},
                          {"run_estimates", r.run_estimates},
                          {"confidence", r.confidence},
                          {"interval", {finite(r.interval_low), finite(r.interval_high)}},
                          {"half_width", finite(r.half_width)},
                          {"seconds_per_run", r.seconds_per_run},
                          {"efficiency", finite(r.efficiency)}};
    if (to_tolerance)
      out["tolerance"] = {{"abs_tol", o.abs_tol.value_or(0)},
                          {"rel_tol", o.rel_tol.value_or(0)},
                          {"target", tolerance.target},
                          {"met", tolerance.met},
                          {"steps", steps}};
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("integrand       {} (d = {})\nsampler         {}:{} n = {} runs = {}\n", r.integrand, r.d, r.sampler,
             r.randomize, r.n, r.runs);
  const std::string standard_error =
      r.standard_error_kind == "identical-runs"
          ? fmt::format(
                "unavailable: the {} runs gave identical estimates ({}:{} is not randomized; choose a "
                "randomizer, e.g. :cp)",
                r.runs, r.sampler, r.randomize)
          : fmt::format(
                "{:.6g} ({})", r.standard_error,
                r.standard_error_kind == "iid" ? "iid: s/sqrt(n) of one point set" : "from the runs' replicates");
  fmt::print("estimate        {:.17g}\nstandard error  {}\nexact           {:.17g}\nerror           {:.6g}\n",
             r.estimate, standard_error, r.exact, r.error);
  if (std::isfinite(r.half_width))
    fmt::print(
        "{:.4g}% interval [{:.10g}, {:.10g}] (estimate ± {:.4g}, Student-t over {})\n"
        "efficiency      {:.6g} (1 / (variance × seconds), {:.4g} s per run)\n",
        100 * r.confidence, r.interval_low, r.interval_high, r.half_width,
        r.runs >= 2 ? fmt::format("{} runs", r.runs) : std::string("the n values: iid"), r.efficiency,
        r.seconds_per_run);
  if (to_tolerance)
    fmt::print("tolerance       {}: half-width {:.4g} {} target {:.4g} at n = {} ({} steps: n = {})\n",
               tolerance.met ? "met" : "NOT met (max-n reached)", r.half_width, tolerance.met ? "<=" : ">",
               tolerance.target, r.n, tolerance.steps.size(), step_counts);
}
}  // namespace

void add_integrate_command(CLI::App& app) {
  auto o = std::make_shared<IntegrateOptions>();
  auto* command = app.add_subcommand("integrate", "Estimate a test integrand with a sampler (--list: integrands)");
  command->add_option("--integrand", o->integrand, "integrand name (see --list)");
  add_sampler_options(*command, o->sampler, "the sampler", "seed (runs > 1: run r uses hash(seed, r))")
      ->capture_default_str();
  command->add_option("-n", o->n, "points per run");
  command->add_option("-d", o->d, "dimension (default: the integrand's)");
  command->add_option("--runs", o->runs, "independent randomizations (>= 2: replicate standard error)")
      ->capture_default_str();
  add_threads_option(*command, o->threads, "threads");
  command
      ->add_option("--confidence", o->confidence,
                   "level of the confidence interval, in (0, 1) (Student-t over the runs' replicates)")
      ->capture_default_str();
  command->add_option("--abs-tol", o->abs_tol,
                      "integrate to a tolerance: double n until the interval's half-width <= max(abs-tol, rel-tol x "
                      "|estimate|) (docs/samplers.md)");
  command->add_option("--rel-tol", o->rel_tol, "relative tolerance, in [0, 1) (with or instead of --abs-tol)");
  command->add_option("--max-n", o->max_n, "with a tolerance: the most points per run (default 2^24)");
  command->add_option("--integrand-param", o->integrand_params, "integrand parameter KEY=V1,V2,... (repeatable)");
  command->add_flag("--json", o->json, "print JSON");
  command->add_flag("--list", o->list, "list the integrands and exit");
  command->callback([o] { run_integrate(*o); });
}

}  // namespace stratum::cli
