/// §4 Stratified sampling: convergence of the variance of an estimate with N
/// for random, jittered, Owen-scrambled Sobol' and PMJ02 points (plus the
/// --sampler extras) on an edge and on a smooth integrand, with the fitted
/// log-log slopes. The lecture's claim: an edge crossing the square is seen
/// by only the √N strata it crosses, so jittered variance falls as N^-1.5
/// against random's N^-1 (Mitchell 1996, "Consequences of stratified
/// sampling in graphics"); on a smooth integrand jittered reaches N^-2
/// and scrambled (0,2)-sequences N^-3 (Owen 1997, "Scrambled net variance
/// for integrals of smooth functions"; Christensen, Kensler, Kilpatrick
/// 2018, "Progressive multi-jittered sample sequences").
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/registry.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

std::string label(const sa::SamplerChoice& choice) {
  return choice.randomize.empty() ? choice.name : choice.name + ":" + choice.randomize;
}

/// Whether `choice` makes 2D points at every N of `counts` (an extra sampler
/// with its own rules for N is left out rather than failing the report).
bool takes_counts(const sa::SamplerChoice& choice, const std::vector<std::uint64_t>& counts) {
  try {
    const SamplerInfo& info = find_sampler(choice.name);
    for (std::uint64_t n : counts) {
      SamplerRequest request;
      request.n = n;
      request.d = 2;
      request.randomize = choice.randomize;
      validate_request(info, request);
    }
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

/// The quantity whose slope was fitted: the variance, or the MSE for a
/// deterministic sampler (see SamplerConvergence::fitted).
double fitted_value(const sa::SamplerConvergence& entry, const sa::ConvergenceRow& row) {
  return entry.fitted == "mse" ? row.rmse * row.rmse : row.variance;
}

nlohmann::json finite(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

/// The slope with its confidence interval (the jackknife over runs), or with
/// the fit's residual standard error when there is none (deterministic runs).
std::string slope_text(const sa::SamplerConvergence& entry) {
  const sa::SlopeFit& fit = entry.slope;
  if (!std::isfinite(fit.slope)) return "n/a";
  if (std::isfinite(entry.interval.low))
    return format_number(fit.slope) + " (" + format_number(100 * entry.interval.confidence) + "% interval " +
           format_number(entry.interval.low, 2) + " … " + format_number(entry.interval.high, 2) + ")";
  if (!std::isfinite(fit.slope_standard_error)) return format_number(fit.slope);
  return format_number(fit.slope) + " ± " + format_number(fit.slope_standard_error, 2) + " (fit)";
}

const sa::SamplerConvergence& entry_of(const sa::ConvergenceResult& result, const std::string& name) {
  for (const auto& entry : result.samplers)
    if (entry.sampler.name == name) return entry;
  throw std::logic_error("stratification section: no sampler " + name);
}

/// One panel of the figure: each sampler's variance against N, with the
/// lecture's reference rate drawn through the jittered curve's first point.
nlohmann::json panel(const sa::ConvergenceResult& result, const std::string& title, double reference_slope,
                     const std::string& reference_source) {
  nlohmann::json series = nlohmann::json::array();
  for (const auto& entry : result.samplers) {
    std::vector<double> x, y;
    for (const auto& row : entry.rows)
      if (fitted_value(entry, row) > 0) x.push_back(static_cast<double>(row.n)), y.push_back(fitted_value(entry, row));
    series.push_back({{"label", fmt::format("{} ({}{})", sampler_name(entry.sampler), slope_text(entry),
                                            entry.fitted == "mse" ? ", MSE" : "")},
                      {"x", x},
                      {"y", y}});
  }
  const auto& jittered = entry_of(result, "jittered");
  const double n0 = static_cast<double>(jittered.rows.front().n), v0 = jittered.rows.front().variance;
  std::vector<double> x, y;
  for (const auto& row : jittered.rows) {
    x.push_back(static_cast<double>(row.n));
    y.push_back(v0 * std::pow(static_cast<double>(row.n) / n0, reference_slope));
  }
  series.push_back({{"label", fmt::format("∝ N^{:g} ({})", reference_slope, reference_source)},
                    {"x", x},
                    {"y", y},
                    {"reference", true}});
  return {{"title", title}, {"xlabel", "N (points per estimate)"}, {"ylabel", "variance of the estimate"},
          {"xlog", true}, {"ylog", true}, {"series", series}};
}

nlohmann::json to_numbers(const sa::ConvergenceResult& result) {
  nlohmann::json samplers = nlohmann::json::object();
  for (const auto& entry : result.samplers) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : entry.rows)
      rows.push_back({{"n", row.n}, {"variance", row.variance}, {"rmse", row.rmse}, {"mean_error", row.mean_error}});
    samplers[label(entry.sampler)] = {{"slope", finite(entry.slope.slope)},
                                      {"slope_standard_error", finite(entry.slope.slope_standard_error)},
                                      {"slope_interval", {finite(entry.interval.low), finite(entry.interval.high)}},
                                      {"fitted", entry.fitted},
                                      {"rows", rows}};
  }
  return {{"integrand", result.integrand}, {"exact", result.exact}, {"runs", result.runs}, {"samplers", samplers}};
}

}  // namespace

