/// `stratum study mis`: multiple importance sampling measured (Veach 1997,
/// §9.2) — a Phong lobe lit by a round light, by light sampling, BSDF
/// sampling and their combinations by the balance and power heuristics, as
/// the lobe sharpens and the light grows: per-sample variances (measured and
/// predicted), as a table or JSON.
#include <fmt/core.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/analysis/mis_study.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct MisOptions {
  std::int64_t runs = 16, samples = 1024, threads = 0;
  std::vector<double> exponents{1, 10, 100, 1000}, angles{2, 10, 30, 60};
  double beta = 2;
  std::uint64_t seed = 0;
  bool json = false;
};

nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

void run_mis(const MisOptions& o) {
  require(o.runs >= 2 && o.runs <= 100000, "runs", o.runs, "must be in [2, 100000] (a standard error needs 2 runs)");
  require(o.samples >= 4 && o.samples <= (std::int64_t{1} << 32), "samples", o.samples, "must be even, in [4, 2^32]");
  sa::MisStudyRequest request;
  request.exponents = o.exponents;
  request.angles = o.angles;
  request.runs = static_cast<unsigned>(o.runs);
  request.samples = static_cast<std::uint64_t>(o.samples);
  request.beta = o.beta;
  request.seed = o.seed;
  request.threads = static_cast<unsigned>(o.threads);
  const sa::MisStudy study = sa::run_mis_study(request);
  if (o.json) {
    nlohmann::json cases = nlohmann::json::array();
    for (const auto& c : study.cases) {
      nlohmann::json methods = nlohmann::json::array();
      for (const auto& m : c.methods)
        methods.push_back({{"method", m.method},
                           {"estimate", m.estimate},
                           {"estimate_stderr", m.estimate_stderr},
                           {"variance", m.variance},
                           {"variance_stderr", m.variance_stderr},
                           {"predicted_variance", m.predicted_variance}});
      cases.push_back({{"exponent", c.exponent},
                       {"angle", c.angle},
                       {"exact", c.exact},
                       {"methods", methods},
                       {"best_single", c.best_single},
                       {"balance_over_best", number(c.balance_over_best)},
                       {"power_over_best", number(c.power_over_best)},
                       {"balance_bound", c.balance_bound}});
    }
    const nlohmann::json out = {
        {"runs", study.runs}, {"samples", study.samples}, {"beta", study.beta}, {"cases", cases}};
    return io::write_stdout([&](std::ostream& stream) { stream << out.dump(2) << '\n'; });
  }
  fmt::print(
      "reflected radiance of a Phong lobe (exponent e) from a round light (half-angle a, radiance 1);\n"
      "per-sample variances over {} runs x {} samples (MIS: half from each strategy, power beta = {}); "
      "(predicted)\n\n",
      study.runs, study.samples, study.beta);
  fmt::print("{:>7} {:>6} {:>10}  {:>21} {:>21} {:>21} {:>21} {:>9} {:>9}\n", "e", "a(deg)", "exact", "light", "bsdf",
             "balance", "power", "bal/best", "pow/best");
  for (const auto& c : study.cases) {
    fmt::print("{:>7.4g} {:>6.3g} {:>10.5g} ", c.exponent, c.angle, c.exact);
    for (const auto& m : c.methods)
      fmt::print(" {:>21}", fmt::format("{:.3e} ({:.3e})", m.variance, m.predicted_variance));
    fmt::print(" {:>9.3g} {:>9.3g}\n", c.balance_over_best, c.power_over_best);
  }
}
}  // namespace

void add_study_mis_command(CLI::App& study) {
  auto o = std::make_shared<MisOptions>();
  auto* command = study.add_subcommand(
      "mis", "Multiple importance sampling: light vs BSDF sampling vs the balance and power heuristics (Veach 1997)");
  command->add_option("--exponents", o->exponents, "Phong exponents e (sharper lobes: larger)")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--angles", o->angles, "light half-angles in degrees, in (0, 90]")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--runs", o->runs, "independent replicates per method")->capture_default_str();
  command->add_option("--samples", o->samples, "samples per replicate (even: MIS takes half from each strategy)")
      ->capture_default_str();
  command->add_option("--beta", o->beta, "the power heuristic's exponent")->capture_default_str();
  add_seed_option(*command, o->seed, "seed of the random numbers");
  add_threads_option(*command, o->threads, "threads (results do not depend on it)");
  command->add_flag("--json", o->json, "print JSON");
  command->callback([o] { run_mis(*o); });
}

}  // namespace stratum::cli
