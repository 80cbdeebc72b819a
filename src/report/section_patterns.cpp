/// §12 Comparing patterns: Mitchell's (1992, "Ray tracing and
/// irregularities of distribution") random-edge discrepancy of Zaremba,
/// jittered, Poisson-disk, N-rooks and random patterns at 16, 256 and 1600
/// points, each pattern's points and radially averaged power spectrum, and
/// the --sampler extras run through the same study.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include <numbers>

#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/edge_discrepancy.hpp"
#include "stratum/analysis/mitchell_study.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

/// The --sampler extras as study patterns, leaving out any already among Mitchell's five.
std::vector<sa::MitchellPattern> extra_patterns(const SectionContext& context) {
  std::vector<sa::MitchellPattern> extras;
  for (const auto& choice : context.extra_samplers()) {
    sa::MitchellPattern pattern{capitalized(sampler_name(choice)), choice.name, choice.params, choice.randomize};
    const std::string id = sa::mitchell_pattern_id(pattern);
    const auto same = [&](const sa::MitchellPattern& p) { return sa::mitchell_pattern_id(p) == id; };
    if (std::none_of(sa::mitchell_patterns().begin(), sa::mitchell_patterns().end(), same) &&
        std::none_of(extras.begin(), extras.end(), same))
      extras.push_back(std::move(pattern));
  }
  return extras;
}

/// Mitchell's (1992) table as the lecture prints it: RMS discrepancy of
/// random edges at 16, 256 and 1600 points, by registry pattern id.
struct PublishedRow {
  const char* id;
  double values[3];
};
constexpr std::size_t published_counts[3] = {16, 256, 1600};
constexpr PublishedRow mitchell_1992[] = {{"zaremba", {0.0504, 0.00478, 0.00111}},
                                          {"jittered", {0.0538, 0.00595, 0.00146}},
                                          {"poisson-disk", {0.0613, 0.00767, 0.00241}},
                                          {"n-rooks", {0.0637, 0.0123, 0.00488}},
                                          {"random", {0.0924, 0.0224, 0.00866}}};

}  // namespace

/// E[A(1 − A)] over the motion-invariant measure of lines hitting the unit
/// square (density dp dθ, θ ∈ [0, π), p over the square's projection), A the
/// area on one side: for N independent uniform points the count on one side
/// is binomial, so E[D²] = E[A(1 − A)]/N exactly and the expected RMS of
/// random points is √(E[A(1 − A)]/N). Midpoint rule, `steps` × `steps`.
double expected_binomial_edge_variance(int steps) {
  double weighted = 0, width_total = 0;
  for (int i = 0; i < steps; ++i) {
    const double angle = std::numbers::pi * (i + 0.5) / steps;
    const double nx = std::cos(angle), ny = std::sin(angle);
    const double lo = std::min(0.0, nx) + std::min(0.0, ny), hi = std::max(0.0, nx) + std::max(0.0, ny);
    double sum = 0;
    for (int j = 0; j < steps; ++j) {
      const double area = sa::half_plane_area(nx, ny, lo + (hi - lo) * (j + 0.5) / steps);
      sum += area * (1 - area);
    }
    weighted += (hi - lo) * sum / steps;
    width_total += hi - lo;
  }
  return weighted / width_total;
}

