/// §13 Four views of integration: every pattern measured from each of the
/// lecture's four views at the same N — signal processing (its spectrum:
/// the power at low frequencies and the effective Nyquist frequency of
/// Heck, Schlömer & Deussen 2013, "Blue noise sampling with controlled
/// aliasing", and the highest ring of the radial power, whose spikes
/// betray a regular structure), statistical sampling (the variance of its estimates of an
/// edge integral over independent randomizations), quasi-Monte Carlo (star
/// and L2-star discrepancy: Niederreiter 1992; Warnock 1972) and numerical
/// quadrature (its RMSE on a smooth integrand, beside two product rules at
/// the same point count: the midpoint rule and Gauss–Legendre). One table,
/// one rank chart, and where the ranking departs from the lecture's
/// recommendation (jittered and Poisson disk; the periodic Poisson disk, as
/// §10 and §12 use it, beside the plain one).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <boost/math/quadrature/gauss.hpp>
#include <numeric>

#include "sections.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/analysis/spectrum.hpp"
#include "stratum/registry.hpp"
#include "stratum/registry/spec.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

/// The spec with its parameters: "poisson-disk(periodic=1)", "zaremba:cp".
std::string label(const sa::SamplerChoice& choice) {
  return format_sampler_spec({choice.name, choice.params, choice.randomize});
}

/// The human name, "periodic" added for a toroidal pattern, and the spec.
std::string display_name(const sa::SamplerChoice& choice) {
  const auto periodic = choice.params.find("periodic");
  const bool toroidal = periodic != choice.params.end() && periodic->second == "1";
  return sampler_name(choice) + (toroidal ? " (periodic)" : "") + " `" + label(choice) + "`";
}

/// A product rule's error on integrand `name` over [0,1]²: the rule applied
/// in x and in y, n points each (n² in all).
struct ProductRules {
  double midpoint = 0, gauss = 0;
};

template <unsigned N>
double gauss_product(const sa::Integrand& f) {
  using boost::math::quadrature::gauss;
  return gauss<double, N>::integrate(
      [&](double x) {
        return gauss<double, N>::integrate(
            [&](double y) {
              const double point[2] = {x, y};
              double value = 0;
              f.evaluate(point, 1, &value);
              return value;
            },
            0.0, 1.0);
      },
      0.0, 1.0);
}

ProductRules product_rule_errors(const std::string& name, std::uint64_t n_points) {
  const auto f = sa::make_integrand(name, 2);
  const auto side = static_cast<unsigned>(std::llround(std::sqrt(double(n_points))));
  std::vector<double> points;
  for (unsigned i = 0; i < side; ++i)
    for (unsigned j = 0; j < side; ++j) points.push_back((i + 0.5) / side), points.push_back((j + 0.5) / side);
  std::vector<double> values(std::size_t(side) * side);
  f->evaluate(points.data(), values.size(), values.data());
  ProductRules errors;
  errors.midpoint = std::abs(std::accumulate(values.begin(), values.end(), 0.0) / double(values.size()) - f->exact());
  // Gauss–Legendre nodes are templated on their count: the two sizes the report uses.
  if (side == 16) errors.gauss = std::abs(gauss_product<16>(*f) - f->exact());
  else if (side == 32) errors.gauss = std::abs(gauss_product<32>(*f) - f->exact());
  else throw std::logic_error("four views: no Gauss–Legendre rule of " + std::to_string(side) + " points");
  return errors;
}

/// One pattern's four views.
struct Views {
  double low_power = 0;          ///< mean radial power at frequencies ≤ ½ (units of the mean spacing)
  double effective_nyquist = 0;  ///< normalized by √N
  bool nyquist_lower_bound = false;
  double peak_power = 0;         ///< highest ring of the radial power: spikes mean structured aliasing
  double edge_variance = 0;      ///< sample variance of the edge estimates over the runs
  double star = 0, l2_star = 0;  ///< mean over the realizations
  double smooth_rmse = 0;        ///< sqrt(mean squared error) on the smooth integrand
};

struct Settings {
  std::uint64_t n;
  unsigned runs;          ///< randomizations for the variance and the RMSE
  unsigned realizations;  ///< point sets for the spectrum and the discrepancies
  int max_frequency;
};

