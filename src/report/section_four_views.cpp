/// §13 Four views of integration: every pattern measured from each of the
/// lecture's four views at the same N — signal processing (its spectrum:
/// the power at low frequencies and the effective Nyquist frequency of
/// Heck, Schlömer & Deussen 2013, "Blue noise sampling with controlled
/// aliasing", and the highest ring of the radial power, whose spikes
/// betray a regular structure), statistical sampling (the variance of its estimates of an
/// edge integral over independent randomizations), quasi-Monte Carlo (star
/// and L2-star discrepancy: Niederreiter 1992; Warnock 1972) and numerical
/// quadrature (its RMSE on a smooth integrand). One table, one rank chart.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "sections.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/analysis/spectrum.hpp"
#include "stratum/registry.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

std::string label(const sa::SamplerChoice& choice) {
  return choice.randomize.empty() ? choice.name : choice.name + ":" + choice.randomize;
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
  for (const char* text : {"random", "jittered", "n-rooks", "multi-jittered", "poisson-disk", "best-candidate",
                           "zaremba:cp", "hammersley", "halton", "sobol:owen", "pmj02"})
    samplers.push_back(sa::parse_sampler_choice(text));
  std::vector<std::string> skipped;
  for (const auto& extra : context.extra_samplers()) {
    if (std::any_of(samplers.begin(), samplers.end(), [&](const auto& s) { return label(s) == label(extra); }))
      continue;
    if (takes(extra, settings.n))
      samplers.push_back(extra);
    else
      skipped.push_back(named_with_spec(extra));
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
              {"pattern"}, {}};
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
    std::vector<std::string> row{named_with_spec(samplers[s])};
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
    return fmt::format("the lowest {} is {}'s ({}; random {})", what,
                       sampler_name(samplers[row_of(best_of(key))]), value_of(best_of(key), key),
                       value_of("random", key));
  };
  section.text.push_back(fmt::format(
      "At N = {}, {}, {}, {} and {}.", settings.n,
      best_sentence("mean spectral power at low frequencies (0 < |k| ≤ √N/2; white noise 1)", "low_frequency_power"),
      best_sentence("edge variance", "edge_variance"), best_sentence("star discrepancy", "star"),
      best_sentence("RMSE on the smooth Gaussian", "smooth_rmse")));
  section.text.push_back(fmt::format(
      "Zaremba's points (here moved by a random Cranley–Patterson shift, which leaves the spectrum unchanged) rank "
      "{} of {} by star discrepancy and {} by the height of their radial power peak ({}; Poisson-disk {}, random "
      "{}); Poisson-disk points rank {} by low-frequency power and {} by star discrepancy.",
      rank_of("zaremba:cp", "star"), samplers.size(), rank_of("zaremba:cp", "peak_power"),
      value_of("zaremba:cp", "peak_power"), value_of("poisson-disk", "peak_power"), value_of("random", "peak_power"),
      rank_of("poisson-disk", "low_frequency_power"), rank_of("poisson-disk", "star")));
  if (!skipped.empty()) {
    std::string list;
    for (const auto& name : skipped) list += (list.empty() ? "" : ", ") + name;
    section.text.push_back(fmt::format("Left out (they cannot make exactly {} points): {}.", settings.n, list));
  }

  nlohmann::json header = nlohmann::json::array();
  for (const auto& column : columns) header.push_back(column.name);
  section.figures.push_back(context.plot(
      "report_four_views",
      {{"patterns", names}, {"views", header}, {"values", chart_values}, {"ranks", chart_ranks}},
      "ranks",
      fmt::format("Each pattern ranked in each view at N = {} (1 = best; colour by rank, the measured value in "
                  "the cell)",
                  settings.n)));
  section.tables.push_back(std::move(table));
  section.try_it = {"stratum spectrum -s poisson-disk -n 1024 -o spectrum.png"};
  return section;
}

}  // namespace stratum::report