namespace {

/// Our values beside Mitchell's: the table, report.json's "mitchell_1992"
/// and the sentences on where they differ.
void add_published_comparison(Section& section, double expected_c) {
  Table table{
      "Beside the lecture: Mitchell's (1992) random-edge discrepancy as printed, ours (mean of the "
      "realizations) and the ratio ours / Mitchell's",
      {"pattern"},
      {},
      "mitchell-1992"};
  for (std::size_t n : published_counts)
    table.header.insert(table.header.end(), {fmt::format("N = {}: ours", n), "Mitchell", "ratio"});
  nlohmann::json& published = section.numbers["mitchell_1992"];
  double low = INFINITY, high = 0;
  std::vector<std::pair<double, std::string>> ours_16, theirs_16;
  for (const PublishedRow& row : mitchell_1992) {
    const auto& entry = section.numbers["patterns"][row.id];
    std::vector<std::string> cells{entry["label"].get<std::string>()};
    for (std::size_t k = 0; k < 3; ++k) {
      const double ours = entry["cells"][k]["rms"], ratio = ours / row.values[k];
      cells.insert(cells.end(), {format_number(ours), format_number(row.values[k]), format_number(ratio)});
      published[row.id].push_back(
          {{"n", published_counts[k]}, {"mitchell", row.values[k]}, {"ours", ours}, {"ratio", ratio}});
      if (k == 0) low = std::min(low, ratio), high = std::max(high, ratio);
    }
    ours_16.push_back({entry["cells"][0]["rms"].get<double>(), entry["label"].get<std::string>()});
    theirs_16.push_back({row.values[0], entry["label"].get<std::string>()});
    table.rows.push_back(std::move(cells));
  }
  std::vector<std::string> expected{"random, expected √(E[A(1−A)]/N)"};
  for (std::size_t k = 0; k < 3; ++k) {
    const double value = std::sqrt(expected_c / double(published_counts[k]));
    expected.insert(expected.end(), {format_number(value), format_number(mitchell_1992[4].values[k]),
                                     format_number(value / mitchell_1992[4].values[k])});
    section.numbers["random_expected_rms"].push_back({{"n", published_counts[k]}, {"rms", value}});
  }
  table.rows.push_back(std::move(expected));
  section.numbers["expected_binomial_edge_variance"] = expected_c;
  section.tables.push_back(std::move(table));

  // Orders at N = 16, best first: where Mitchell's and ours disagree.
  std::sort(ours_16.begin(), ours_16.end());
  std::sort(theirs_16.begin(), theirs_16.end());
  std::string swaps;
  for (std::size_t i = 0; i < ours_16.size(); ++i)
    if (ours_16[i].second != theirs_16[i].second)
      swaps += (swaps.empty() ? "" : ", ") + fmt::format("{} is {} in ours", ours_16[i].second, i + 1);
  section.numbers["order_differs_at_16"] = !swaps.empty();
  // Mitchell's random column as c/√N: the c his line measure implies.
  double implied = 0;
  for (std::size_t k = 0; k < 3; ++k)
    implied += mitchell_1992[4].values[k] * std::sqrt(double(published_counts[k])) / 3;
  section.numbers["mitchell_random_constant"] = implied;
  section.text.push_back(fmt::format(
      "Beside Mitchell's published values, ours at N = 16 are {}–{}× his{}. For independent points the expected "
      "RMS depends only on how the random edges are drawn: E[D²] = E[A(1−A)]/N with A the area cut off, which "
      "for our motion-invariant measure of lines (Santaló) is {}/N, so the RMS is {}/√N; Mitchell's random "
      "column is close to {}/√N, so his edges were drawn from a measure that cuts the square more evenly (the "
      "lecture does not state it). The line measure scales every pattern alike; what is left differs by "
      "construction: Mitchell does not say how his Poisson-disk points were made (ours: Bridson's dart "
      "throwing with toroidal distances, the radius chosen so that exactly N points fit).",
      format_number(low), format_number(high),
      swaps.empty() ? ", and the order of the five patterns is the same"
                    : fmt::format(", and the order differs ({}, best first)", swaps),
      format_number(expected_c), format_number(std::sqrt(expected_c)), format_number(implied)));
}

struct SpectrumSummary {
  double low = 0;   ///< mean radial power at frequency < 0.5·√N (low: little large-scale clumping)
  double peak = 0;  ///< the largest radial power (a spike: regular structure that aliases)
};

SpectrumSummary summarize(const sa::MitchellSpectrum& spectrum) {
  SpectrumSummary summary;
  std::size_t low_count = 0;
  for (std::size_t k = 0; k < spectrum.frequency.size(); ++k) {
    if (spectrum.frequency[k] > 0 && spectrum.frequency[k] < 0.5) summary.low += spectrum.power[k], ++low_count;
    summary.peak = std::max(summary.peak, spectrum.power[k]);
  }
  if (low_count) summary.low /= static_cast<double>(low_count);
  return summary;
}

}  // namespace