double integrate_runs(const sa::SamplerChoice& sampler, const std::string& integrand, const Settings& settings,
                      std::uint64_t seed, unsigned threads, bool variance) {
  sa::IntegrationRequest request;
  request.integrand.name = integrand;
  request.sampler = sampler;
  request.n = settings.n;
  request.runs = settings.runs;
  request.seed = seed;
  request.threads = threads;
  const sa::IntegrationResult result = sa::integrate(request);
  const auto& estimates = result.run_estimates;
  double sum = 0;
  if (variance) {
    const double mean =
        std::accumulate(estimates.begin(), estimates.end(), 0.0) / static_cast<double>(estimates.size());
    for (double e : estimates) sum += (e - mean) * (e - mean);
    return sum / static_cast<double>(estimates.size() - 1);
  }
  for (double e : estimates) sum += (e - result.exact) * (e - result.exact);
  return std::sqrt(sum / static_cast<double>(estimates.size()));
}

Views measure_views(const sa::SamplerChoice& sampler, const Settings& settings, std::uint64_t seed, unsigned threads) {
  Views views;
  std::vector<PointSet> sets;
  std::vector<sa::PointView> realizations;
  for (unsigned r = 0; r < settings.realizations; ++r) {
    SamplerRequest request;
    request.n = settings.n;
    request.d = 2;
    request.seed = seed + 7919 * (r + 1);
    request.randomize = sampler.randomize;
    request.params = sampler.params;
    sets.push_back(generate_points(sampler.name, request));
    realizations.push_back({sets.back().data.get(), sets.back().n, sets.back().d});
  }
  const sa::Periodogram periodogram = sa::mean_periodogram(realizations, settings.max_frequency, threads);
  const sa::RadialPower radial = sa::radial_average(periodogram);
  double weighted = 0, count = 0;
  for (std::size_t r = 0; r < radial.frequency.size(); ++r)
    if (radial.frequency[r] <= 0.5) weighted += radial.power[r] * radial.count[r], count += radial.count[r];
  views.low_power = weighted / count;
  views.peak_power = *std::max_element(radial.power.begin(), radial.power.end());
  const sa::BlueNoiseFigures figures = sa::blue_noise_figures(radial);
  views.effective_nyquist = figures.effective_nyquist;
  views.nyquist_lower_bound = figures.nyquist_is_lower_bound;

  sa::MeasureRequest measure;
  measure.threads = threads;
  for (const auto& view : realizations) {
    views.star += sa::compute_measure("star", view, measure).value / settings.realizations;
    views.l2_star += sa::compute_measure("l2-star", view, measure).value / settings.realizations;
  }
  views.edge_variance = integrate_runs(sampler, "disk", settings, seed, threads, true);
  views.smooth_rmse = integrate_runs(sampler, "gaussian", settings, seed + 1, threads, false);
  return views;
}

