/// §6 High dimensions: a product quadrature rule against Monte Carlo (and
/// Owen-scrambled Sobol') on the same smooth integrand as d grows. A rule of
/// order r with m points per axis costs N = m^d evaluations, so its error
/// falls as N^(−r/d) (the lecture's N^(−1/d) for r = 1; the midpoint rule
/// has r = 2), while Monte Carlo's RMSE is σ/√N in every dimension
/// (Metropolis & Ulam 1949, "The Monte Carlo method"). The study itself is
/// analysis::run_dimension_study (src/analysis/include/stratum/analysis/dimension_study.hpp).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include "stratum/analysis/dimension_study.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

nlohmann::json finite(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

nlohmann::json finite_list(const std::vector<double>& values) {
  nlohmann::json list = nlohmann::json::array();
  for (double v : values) list.push_back(finite(v));
  return list;
}

/// The JSON of `stratum study dimension --plot` (the dimension.py script reads it).
nlohmann::json plot_data(const sa::DimensionStudy& study) {
  nlohmann::json series = nlohmann::json::array();
  for (const auto& s : study.series)
    series.push_back({{"d", s.d},
                      {"n", s.n},
                      {"product_error", finite_list(s.product_error)},
                      {"mc_rmse", finite_list(s.mc_rmse)},
                      {"mc_predicted", finite_list(s.mc_predicted)},
                      {"sobol_rmse", finite_list(s.sobol_rmse)},
                      {"product_slope", finite(s.product_slope)},
                      {"mc_slope", finite(s.mc_slope)},
                      {"sobol_slope", finite(s.sobol_slope)}});
  return {{"rule", study.rule}, {"integrand", study.integrand}, {"runs", study.runs}, {"series", series}};
}

}  // namespace

Section dimension_section(SectionContext& context) {
  Section section = context.start();
  sa::DimensionStudyRequest request;
  request.min_dim = 1;
  request.max_dim = context.quick() ? 6 : 10;
  request.min_n = 16;
  request.max_n = context.quick() ? (1u << 14) : (1u << 19);
  request.runs = context.quick() ? 8 : 24;
  request.rule = "midpoint";
  request.integrand = "sine-product";
  request.sobol = true;
  request.seed = context.seed();
  request.threads = context.threads();
  const sa::DimensionStudy study = sa::run_dimension_study(request);

  Table table{
      fmt::format("Fitted log-log slopes of the error against N per dimension ({} product rule; MC and "
                  "Sobol' RMSE over {} runs), and the errors at the largest N",
                  study.rule, study.runs),
      {"d", "N", "product slope", "−2/d", "MC slope", "Sobol' slope", "product error", "MC RMSE", "Sobol' RMSE"},
      {}};
  nlohmann::json per_dimension = nlohmann::json::array();
  int first_mc_win = 0;  // the first d where MC's RMSE at the largest N is below the product rule's error
  for (const auto& s : study.series) {
    const std::size_t last = s.n.size() - 1;
    const bool mc_wins = s.mc_rmse[last] < s.product_error[last];
    if (mc_wins && first_mc_win == 0) first_mc_win = static_cast<int>(s.d);
    table.rows.push_back({std::to_string(s.d), fmt::format("{} … {}", s.n.front(), s.n.back()),
                          format_number(s.product_slope), format_number(s.product_predicted_slope),
                          format_number(s.mc_slope), format_number(s.sobol_slope), format_number(s.product_error[last]),
                          format_number(s.mc_rmse[last]), format_number(s.sobol_rmse[last])});
    per_dimension.push_back({{"d", s.d},
                             {"m", s.m},
                             {"n", s.n},
                             {"product_error", finite_list(s.product_error)},
                             {"mc_rmse", finite_list(s.mc_rmse)},
                             {"sobol_rmse", finite_list(s.sobol_rmse)},
                             {"product_slope", finite(s.product_slope)},
                             {"product_predicted_slope", finite(s.product_predicted_slope)},
                             {"mc_slope", finite(s.mc_slope)},
                             {"sobol_slope", finite(s.sobol_slope)},
                             {"mc_wins_at_largest_n", mc_wins}});
  }
  section.numbers["rule"] = study.rule;
  section.numbers["integrand"] = study.integrand;
  section.numbers["runs"] = study.runs;
  section.numbers["dimensions"] = per_dimension;
  section.numbers["first_dimension_mc_wins"] = first_mc_win;

  const auto& first = study.series.front();
  const auto& last = study.series.back();
  section.text.push_back(fmt::format(
      "On the sine product Π (π/2) sin(πx_j) (integral 1), the {} rule's error falls with a fitted slope of {} "
      "in d = {} (its order 2 gives −2/d = {}) but only {} in d = {} (−2/d = {}): N = m^d points buy m per axis.",
      study.rule, format_number(first.product_slope), first.d, format_number(first.product_predicted_slope),
      format_number(last.product_slope), last.d, format_number(last.product_predicted_slope)));
  double mc_lowest = first.mc_slope, mc_highest = first.mc_slope;
  for (const auto& s : study.series) {
    mc_lowest = std::min(mc_lowest, s.mc_slope);
    mc_highest = std::max(mc_highest, s.mc_slope);
  }
  section.text.push_back(fmt::format(
      "Monte Carlo's RMSE has fitted slopes between {} and {} over d = {} … {} (σ/√N predicts −1/2 in every "
      "dimension); those of Owen-scrambled Sobol' points go from {} in d = {} to {} in d = {}.",
      format_number(mc_lowest), format_number(mc_highest), first.d, last.d, format_number(first.sobol_slope), first.d,
      format_number(last.sobol_slope), last.d));
  section.text.push_back(
      first_mc_win > 0
          ? fmt::format("At the largest N of each dimension, Monte Carlo's RMSE is first below the product rule's "
                        "error in d = {}.",
                        first_mc_win)
          : fmt::format("At the largest N of each dimension up to d = {}, the product rule's error stays below "
                        "Monte Carlo's RMSE.",
                        last.d));
  section.figures.push_back(context.plot(
      "dimension", plot_data(study), "errors",
      fmt::format("Error against N for d = {} … {}: {} product rule, Monte Carlo RMSE (dotted: σ/√N exactly) and "
                  "Owen-scrambled Sobol' RMSE; fitted slopes in the legends",
                  first.d, last.d, study.rule)));
  section.tables.push_back(std::move(table));
  section.try_it = {"stratum study dimension --plot dimension.png"};
  return section;
}

}  // namespace stratum::report