Section patterns_section(SectionContext& context) {
  Section section = context.start();
  sa::MitchellStudyOptions options;
  options.counts = {16, 256, 1600};
  options.realizations = context.quick() ? 6 : 20;
  options.lines = context.quick() ? 2000 : 10000;
  options.seed = context.seed();
  options.threads = context.threads();
  options.extra_patterns = extra_patterns(context);
  const sa::MitchellStudy study = sa::run_mitchell_study(options);

  // Points and spectra (the JSON shape of `stratum study mitchell --json`), and the table.
  nlohmann::json patterns = nlohmann::json::array();
  nlohmann::json lines = nlohmann::json::array();
  Table table{fmt::format("Random-edge discrepancy: RMS over {} random lines, mean ± standard error over {} "
                          "realizations; spectrum at N = {} (radial power, 1 = white noise)",
                          options.lines, options.realizations, study.spectra.front().n),
              {"pattern"},
              {}};
  for (std::size_t n : options.counts) table.header.push_back(fmt::format("N = {}", n));
  table.header.insert(table.header.end(), {"slope of log RMS", "low-frequency power", "spectral peak"});
  double lowest = INFINITY;
  std::string lowest_label;
  for (std::size_t p = 0; p < study.patterns.size(); ++p) {
    const auto& pattern = study.patterns[p];
    const std::string id = sa::mitchell_pattern_id(pattern);
    nlohmann::json cells = nlohmann::json::array();
    std::vector<std::string> row{pattern.label};
    std::vector<double> n, rms, error;
    for (std::size_t requested : options.counts) {
      const auto& cell = study.cell(id, requested);
      cells.push_back({{"requested", cell.requested},
                       {"n", cell.n},
                       {"rms", cell.rms.mean},
                       {"rms_se", cell.rms.error},
                       {"mean", cell.mean.mean},
                       {"mean_se", cell.mean.error},
                       {"max", cell.max.mean},
                       {"max_se", cell.max.error}});
      row.push_back(fmt::format("{} ± {}{}", format_number(cell.rms.mean), format_number(cell.rms.error, 2),
                                cell.n != requested ? fmt::format(" (N = {})", cell.n) : ""));
      n.push_back(static_cast<double>(cell.n));
      rms.push_back(cell.rms.mean);
      error.push_back(cell.rms.error);
      if (requested == 1600 && cell.rms.mean < lowest) lowest = cell.rms.mean, lowest_label = pattern.label;
    }
    const sa::SlopeFit fit = sa::fit_log_log(n, rms);
    const auto& spectrum = study.spectra[p];
    const SpectrumSummary summary = summarize(spectrum);
    row.insert(row.end(), {format_number(fit.slope), format_number(summary.low), format_number(summary.peak)});
    table.rows.push_back(std::move(row));
    patterns.push_back({{"label", pattern.label},
                        {"sampler", pattern.sampler},
                        {"cells", cells},
                        {"spectrum", {{"n", spectrum.n}, {"frequency", spectrum.frequency}, {"power", spectrum.power}}},
                        {"example", spectrum.example}});
    lines.push_back({{"label", pattern.label}, {"x", n}, {"y", rms}, {"yerr", error}});
    section.numbers["patterns"][id] = {{"label", pattern.label},
                                       {"cells", cells},
                                       {"slope", fit.slope},
                                       {"slope_se", fit.slope_standard_error},
                                       {"low_frequency_power", summary.low},
                                       {"spectral_peak", summary.peak}};
  }
  section.numbers["lines"] = options.lines;
  section.numbers["realizations"] = options.realizations;
  section.numbers["notes"] = study.notes;
  section.numbers["lowest_at_1600"] = lowest_label;

  // c·N^(−1/2) through the random pattern's three values (least squares in log space).
  const auto& random = section.numbers["patterns"]["random"];
  double log_c = 0;
  for (const auto& cell : random["cells"])
    log_c += std::log(cell["rms"].get<double>() * std::sqrt(cell["n"].get<double>())) / 3;
  std::vector<double> ref_n, ref_y;
  for (double x : {16.0, 256.0, 1600.0}) ref_n.push_back(x), ref_y.push_back(std::exp(log_c) / std::sqrt(x));
  lines.push_back({{"label", "c·N^(−1/2)"}, {"x", ref_n}, {"y", ref_y}, {"reference", true}});

  section.figures.push_back(context.plot(
      "report_patterns", {{"patterns", patterns}}, "spectra",
      fmt::format("Each pattern (one realization, N = {}) above its radially averaged power spectrum (mean of {} "
                  "realizations; dashed: white noise)",
                  study.spectra.front().n, options.realizations)));
  nlohmann::json panel = {{"title", "random-edge discrepancy against N"},
                          {"xlabel", "N"},
                          {"ylabel", "RMS over random edges"},
                          {"xlog", true},
                          {"ylog", true},
                          {"series", lines}};
  nlohmann::json line_plot = {{"panels", nlohmann::json::array({panel})}};
  section.figures.push_back(context.plot(
      "report_lines", line_plot, "convergence",
      "Random-edge discrepancy against N (mean ± s.e.); dotted: c·N^(−1/2) fitted to the random pattern in log space"));
  section.tables.push_back(std::move(table));
  add_published_comparison(section, expected_binomial_edge_variance(context.quick() ? 400 : 1000));

  const double random_slope = random["slope"], random_se = random["slope_se"];
  const auto& random_cells = random["cells"];
  section.text.push_back(fmt::format(
      "Mitchell's experiment: the RMS discrepancy of {} random edges, averaged over {} realizations per pattern and "
      "N. Random points converge with a fitted slope of log RMS on log N of {} (± {}; for independent points E[D²] is "
      "exactly c/N, "
      "so ≈ −1/2 is expected), from {} at N = 16 to {} at N = 1600.",
      options.lines, options.realizations, format_number(random_slope), format_number(random_se),
      format_number(random_cells[0]["rms"].get<double>()), format_number(random_cells[2]["rms"].get<double>())));
  section.text.push_back(fmt::format("At N = 1600 the lowest random-edge discrepancy is {}'s ({}), {}× below random's.",
                                     lowest_label, format_number(lowest),
                                     format_number(random_cells[2]["rms"].get<double>() / lowest)));
  const auto peak_of = [&](const char* id) { return section.numbers["patterns"][id]["spectral_peak"].get<double>(); };
  section.text.push_back(fmt::format(
      "At N = {} the largest radial power in the spectrum is {} for Zaremba, {} for jittered, "
      "{} for Poisson disk and {} for random (1 is white noise; a tall spike is regular structure that aliases).",
      study.spectra.front().n, format_number(peak_of("zaremba")), format_number(peak_of("jittered")),
      format_number(peak_of("poisson-disk")), format_number(peak_of("random"))));
  section.try_it = {"stratum study mitchell --sampler sobol:owen --plot mitchell.png"};
  return section;
}

}  // namespace stratum::report
