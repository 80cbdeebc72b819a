/// `stratum study dimension`: a product quadrature rule against Monte Carlo
/// (and Owen-scrambled Sobol') on one smooth integrand for d = 1..10
/// (LECTURE.md §6) — error vs N per d and the fitted slopes, as a table,
/// JSON or a figure.
#include <fmt/core.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "sampler_options.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/plot.hpp"
#include "stratum/analysis/dimension_study.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct DimensionOptions {
  std::string dims = "1:10", counts = "16:65536", rule = "midpoint", integrand = "sine-product", plot;
  std::int64_t runs = 16, threads = 0;
  std::uint64_t seed = 0;
  bool json = false, no_sobol = false;
};

/// "A:B" or "A" into [lo, hi]; both integers in [1, max] with lo ≤ hi.
std::pair<std::uint64_t, std::uint64_t> parse_range(const std::string& name, const std::string& text,
                                                    std::uint64_t max) {
  const std::string allowed = "must be A:B or A, integers with 1 <= A <= B <= " + std::to_string(max);
  const auto to_number = [&](const std::string& part) -> std::uint64_t {
    if (part.empty() || part.size() > 12 || part.find_first_not_of("0123456789") != std::string::npos)
      throw invalid_argument(name, text, allowed);
    return std::stoull(part);
  };
  const auto colon = text.find(':');
  const std::uint64_t lo = to_number(text.substr(0, colon));
  const std::uint64_t hi = colon == std::string::npos ? lo : to_number(text.substr(colon + 1));
  require(lo >= 1 && lo <= hi && hi <= max, name, text, allowed);
  return {lo, hi};
}

nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }
nlohmann::json numbers(const std::vector<double>& values) {
  nlohmann::json list = nlohmann::json::array();
  for (double v : values) list.push_back(number(v));
  return list;
}

nlohmann::json to_json(const sa::DimensionStudy& study) {
  nlohmann::json series = nlohmann::json::array();
  for (const auto& s : study.series)
    series.push_back({{"d", s.d},
                      {"exact", s.exact},
                      {"variance", number(s.variance)},
                      {"m", s.m},
                      {"n", s.n},
                      {"product_error", numbers(s.product_error)},
                      {"mc_rmse", numbers(s.mc_rmse)},
                      {"mc_predicted", numbers(s.mc_predicted)},
                      {"sobol_rmse", numbers(s.sobol_rmse)},
                      {"product_slope", number(s.product_slope)},
                      {"product_predicted_slope", number(s.product_predicted_slope)},
                      {"mc_slope", number(s.mc_slope)},
                      {"sobol_slope", number(s.sobol_slope)}});
  return {{"rule", study.rule}, {"integrand", study.integrand}, {"runs", study.runs}, {"series", series}};
}

void run_dimension(const DimensionOptions& o) {
  const auto figure = plot::prepare_plot("plot", o.plot);  // checked before the work
  require(o.runs >= 2 && o.runs <= 100000, "runs", o.runs, "must be in [2, 100000] (an RMSE needs 2 runs)");
  sa::DimensionStudyRequest request;
  const auto [d_lo, d_hi] = parse_range("dims", o.dims, 64);
  const auto [n_lo, n_hi] = parse_range("n", o.counts, std::uint64_t{1} << 24);
  request.min_dim = static_cast<unsigned>(d_lo), request.max_dim = static_cast<unsigned>(d_hi);
  request.min_n = n_lo, request.max_n = n_hi;
  request.runs = static_cast<unsigned>(o.runs);
  request.rule = o.rule;
  request.integrand = o.integrand;
  request.sobol = !o.no_sobol;
  request.seed = o.seed;
  request.threads = static_cast<unsigned>(o.threads);
  const sa::DimensionStudy study = sa::run_dimension_study(request);
  const nlohmann::json data = to_json(study);
  if (figure) plot::write_plot("dimension", data, *figure);
  if (o.json) return fmt::print("{}\n", data.dump(2));
  fmt::print("{} rule vs Monte Carlo on {}, {} runs per (d, N); errors: product |Q - I|, MC and Sobol' RMSE\n",
             study.rule, study.integrand, study.runs);
  for (const auto& s : study.series) {
    fmt::print("\nd = {}: exact {:.17g}; slopes: product {:.3f}", s.d, s.exact, s.product_slope);
    if (std::isfinite(s.product_predicted_slope)) fmt::print(" (theory {:.3f})", s.product_predicted_slope);
    fmt::print(", MC {:.3f} (theory -0.5)", s.mc_slope);
    if (request.sobol) fmt::print(", Sobol' {:.3f}", s.sobol_slope);
    fmt::print("\n{:>6} {:>10} {:>13} {:>13} {:>13}{}\n", "m", "N", "product", "MC", "sigma/sqrt(N)",
               request.sobol ? fmt::format(" {:>13}", "Sobol'") : "");
    for (std::size_t i = 0; i < s.n.size(); ++i)
      fmt::print("{:>6} {:>10} {:>13.4e} {:>13.4e} {:>13.4e}{}\n", s.m[i], s.n[i], s.product_error[i], s.mc_rmse[i],
                 s.mc_predicted[i], request.sobol ? fmt::format(" {:>13.4e}", s.sobol_rmse[i]) : "");
  }
}
}  // namespace

void add_study_dimension_command(CLI::App& study) {
  auto o = std::make_shared<DimensionOptions>();
  auto* command = study.add_subcommand("dimension", "Product quadrature rule vs Monte Carlo as d grows (lecture §6)");
  command->add_option("--dims", o->dims, "dimensions A:B (or one, A)")->capture_default_str();
  command->add_option("--n", o->counts, "range of N = m^d, LO:HI (about one m per doubling)")->capture_default_str();
  command->add_option("--runs", o->runs, "independent MC / RQMC runs per (d, N)")->capture_default_str();
  command->add_option("--rule", o->rule, "product rule: midpoint (order 2) or gauss (Gauss-Legendre)")
      ->capture_default_str();
  command->add_option("--integrand", o->integrand, "sine-product or a smooth registry integrand (genz-gaussian, ...)")
      ->capture_default_str();
  command->add_flag("--no-sobol", o->no_sobol, "leave out the Owen-scrambled Sobol' runs");
  add_seed_option(*command, o->seed, "seed of the random points");
  add_threads_option(*command, o->threads, "threads (results do not depend on it)");
  command->add_flag("--json", o->json, "print JSON");
  command->add_option("--plot", o->plot, "write a figure of error vs N per d (PNG)");
  command->callback([o] { run_dimension(*o); });
}

}  // namespace stratum::cli
