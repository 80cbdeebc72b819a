/// §4 Stratified sampling: convergence of the variance of an estimate with N
/// for random, jittered, Owen-scrambled Sobol' and PMJ02 points (plus the
/// --sampler extras) on an edge and on a smooth integrand, with the fitted
/// log-log slopes. The lecture's claim: an edge crossing the square is seen
/// by only the √N strata it crosses, so jittered variance falls as N^-1.5
/// against random's N^-1 (Mitchell 1996, "Consequences of stratified
/// sampling in graphics"); on a smooth integrand jittered reaches N^-2
/// and scrambled (0,2)-sequences N^-3 (Owen 1997, "Scrambled net variance
/// for integrals of smooth functions"; Christensen, Kensler, Kilpatrick
/// 2018, "Progressive multi-jittered sample sequences"). Beside the
/// axis-aligned edge, a slanted one (which no net stratifies along), and on
/// both the exact variance of jittered sampling (jittered_edge.hpp) drawn
/// over the measured one.
#include <fmt/core.h>

#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "jittered_edge.hpp"
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
  if (std::isfinite(entry.interval.low)) {
    const FormattedInterval text = format_alike(fit.slope, entry.interval.low, entry.interval.high);
    return fmt::format("{} ({:g}% interval {} … {})", text.estimate, 100 * entry.interval.confidence, text.low,
                       text.high);
  }
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
                     const std::string& reference_source, const std::vector<double>& predicted = {}) {
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
  if (!predicted.empty())
    series.push_back({{"label", "jittered, exact: Σ a(1 − a) / N² over the cut cells"},
                      {"x", x},
                      {"y", predicted},
                      {"dashed", true}});
  return {{"title", title},
          {"xlabel", "N (points per estimate)"},
          {"ylabel", "variance of the estimate"},
          {"xlog", true},
          {"ylog", true},
          {"series", series}};
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

/// Which edge-random integrand is the slanted edge: seed 10's line crosses
/// the square near its centre at 53.6° to the x axis (far from 0°, 45° and
/// 90°, where grids and nets line up with it).
constexpr std::uint64_t slanted_edge_seed = 10;

Section stratification_section(SectionContext& context) {
  Section section = context.start();
  std::vector<std::uint64_t> counts;
  for (std::uint64_t n = 16; n <= (context.quick() ? 4096u : 262144u); n *= 4) counts.push_back(n);
  const unsigned runs = context.quick() ? 32 : 64;

  std::vector<sa::SamplerChoice> samplers{sa::parse_sampler_choice("random"), sa::parse_sampler_choice("jittered"),
                                          sa::parse_sampler_choice("sobol:owen"), sa::parse_sampler_choice("pmj02")};
  std::vector<std::string> skipped, skipped_names;  // specs for report.json, human names for the prose
  for (const auto& extra : context.extra_samplers()) {
    const bool duplicate = std::any_of(samplers.begin(), samplers.end(), [&](const sa::SamplerChoice& s) {
      return s.name == extra.name && s.randomize == extra.randomize;
    });
    if (duplicate) continue;
    if (takes_counts(extra, counts)) samplers.push_back(extra);
    else skipped.push_back(label(extra)), skipped_names.push_back(named_with_spec(extra));
  }

  sa::ConvergenceRequest request;
  request.samplers = samplers;
  request.counts = counts;
  request.runs = runs;
  request.seed = context.seed();
  request.threads = context.threads();
  request.integrand.name = "step";
  const sa::ConvergenceResult edge = sa::run_convergence(request);
  request.integrand.name = "edge-random";
  request.integrand.params = {{"seed", {double(slanted_edge_seed)}}};
  const sa::ConvergenceResult slanted = sa::run_convergence(request);
  request.integrand.params.clear();
  request.integrand.name = "gaussian";
  const sa::ConvergenceResult smooth = sa::run_convergence(request);

  // The exact jittered variance on both edges, at every N = n².
  const HalfPlane axis_plane{{1 / std::numbers::pi, 0}, {1, 0}};  // the step's 1[x < 1/π]
  const HalfPlane slanted_plane = random_edge_half_plane(slanted_edge_seed);
  if (std::abs(half_plane_area(slanted_plane, 0, 0, 1, 1) - slanted.exact) > 1e-12)
    throw std::logic_error("stratification section: the slanted edge's half-plane is not the edge-random integrand's");
  std::vector<double> axis_predicted, slanted_predicted;
  nlohmann::json prediction = nlohmann::json::array();
  for (const std::uint64_t n : counts) {
    const auto side = static_cast<std::uint64_t>(std::llround(std::sqrt(double(n))));
    axis_predicted.push_back(jittered_edge_variance(axis_plane, side));
    slanted_predicted.push_back(jittered_edge_variance(slanted_plane, side));
  }
  const auto& jittered_axis = entry_of(edge, "jittered");
  const auto& jittered_slanted = entry_of(slanted, "jittered");
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const auto side = static_cast<std::uint64_t>(std::llround(std::sqrt(double(counts[i]))));
    prediction.push_back(
        {{"n", counts[i]},
         {"grid", side},
         {"edge", axis_predicted[i]},
         {"edge_cut_cells", cut_cells(axis_plane, side)},
         {"edge_measured_over_predicted", jittered_axis.rows[i].variance / axis_predicted[i]},
         {"slanted_edge", slanted_predicted[i]},
         {"slanted_edge_cut_cells", cut_cells(slanted_plane, side)},
         {"slanted_edge_measured_over_predicted", jittered_slanted.rows[i].variance / slanted_predicted[i]}});
  }

  Table table{
      fmt::format(
          "Fitted slopes of log variance against log N (95% interval: jackknife over runs), N = {} … {}, {} runs per N",
          counts.front(), counts.back(), runs),
      {"sampler", "axis-aligned edge slope", "slanted edge slope", "smooth (gaussian) slope",
       "axis-aligned edge variance at N = " + std::to_string(counts.back()),
       "slanted edge variance at N = " + std::to_string(counts.back()),
       "smooth variance at N = " + std::to_string(counts.back())},
      {}};
  for (std::size_t s = 0; s < samplers.size(); ++s) {
    const auto& e = edge.samplers[s];
    const auto& l = slanted.samplers[s];
    const auto& g = smooth.samplers[s];
    table.rows.push_back({named_with_spec(e.sampler), slope_text(e) + (e.fitted == "mse" ? " (MSE)" : ""),
                          slope_text(l) + (l.fitted == "mse" ? " (MSE)" : ""),
                          slope_text(g) + (g.fitted == "mse" ? " (MSE)" : ""),
                          format_number(fitted_value(e, e.rows.back())), format_number(fitted_value(l, l.rows.back())),
                          format_number(fitted_value(g, g.rows.back()))});
  }
  Table predicted_table{
      fmt::format("Jittered sampling on the two edges: the exact variance Σ a_i(1 − a_i)/N² (a_i: the part of cell i "
                  "below the edge) against the variance measured over {} runs (whose relative standard error is "
                  "about √(2/{}) = {}%)",
                  runs, runs - 1, format_number(100 * std::sqrt(2.0 / (runs - 1)), 2)),
      {"N", "grid", "axis-aligned: cut cells", "exact", "measured / exact", "slanted: cut cells", "exact",
       "measured / exact"},
      {},
      "jittered-edge"};
  for (const auto& row : prediction)
    predicted_table.rows.push_back(
        {std::to_string(row["n"].get<std::uint64_t>()), fmt::format("{0}×{0}", row["grid"].get<std::uint64_t>()),
         std::to_string(row["edge_cut_cells"].get<std::uint64_t>()), format_number(row["edge"].get<double>()),
         format_number(row["edge_measured_over_predicted"].get<double>()),
         std::to_string(row["slanted_edge_cut_cells"].get<std::uint64_t>()),
         format_number(row["slanted_edge"].get<double>()),
         format_number(row["slanted_edge_measured_over_predicted"].get<double>())});
  section.numbers["edge"] = to_numbers(edge);
  section.numbers["smooth"] = to_numbers(smooth);
  section.numbers["slanted_edge"] = to_numbers(slanted);
  section.numbers["slanted_edge"]["seed"] = slanted_edge_seed;
  section.numbers["slanted_edge"]["point"] = slanted_plane.point;
  section.numbers["slanted_edge"]["normal"] = slanted_plane.normal;
  section.numbers["jittered_prediction"] = prediction;
  section.numbers["counts"] = counts;
  section.numbers["runs"] = runs;
  section.numbers["skipped_extras"] = skipped;

  const auto& random_edge = entry_of(edge, "random");
  // Independent runs: s²_random/s²_jittered over σ²_random/σ²_jittered is F(R − 1, R − 1).
  const double variance_ratio = random_edge.rows.back().variance / entry_of(edge, "jittered").rows.back().variance;
  const boost::math::fisher_f f_distribution(runs - 1.0, runs - 1.0);
  const double f_low = boost::math::quantile(f_distribution, 0.025),
               f_high = boost::math::quantile(f_distribution, 0.975);
  section.numbers["edge_variance_ratio_random_over_jittered"] = {{"estimate", variance_ratio},
                                                                 {"low", variance_ratio / f_high},
                                                                 {"high", variance_ratio / f_low},
                                                                 {"confidence", 0.95}};
  const auto& jittered_edge = entry_of(edge, "jittered");
  const FormattedInterval edge_ratio = format_alike(variance_ratio, variance_ratio / f_high, variance_ratio / f_low);
  section.text.push_back(fmt::format(
      "On the edge integrand 1[x < 1/π], the variance of jittered estimates falls with a fitted slope of {} "
      "(the lecture predicts −1.5: only the √N strata the edge crosses contribute) and that of random estimates "
      "with {} (predicted −1); at N = {} random's variance is {}× jittered's (95% interval {}–{}: the ratio of two "
      "sample variances of {} runs each over the F distribution's quantiles, for near-normal estimates).",
      slope_text(jittered_edge), slope_text(random_edge), counts.back(), edge_ratio.estimate, edge_ratio.low,
      edge_ratio.high, runs));
  const auto& sobol_edge = entry_of(edge, "sobol");
  const auto& pmj_edge = entry_of(edge, "pmj02");
  section.text.push_back(fmt::format(
      "This edge is parallel to an axis, and the (0,2)-sequences stratify x into N intervals: Owen-scrambled "
      "Sobol' reaches {} and PMJ02 {} on it.",
      slope_text(sobol_edge), slope_text(pmj_edge)));
  // "falls to" when the slanted edge's fitted slope is shallower than the axis-aligned one's.
  const auto change = [&](const std::string& name) {
    return entry_of(slanted, name).slope.slope > entry_of(edge, name).slope.slope ? "falls to" : "goes to";
  };
  const double slanted_degrees =
      std::fmod(std::atan2(-slanted_plane.normal[0], slanted_plane.normal[1]) * 180 / std::numbers::pi + 180, 180);
  section.text.push_back(fmt::format(
      "Slanted at {}° to the x axis, the edge is no longer stratified by the (0,2)-sequences' N intervals in x: "
      "Owen-scrambled Sobol' {} {} and PMJ02 {} {}, jittered {} and random {}. Jittered's variance is known "
      "exactly: with one uniform point in each of the N cells, the point of cell i falls below the edge with "
      "probability a_i (the part of the cell below it), so Var = Σ a_i(1 − a_i)/N², which only cut cells feed "
      "— about √N of them, each at most 1/4, hence N^-1.5. Measured over exact it is {} on the axis-aligned edge "
      "and {} on the slanted one (from N = {} to {}; a variance from {} runs of normal estimates has a relative "
      "standard error of about {}%); the wobble of the axis-aligned curve is exact too: its cut column covers "
      "frac(√N/π) of each cell.",
      format_number(slanted_degrees), change("sobol"), slope_text(entry_of(slanted, "sobol")), change("pmj02"),
      slope_text(entry_of(slanted, "pmj02")), slope_text(jittered_slanted), slope_text(entry_of(slanted, "random")),
      [&] {
        double low = 1e300, high = 0;
        for (const auto& row : prediction) {
          low = std::min(low, row["edge_measured_over_predicted"].get<double>());
          high = std::max(high, row["edge_measured_over_predicted"].get<double>());
        }
        return format_number(low) + "–" + format_number(high);
      }(),
      [&] {
        double low = 1e300, high = 0;
        for (const auto& row : prediction) {
          low = std::min(low, row["slanted_edge_measured_over_predicted"].get<double>());
          high = std::max(high, row["slanted_edge_measured_over_predicted"].get<double>());
        }
        return format_number(low) + "–" + format_number(high);
      }(),
      counts.front(), counts.back(), runs, format_number(100 * std::sqrt(2.0 / (runs - 1)), 2)));
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
      {"panels",
       {panel(edge, "An axis-aligned edge, 1[x < 1/π]", -1.5, "lecture", axis_predicted),
        panel(slanted, fmt::format("A slanted edge at {}°", format_number(slanted_degrees)), -1.5, "lecture",
              slanted_predicted),
        panel(smooth, "A smooth integrand, exp(−x² − y²)", -2.0, "jittered, smooth f: theory")}}};
  section.figures.push_back(context.plot(
      "report_lines", figure, "convergence",
      fmt::format(
          "Variance of the estimate against N ({} randomizations per N) on an axis-aligned edge, a slanted "
          "edge and a smooth integrand; fitted slopes in the legend; dashed: jittered's exact variance; dotted, "
          "through jittered's first point: the lecture's N^-1.5 on the edges and "
          "the theoretical N^-2 of jittered sampling on a smooth integrand (the lecture states no rate there)",
          runs)));
  section.tables.push_back(std::move(table));
  section.tables.push_back(std::move(predicted_table));
  section.try_it = {
      "stratum converge --integrand step --samplers random,jittered,sobol:owen,halton:owen --n 16:4096:4 --plot "
      "step.png"};
  return section;
}

}  // namespace stratum::report