Section stratification_section(SectionContext& context) {
  Section section = context.start();
  std::vector<std::uint64_t> counts;
  for (std::uint64_t n = 16; n <= (context.quick() ? 4096u : 262144u); n *= 4) counts.push_back(n);
  const unsigned runs = context.quick() ? 32 : 64;

  std::vector<sa::SamplerChoice> samplers{
      sa::parse_sampler_choice("random"), sa::parse_sampler_choice("jittered"),
      sa::parse_sampler_choice("sobol:owen"), sa::parse_sampler_choice("pmj02")};
  std::vector<std::string> skipped, skipped_names;  // specs for report.json, human names for the prose
  for (const auto& extra : context.extra_samplers()) {
    const bool duplicate = std::any_of(samplers.begin(), samplers.end(), [&](const sa::SamplerChoice& s) {
      return s.name == extra.name && s.randomize == extra.randomize;
    });
    if (duplicate) continue;
    if (takes_counts(extra, counts))
      samplers.push_back(extra);
    else
      skipped.push_back(label(extra)), skipped_names.push_back(named_with_spec(extra));
  }

  sa::ConvergenceRequest request;
  request.samplers = samplers;
  request.counts = counts;
  request.runs = runs;
  request.seed = context.seed();
  request.threads = context.threads();
  request.integrand.name = "step";
  const sa::ConvergenceResult edge = sa::run_convergence(request);
  request.integrand.name = "gaussian";
  const sa::ConvergenceResult smooth = sa::run_convergence(request);

  Table table{fmt::format("Fitted slopes of log variance against log N (95% interval: jackknife over runs), N = {} … {}, {} runs per N",
                          counts.front(), counts.back(), runs),
              {"sampler", "edge (step) slope", "smooth (gaussian) slope", "edge variance at N = " +
                                                                               std::to_string(counts.back()),
               "smooth variance at N = " + std::to_string(counts.back())},
              {}};
  for (std::size_t s = 0; s < samplers.size(); ++s) {
    const auto& e = edge.samplers[s];
    const auto& g = smooth.samplers[s];
    table.rows.push_back({named_with_spec(e.sampler), slope_text(e) + (e.fitted == "mse" ? " (MSE)" : ""),
                          slope_text(g) + (g.fitted == "mse" ? " (MSE)" : ""),
                          format_number(fitted_value(e, e.rows.back())),
                          format_number(fitted_value(g, g.rows.back()))});
  }
  section.numbers["edge"] = to_numbers(edge);
  section.numbers["smooth"] = to_numbers(smooth);
  section.numbers["counts"] = counts;
  section.numbers["runs"] = runs;
  section.numbers["skipped_extras"] = skipped;

  const auto& random_edge = entry_of(edge, "random");
  const auto& jittered_edge = entry_of(edge, "jittered");
  section.text.push_back(fmt::format(
      "On the edge integrand 1[x < 1/π], the variance of jittered estimates falls with a fitted slope of {} "
      "(the lecture predicts −1.5: only the √N strata the edge crosses contribute) and that of random estimates "
      "with {} (predicted −1); at N = {} random's variance is {}× jittered's.",
      slope_text(jittered_edge), slope_text(random_edge), counts.back(),
      format_number(random_edge.rows.back().variance / jittered_edge.rows.back().variance)));
  const auto& sobol_edge = entry_of(edge, "sobol");
  const auto& pmj_edge = entry_of(edge, "pmj02");
  section.text.push_back(fmt::format(
      "This edge is parallel to an axis, and the (0,2)-sequences stratify x into N intervals: Owen-scrambled "
      "Sobol' reaches {} and PMJ02 {} on it.",
      slope_text(sobol_edge), slope_text(pmj_edge)));
  section.text.push_back(fmt::format(
      "On the smooth Gaussian exp(−x² − y²) the slopes are {} for random, {} for jittered (theory −2), {} for "
      "Owen-scrambled Sobol' and {} for PMJ02 (theory −3 for scrambled nets).",
      slope_text(entry_of(smooth, "random")), slope_text(entry_of(smooth, "jittered")),
      slope_text(entry_of(smooth, "sobol")), slope_text(entry_of(smooth, "pmj02"))));
  if (!skipped.empty()) {
    std::string names;
    for (const auto& name : skipped_names) names += (names.empty() ? "" : ", ") + name;
    section.text.push_back(fmt::format("Left out (they do not take every N of the study): {}.", names));
  }

  const nlohmann::json figure = {
      {"columns", 2},
      {"panels", {panel(edge, "An edge, 1[x < 1/π]", -1.5, "lecture"),
                  panel(smooth, "A smooth integrand, exp(−x² − y²)", -2.0, "jittered, smooth f: theory")}}};
  section.figures.push_back(context.plot(
      "report_lines", figure, "convergence",
      fmt::format("Variance of the estimate against N ({} randomizations per N) on the edge and smooth integrands; "
                  "fitted slopes in the legend; dotted, through jittered's first point: the lecture's N^-1.5 on the edge and "
                  "the theoretical N^-2 of jittered sampling on a smooth integrand (the lecture states no rate there)",
                  runs)));
  section.tables.push_back(std::move(table));
  section.try_it = {"stratum converge --integrand step --samplers random,jittered,sobol:owen,halton:owen --n 16:4096:4 --plot step.png"};
  return section;
}

}  // namespace stratum::report
