/// §12 Comparing patterns: Mitchell's (1992, "Ray tracing and
/// irregularities of distribution") random-edge discrepancy of Zaremba,
/// jittered, Poisson-disk, N-rooks and random patterns at 16, 256 and 1600
/// points, each pattern's points and radially averaged power spectrum, and
/// the --sampler extras run through the same study.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/mitchell_study.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

/// The --sampler extras as study patterns, leaving out any already among Mitchell's five.
std::vector<sa::MitchellPattern> extra_patterns(const SectionContext& context) {
  std::vector<sa::MitchellPattern> extras;
  for (const auto& choice : context.extra_samplers()) {
    sa::MitchellPattern pattern{choice.randomize.empty() ? choice.name : choice.name + ":" + choice.randomize,
                                choice.name, choice.params, choice.randomize};
    const std::string id = sa::mitchell_pattern_id(pattern);
    const auto same = [&](const sa::MitchellPattern& p) { return sa::mitchell_pattern_id(p) == id; };
    if (std::none_of(sa::mitchell_patterns().begin(), sa::mitchell_patterns().end(), same) &&
        std::none_of(extras.begin(), extras.end(), same))
      extras.push_back(std::move(pattern));
  }
  return extras;
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
              {"pattern"}, {}};
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
      cells.push_back({{"requested", cell.requested}, {"n", cell.n}, {"rms", cell.rms.mean}, {"rms_se", cell.rms.error},
                       {"mean", cell.mean.mean}, {"mean_se", cell.mean.error}, {"max", cell.max.mean},
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
    patterns.push_back({{"label", pattern.label}, {"sampler", pattern.sampler}, {"cells", cells},
                        {"spectrum", {{"n", spectrum.n}, {"frequency", spectrum.frequency}, {"power", spectrum.power}}},
                        {"example", spectrum.example}});
    lines.push_back({{"label", pattern.label}, {"x", n}, {"y", rms}, {"yerr", error}});
    section.numbers["patterns"][id] = {{"label", pattern.label}, {"cells", cells}, {"slope", fit.slope},
                                       {"slope_se", fit.slope_standard_error}, {"low_frequency_power", summary.low},
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
  nlohmann::json panel = {{"title", "random-edge discrepancy against N"}, {"xlabel", "N"},
                          {"ylabel", "RMS over random edges"}, {"xlog", true}, {"ylog", true}, {"series", lines}};
  nlohmann::json line_plot = {{"panels", nlohmann::json::array({panel})}};
  section.figures.push_back(context.plot(
      "report_lines", line_plot, "convergence",
      "Random-edge discrepancy against N (mean ± s.e.); dotted: c·N^(−1/2) fitted to the random pattern in log space"));
  section.tables.push_back(std::move(table));

  const double random_slope = random["slope"], random_se = random["slope_se"];
  const auto& random_cells = random["cells"];
  section.text.push_back(fmt::format(
      "Mitchell's experiment: the RMS discrepancy of {} random edges, averaged over {} realizations per pattern and "
      "N. Random points converge with a fitted slope of log RMS on log N of {} (± {}; for independent points E[D²] is exactly c/N, "
      "so ≈ −1/2 is expected), from {} at N = 16 to {} at N = 1600.",
      options.lines, options.realizations, format_number(random_slope), format_number(random_se),
      format_number(random_cells[0]["rms"].get<double>()), format_number(random_cells[2]["rms"].get<double>())));
  section.text.push_back(fmt::format(
      "At N = 1600 the lowest random-edge discrepancy is {}'s ({}), {}× below random's.", lowest_label,
      format_number(lowest), format_number(random_cells[2]["rms"].get<double>() / lowest)));
  const auto peak_of = [&](const char* id) { return section.numbers["patterns"][id]["spectral_peak"].get<double>(); };
  section.text.push_back(fmt::format(
      "At N = {} the largest radial power in the spectrum is {} for Zaremba, {} for jittered, "
      "{} for Poisson disk and {} for random (1 is white noise; a tall spike is regular structure that aliases).",
      study.spectra.front().n, format_number(peak_of("zaremba")), format_number(peak_of("jittered")), format_number(peak_of("poisson-disk")),
      format_number(peak_of("random"))));
  return section;
}

}  // namespace stratum::report