/// Whether `choice` makes exactly n 2D points (extras that cannot are left out).
bool takes(const sa::SamplerChoice& choice, std::uint64_t n) {
  try {
    SamplerRequest request;
    request.n = n;
    request.d = 2;
    request.randomize = choice.randomize;
    validate_request(find_sampler(choice.name), request);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

/// A rule's error, or "under 1e-14 (rounding)" at the level of double rounding.
std::string rule_error(double error) { return error < 1e-14 ? "under 1e-14 (rounding)" : format_number(error); }

/// 1-based ranks, 1 for the best (ties share the better rank).
std::vector<int> ranks(const std::vector<double>& values, bool higher_is_better) {
  std::vector<int> result(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    int better = 0;
    for (double other : values) better += higher_is_better ? other > values[i] : other < values[i];
    result[i] = better + 1;
  }
  return result;
}

}  // namespace

Section four_views_section(SectionContext& context) {
  Section section = context.start();
  const Settings settings = context.quick() ? Settings{256, 16, 4, 32} : Settings{1024, 64, 16, 64};
  std::vector<sa::SamplerChoice> samplers;
  for (const char* text :
       {"random", "jittered", "n-rooks", "multi-jittered", "poisson-disk", "poisson-disk(periodic=1)", "best-candidate",
        "zaremba:cp", "hammersley", "halton", "sobol:owen", "pmj02"})
    samplers.push_back(sa::parse_sampler_choice(text));
  std::vector<std::string> skipped;
  for (const auto& extra : context.extra_samplers()) {
    if (std::any_of(samplers.begin(), samplers.end(), [&](const auto& s) { return label(s) == label(extra); }))
      continue;
    if (takes(extra, settings.n)) samplers.push_back(extra);
    else skipped.push_back(display_name(extra));
  }

  std::vector<Views> views;
  for (const auto& sampler : samplers)
    views.push_back(measure_views(sampler, settings, context.seed(), context.threads()));

  struct Column {
    std::string name, key;
    bool higher_is_better;
    double Views::*value;
  };
  const std::vector<Column> columns{
      {"low-frequency power (spectrum)", "low_frequency_power", false, &Views::low_power},
      {"effective Nyquist / √N (spectrum)", "effective_nyquist", true, &Views::effective_nyquist},
      {"radial power peak (spectrum)", "peak_power", false, &Views::peak_power},
      {"edge variance (statistics)", "edge_variance", false, &Views::edge_variance},
      {"star discrepancy (QMC)", "star", false, &Views::star},
      {"L2-star discrepancy (QMC)", "l2_star", false, &Views::l2_star},
      {"smooth RMSE (quadrature)", "smooth_rmse", false, &Views::smooth_rmse}};

  Table table{fmt::format("Four views of each pattern at N = {}: spectrum over {} sets, variance and RMSE over {} "
                          "randomizations, discrepancies averaged over {} sets (rank among the patterns in brackets)",
                          settings.n, settings.realizations, settings.runs, settings.realizations),
              {"pattern"},
              {}};
  for (const auto& column : columns) table.header.push_back(column.name);
  std::vector<std::vector<int>> column_ranks;
  for (const auto& column : columns) {
    std::vector<double> values;
    for (const auto& v : views) values.push_back(v.*column.value);
    column_ranks.push_back(ranks(values, column.higher_is_better));
  }
  nlohmann::json chart_values = nlohmann::json::array(), chart_ranks = nlohmann::json::array();
  std::vector<std::string> names;
  for (std::size_t s = 0; s < samplers.size(); ++s) {
    names.push_back(label(samplers[s]));
    std::vector<std::string> row{display_name(samplers[s])};
    nlohmann::json values = nlohmann::json::array(), row_ranks = nlohmann::json::array();
    nlohmann::json entry;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double value = views[s].*columns[c].value;
      const bool bound = columns[c].key == "effective_nyquist" && views[s].nyquist_lower_bound;
      row.push_back(fmt::format("{}{} ({})", bound ? "≥ " : "", format_number(value), column_ranks[c][s]));
      values.push_back(value);
      row_ranks.push_back(column_ranks[c][s]);
      entry[columns[c].key] = value;
      entry[columns[c].key + "_rank"] = column_ranks[c][s];
    }
    entry["nyquist_is_lower_bound"] = views[s].nyquist_lower_bound;
    section.numbers["patterns"][names.back()] = entry;
    table.rows.push_back(row);
    chart_values.push_back(values);
    chart_ranks.push_back(row_ranks);
  }
  section.numbers["n"] = settings.n;
  section.numbers["runs"] = settings.runs;
  section.numbers["realizations"] = settings.realizations;
  section.numbers["edge_integrand"] = "disk";
  section.numbers["smooth_integrand"] = "gaussian";
  section.numbers["skipped_extras"] = skipped;

  // The text: who is best in each view, from the measured ranks.
  const auto column_of = [&](const std::string& key) {
    return static_cast<std::size_t>(
        std::find_if(columns.begin(), columns.end(), [&](const Column& c) { return c.key == key; }) - columns.begin());
  };
  const auto row_of = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const auto best_of = [&](const std::string& key) {
    const auto& r = column_ranks[column_of(key)];
    return names[static_cast<std::size_t>(std::find(r.begin(), r.end(), 1) - r.begin())];
  };
  const auto value_of = [&](const std::string& name, const std::string& key) {
    return format_number(views[row_of(name)].*columns[column_of(key)].value);
  };
  const auto rank_of = [&](const std::string& name, const std::string& key) {
    return column_ranks[column_of(key)][row_of(name)];
  };
  const auto best_sentence = [&](const std::string& what, const std::string& key) {
    return fmt::format("the lowest {} is {}'s ({}; random {})", what, sampler_name(samplers[row_of(best_of(key))]),
                       value_of(best_of(key), key), value_of("random", key));
  };
  section.text.push_back(fmt::format(
      "At N = {}, {}, {}, {} and {}.", settings.n,
      best_sentence("mean spectral power at low frequencies (0 < |k| ≤ √N/2; white noise 1)", "low_frequency_power"),
      best_sentence("edge variance", "edge_variance"), best_sentence("star discrepancy", "star"),
      best_sentence("RMSE on the smooth Gaussian", "smooth_rmse")));
  section.text.push_back(fmt::format(
      "Zaremba's points (here moved by a random Cranley–Patterson shift, which leaves the spectrum unchanged) rank "
      "{} of {} by star discrepancy and {} by the height of their radial power peak ({}; Poisson-disk {}, random "
      "{}); the plain (not periodic) Poisson-disk points rank {} by low-frequency power and {} by star "
      "discrepancy.",
      rank_of("zaremba:cp", "star"), samplers.size(), rank_of("zaremba:cp", "peak_power"),
      value_of("zaremba:cp", "peak_power"), value_of("poisson-disk", "peak_power"), value_of("random", "peak_power"),
      rank_of("poisson-disk", "low_frequency_power"), rank_of("poisson-disk", "star")));
  // The quadrature view's own rules, at the same N: product midpoint and
  // product Gauss–Legendre (√N nodes a side), on the smooth Gaussian and on
  // the quarter disk (the edge view's integrand).
  const ProductRules gaussian_rules = product_rule_errors("gaussian", settings.n);
  const ProductRules disk_rules = product_rule_errors("disk", settings.n);
  const auto side = static_cast<unsigned>(std::llround(std::sqrt(double(settings.n))));
  section.numbers["quadrature"] = {
      {"grid", side},
      {"midpoint", {{"gaussian_error", gaussian_rules.midpoint}, {"disk_error", disk_rules.midpoint}}},
      {"gauss_legendre", {{"gaussian_error", gaussian_rules.gauss}, {"disk_error", disk_rules.gauss}}}};
  Table quadrature{fmt::format("The quadrature view at N = {}: two product rules ({} nodes a side) beside the patterns "
                               "(RMSE over {} randomizations on the Gaussian; √variance on the quarter disk, whose "
                               "randomized estimates are unbiased)",
                               settings.n, side, settings.runs),
                   {"rule or pattern", "error on exp(−x² − y²)", "error on the quarter disk"},
                   {}};
  quadrature.rows.push_back({fmt::format("product Gauss–Legendre, {0}×{0}", side), rule_error(gaussian_rules.gauss),
                             rule_error(disk_rules.gauss)});
  quadrature.rows.push_back({fmt::format("product midpoint rule, {0}×{0}", side), rule_error(gaussian_rules.midpoint),
                             rule_error(disk_rules.midpoint)});
  std::vector<std::size_t> by_smooth(samplers.size());
  std::iota(by_smooth.begin(), by_smooth.end(), std::size_t(0));
  std::sort(by_smooth.begin(), by_smooth.end(),
            [&](std::size_t a, std::size_t b) { return views[a].smooth_rmse < views[b].smooth_rmse; });
  for (const std::size_t s : by_smooth)
    quadrature.rows.push_back({display_name(samplers[s]), format_number(views[s].smooth_rmse),
                               format_number(std::sqrt(views[s].edge_variance))});
  const std::size_t beaten_by_midpoint = std::size_t(std::count_if(
      views.begin(), views.end(), [&](const Views& v) { return v.smooth_rmse > gaussian_rules.midpoint; }));
  const auto beating = [&](double error) {  // patterns whose disk error is below `error`
    return std::size_t(
        std::count_if(views.begin(), views.end(), [&](const Views& v) { return std::sqrt(v.edge_variance) < error; }));
  };
  section.text.push_back(fmt::format(
      "The quadrature view's own rules at the same {} points: product Gauss–Legendre integrates the smooth Gaussian "
      "to {} and the midpoint rule to {} (better than {} of the {} patterns' RMSE; the best pattern, {}, reaches {}). "
      "On the quarter disk, whose curved edge no product rule follows, Gauss–Legendre's error is {} ({} of the "
      "patterns do better) and the midpoint rule's {} ({} do better).",
      settings.n, rule_error(gaussian_rules.gauss), rule_error(gaussian_rules.midpoint), beaten_by_midpoint,
      samplers.size(), sampler_name(samplers[by_smooth.front()]), format_number(views[by_smooth.front()].smooth_rmse),
      rule_error(disk_rules.gauss), beating(disk_rules.gauss), rule_error(disk_rules.midpoint),
      beating(disk_rules.midpoint)));

  // Where the ranking departs from the lecture's "jittered and Poisson disk
  // are recommended": mean rank over the seven measures.
  std::vector<double> mean_rank(samplers.size(), 0);
  for (std::size_t s = 0; s < samplers.size(); ++s) {
    for (const auto& r : column_ranks) mean_rank[s] += double(r[s]) / double(column_ranks.size());
    section.numbers["patterns"][names[s]]["mean_rank"] = mean_rank[s];
  }
  std::vector<std::size_t> order(samplers.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mean_rank[a] < mean_rank[b]; });
  const auto place = [&](const std::string& name) {
    return std::size_t(std::find(order.begin(), order.end(), row_of(name)) - order.begin()) + 1;
  };
  std::string leaders;
  for (std::size_t k = 0; k < std::min<std::size_t>(3, order.size()); ++k)
    leaders += (k == 0                                            ? ""
                : k + 1 == std::min<std::size_t>(3, order.size()) ? " and "
                                                                  : ", ") +
               fmt::format("{} ({})", sampler_name(samplers[order[k]]), format_number(mean_rank[order[k]], 2));
  const std::string periodic = "poisson-disk(periodic=1)";
  // Do the (0,2)-sequences outrank both recommended patterns in every
  // non-spectral view?
  bool nets_ahead = true;
  for (const char* key : {"edge_variance", "star", "l2_star", "smooth_rmse"})
    for (const char* net : {"sobol:owen", "pmj02"})
      nets_ahead =
          nets_ahead && rank_of(net, key) < rank_of("jittered", key) && rank_of(net, key) < rank_of(periodic, key);
  section.numbers["nets_ahead_outside_the_spectrum"] = nets_ahead;
  section.text.push_back(fmt::format(
      "The lecture recommends jittered and Poisson-disk patterns. Averaged over the seven measures, the best mean "
      "ranks are {}; jittered places {} of {} (mean rank {}), the periodic Poisson disk {} ({}) and the plain one {} "
      "({}). In low-frequency power the periodic Poisson disk ranks {} and jittered {}; by effective Nyquist "
      "frequency {} and {} (the plain Poisson disk, whose spectrum also sees the square's boundary, {}). In the "
      "statistical, QMC and quadrature views (edge variance, star discrepancy, smooth RMSE) Owen-scrambled Sobol' "
      "ranks {}, {} and {} and PMJ02 {}, {} and {}, against jittered's {}, {} and {} and the periodic Poisson "
      "disk's {}, {} and {}. {}",
      leaders, place("jittered"), samplers.size(), format_number(mean_rank[row_of("jittered")], 2), place(periodic),
      format_number(mean_rank[row_of(periodic)], 2), place("poisson-disk"),
      format_number(mean_rank[row_of("poisson-disk")], 2), rank_of(periodic, "low_frequency_power"),
      rank_of("jittered", "low_frequency_power"), rank_of(periodic, "effective_nyquist"),
      rank_of("jittered", "effective_nyquist"), rank_of("poisson-disk", "effective_nyquist"),
      rank_of("sobol:owen", "edge_variance"), rank_of("sobol:owen", "star"), rank_of("sobol:owen", "smooth_rmse"),
      rank_of("pmj02", "edge_variance"), rank_of("pmj02", "star"), rank_of("pmj02", "smooth_rmse"),
      rank_of("jittered", "edge_variance"), rank_of("jittered", "star"), rank_of("jittered", "smooth_rmse"),
      rank_of(periodic, "edge_variance"), rank_of(periodic, "star"), rank_of(periodic, "smooth_rmse"),
      nets_ahead ? "So the ranking departs from the lecture outside the spectrum: the scrambled (0,2)-sequences, "
                   "later than the lecture's sources, stratify every elementary interval at once and beat both "
                   "recommended patterns in every non-spectral measure; the case for the recommended patterns rests on "
                   "the spectrum."
                 : "The scrambled (0,2)-sequences do not beat both recommended patterns in every non-spectral measure "
                   "here, so the lecture's recommendation holds up beyond the spectrum."));
  if (!skipped.empty()) {
    std::string list;
    for (const auto& name : skipped) list += (list.empty() ? "" : ", ") + name;
    section.text.push_back(fmt::format("Left out (they cannot make exactly {} points): {}.", settings.n, list));
  }

  nlohmann::json header = nlohmann::json::array();
  for (const auto& column : columns) header.push_back(column.name);
  section.figures.push_back(context.plot(
      "report_four_views", {{"patterns", names}, {"views", header}, {"values", chart_values}, {"ranks", chart_ranks}},
      "ranks",
      fmt::format("Each pattern ranked in each view at N = {} (1 = best; colour by rank, the measured value in "
                  "the cell)",
                  settings.n)));
  section.tables.push_back(std::move(table));
  section.tables.push_back(std::move(quadrature));
  section.try_it = {"stratum spectrum -s poisson-disk -n 1024 -o spectrum.png"};
  return section;
}

}  // namespace stratum::report
