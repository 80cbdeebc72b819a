/// §11 Quasi-Monte Carlo patterns: the radical inverse φ2 (van der Corput
/// 1935) as a table, Hammersley (1964) and Halton (1960) points, and their
/// exact star discrepancy against N beside random points and the --sampler
/// extras, with the O(log^(d−1) N / N) and O(log^d N / N) rates of the
/// lecture drawn as reference curves (Niederreiter 1992, "Random Number
/// Generation and Quasi-Monte Carlo Methods", Thm 3.6 and 3.8).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/registry.hpp"
#include "stratum/sequences/radical_inverse.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

std::string choice_label(const sa::SamplerChoice& choice) {
  return choice.randomize.empty() ? choice.name : choice.name + ":" + choice.randomize;
}

PointSet pattern_points(const sa::SamplerChoice& choice, std::uint64_t n, std::uint64_t seed) {
  SamplerRequest request;
  request.n = n;
  request.d = 2;
  request.seed = seed;
  request.randomize = choice.randomize;
  request.params = choice.params;
  return generate_points(choice.name, request);
}

bool accepts(const sa::SamplerChoice& choice, std::uint64_t n) {
  SamplerRequest request;
  request.n = n;
  request.d = 2;
  request.randomize = choice.randomize;
  request.params = choice.params;
  try {
    validate_request(find_sampler(choice.name), request);
    return true;
  } catch (const invalid_argument&) {
    return false;
  }
}

/// The radical-inverse table: i, its binary digits, the digits mirrored
/// about the radix point, and φ2(i) from the library.
Table radical_inverse_table(nlohmann::json& numbers) {
  Table table{"The radical inverse φ2(i): the binary digits of i mirrored about the radix point",
              {"i", "i in base 2", "mirrored", "φ2(i)", "φ2(i) × 16", "the slide"},
              {},
              "radical-inverse"};
  bool agrees = true;
  for (std::uint64_t i = 0; i < 16; ++i) {
    std::string binary, mirrored = "0.";
    for (int bit = 3; bit >= 0; --bit) binary += ((i >> bit) & 1) ? '1' : '0';
    double mirrored_value = 0;
    for (int bit = 0; bit < 4; ++bit) {
      const bool one = (i >> bit) & 1;
      mirrored += one ? '1' : '0';
      mirrored_value += one ? std::ldexp(1.0, -(bit + 1)) : 0.0;
    }
    const double phi = radical_inverse(2, i);
    agrees = agrees && phi == mirrored_value;
    // The slide's worked example, i = 4 = 100₂, prints 3/8; mirroring gives 0.001₂ = 1/8.
    const std::string slide = i == 4 ? "3/8: erratum, it is 1/8" : "";
    table.rows.push_back(
        {std::to_string(i), binary + "₂", mirrored + "₂", fmt::format("{}", phi), fmt::format("{}", phi * 16), slide});
    numbers["phi2"].push_back(phi);
  }
  numbers["phi2_equals_mirrored_digits"] = agrees;
  numbers["slide_erratum"] = {{"i", 4}, {"slide", 3.0 / 8}, {"correct", radical_inverse(2, 4)}};
  return table;
}

struct Curve {
  std::string label;  ///< the registry spec (report.json's key)
  std::string name;   ///< for the page
  std::vector<double> n, mean, error;
  sa::SlopeFit fit;
};

/// Exact D* at every count: one set for a deterministic pattern, else the
/// mean (and standard error) over `runs` seeds.
Curve discrepancy_curve(const sa::SamplerChoice& choice, const std::vector<std::uint64_t>& counts, unsigned runs,
                        std::uint64_t seed, unsigned threads) {
  Curve curve{choice_label(choice), sampler_name(choice), {}, {}, {}, {}};
  sa::MeasureRequest measure;
  measure.threads = threads;
  for (std::uint64_t n : counts) {
    if (!accepts(choice, n)) continue;
    std::vector<double> values;
    for (unsigned r = 0; r < runs; ++r) {
      const PointSet points = pattern_points(choice, n, hash64(seed, n, r));
      if (r == 1) {  // a pattern that ignores its seed is deterministic: one set is all there is
        const PointSet first = pattern_points(choice, n, hash64(seed, n, 0));
        if (std::equal(first.data.get(), first.data.get() + 2 * n, points.data.get())) break;
      }
      values.push_back(sa::compute_measure("star", {points.data.get(), points.n, 2}, measure).value);
    }
    double mean = 0, squares = 0;
    for (double v : values) mean += v / values.size();
    for (double v : values) squares += (v - mean) * (v - mean);
    curve.n.push_back(static_cast<double>(n));
    curve.mean.push_back(mean);
    curve.error.push_back(values.size() > 1 ? std::sqrt(squares / (values.size() - 1) / values.size()) : 0.0);
  }
  if (curve.n.size() >= 2) curve.fit = sa::fit_log_log(curve.n, curve.mean);
  return curve;
}

/// c·rate(N) with c fitted to the data by least squares in log space
/// (c = exp(mean(log D − log rate))), so the curve shows the rate's shape
/// through the data without claiming its constant.
nlohmann::json reference(const Curve& curve, const std::string& label, double (*rate)(double), double& scale) {
  double log_c = 0;
  for (std::size_t k = 0; k < curve.n.size(); ++k) log_c += std::log(curve.mean[k] / rate(curve.n[k])) / curve.n.size();
  scale = std::exp(log_c);
  std::vector<double> y;
  for (double n : curve.n) y.push_back(scale * rate(n));
  return {{"label", label}, {"x", curve.n}, {"y", y}, {"reference", true}};
}

nlohmann::json series(const Curve& curve) {
  nlohmann::json s = {{"label", fmt::format("{} (slope {})", capitalized(curve.name), format_number(curve.fit.slope))},
                      {"x", curve.n},
                      {"y", curve.mean}};
  if (std::any_of(curve.error.begin(), curve.error.end(), [](double e) { return e > 0; })) s["yerr"] = curve.error;
  return s;
}

/// The spread max/min of D*(N)/rate(N) over the counts: bounded if the rate is right.
double ratio_spread(const Curve& curve, double (*rate)(double)) {
  double low = INFINITY, high = 0;
  for (std::size_t k = 0; k < curve.n.size(); ++k) {
    const double ratio = curve.mean[k] / rate(curve.n[k]);
    low = std::min(low, ratio), high = std::max(high, ratio);
  }
  return high / low;
}

double log_over_n(double n) { return std::log(n) / n; }
double log2_over_n(double n) { return std::log(n) * std::log(n) / n; }
double inverse_sqrt(double n) { return 1 / std::sqrt(n); }

}  // namespace

Section qmc_section(SectionContext& context) {
  Section section = context.start();
  section.tables.push_back(radical_inverse_table(section.numbers));

  // Hammersley and Halton points as the lecture shows them (unscrambled), beside random.
  const std::uint64_t shown = 256;
  const sa::SamplerChoice hammersley{"hammersley", "none", {}}, halton{"halton", "none", {}}, random{"random", "", {}};
  nlohmann::json panels = nlohmann::json::array();
  for (const auto& [choice, title] : {std::pair{hammersley, "Hammersley (i/N, φ2(i))"},
                                      std::pair{halton, "Halton (φ2(i), φ3(i))"}, std::pair{random, "random"}}) {
    const PointSet points = pattern_points(choice, shown, context.seed());
    std::vector<double> x(points.n), y(points.n);
    for (std::size_t i = 0; i < points.n; ++i) x[i] = points(i, 0), y[i] = points(i, 1);
    panels.push_back({{"title", fmt::format("{}, N = {}", title, shown)}, {"x", x}, {"y", y}});
  }
  section.figures.push_back(context.plot("report_points", {{"columns", 3}, {"panels", panels}}, "points",
                                         "Hammersley and Halton points (no scrambling) beside random points"));

  // Star discrepancy against N, in half-octave steps.
  std::vector<std::uint64_t> counts;
  const double largest = context.quick() ? 2048 : 16384;
  for (double n = 16; n <= largest * 1.001; n *= std::sqrt(2.0))
    counts.push_back(static_cast<std::uint64_t>(std::lround(n)));
  const unsigned runs = context.quick() ? 6 : 16;
  std::vector<sa::SamplerChoice> compared{hammersley, halton, random};
  for (const auto& extra : context.extra_samplers())
    if (std::none_of(compared.begin(), compared.end(),
                     [&](const auto& c) { return choice_label(c) == choice_label(extra); }))
      compared.push_back(extra);
  std::vector<Curve> curves;
  for (const auto& choice : compared)
    curves.push_back(discrepancy_curve(choice, counts, runs, context.seed(), context.threads()));

  double c_hammersley = 0, c_halton = 0, c_random = 0;
  nlohmann::json all = nlohmann::json::array();
  for (const auto& curve : curves)
    if (curve.n.size() >= 2) all.push_back(series(curve));
  all.push_back(reference(curves[2], "c·N^(−1/2)", inverse_sqrt, c_random));
  nlohmann::json plot_panels = {
      {{"title", "Hammersley against c·log N / N (d = 2)"},
       {"xlabel", "N"},
       {"ylabel", "star discrepancy D*"},
       {"xlog", true},
       {"ylog", true},
       {"series", {series(curves[0]), reference(curves[0], "c·log N / N", log_over_n, c_hammersley)}}},
      {{"title", "Halton against c·log² N / N (d = 2)"},
       {"xlabel", "N"},
       {"ylabel", "star discrepancy D*"},
       {"xlog", true},
       {"ylog", true},
       {"series", {series(curves[1]), reference(curves[1], "c·log² N / N", log2_over_n, c_halton)}}},
      {{"title", fmt::format("every pattern (random: mean ± s.e. of {} sets)", runs)},
       {"xlabel", "N"},
       {"ylabel", "star discrepancy D*"},
       {"xlog", true},
       {"ylog", true},
       {"series", all}}};
  section.figures.push_back(context.plot(
      "report_lines", {{"columns", 3}, {"panels", plot_panels}}, "star-vs-n",
      "Exact star discrepancy against N; dotted: the rates c·log N / N, c·log² N / N and c·N^(−1/2), each scaled "
      "to its pattern's data by least squares in log space (c = exp(mean(log D* − log rate)))"));

  Table slopes{"Star discrepancy against N: fitted slope of log D* on log N",
               {"pattern", "N range", "slope", "± s.e.", "D* at largest N"},
               {}};
  for (const auto& curve : curves) {
    if (curve.n.size() < 2) {  // an extra that takes fewer than two of the counts
      section.numbers["skipped"].push_back(curve.label);
      continue;
    }
    slopes.rows.push_back({capitalized(curve.name) + " `" + curve.label + "`",
                           fmt::format("{}–{}", curve.n.front(), curve.n.back()), format_number(curve.fit.slope),
                           format_number(curve.fit.slope_standard_error), format_number(curve.mean.back())});
    section.numbers["curves"][curve.label] = {{"n", curve.n},
                                              {"star", curve.mean},
                                              {"standard_error", curve.error},
                                              {"slope", curve.fit.slope},
                                              {"slope_se", curve.fit.slope_standard_error}};
  }
  section.tables.push_back(std::move(slopes));
  const double spread_hammersley = ratio_spread(curves[0], log_over_n);
  const double spread_halton = ratio_spread(curves[1], log2_over_n);
  section.numbers["reference_scale"] = {
      {"hammersley_log_n_over_n", c_hammersley}, {"halton_log2_n_over_n", c_halton}, {"random_inverse_sqrt", c_random}};
  section.numbers["ratio_spread"] = {{"hammersley", spread_hammersley}, {"halton", spread_halton}};
  section.numbers["runs"] = runs;

  section.text.push_back(fmt::format(
      "φ2(i) mirrors the binary digits of i about the radix point: i = 4 = 100₂ gives 0.001₂ = {} (the slide "
      "prints 3/8 for this entry, an erratum: 3/8 = 0.011₂ is φ2(6)); the library's radical inverse {} the "
      "mirrored digits for every i in the table.",
      radical_inverse(2, 4), section.numbers["phi2_equals_mirrored_digits"].get<bool>() ? "equals" : "DIFFERS FROM"));
  section.text.push_back(fmt::format(
      "From N = {} to {}, the exact star discrepancy falls with fitted slopes {} (Hammersley), {} (Halton) and {} "
      "(random, mean of {} sets) on log–log axes; at N = {} random's D* is {}× Hammersley's.",
      counts.front(), counts.back(), format_number(curves[0].fit.slope), format_number(curves[1].fit.slope),
      format_number(curves[2].fit.slope), runs, counts.back(),
      format_number(curves[2].mean.back() / curves[0].mean.back())));
  section.text.push_back(fmt::format(
      "Over that range D*·N/log N for Hammersley varies by a factor {} and D*·N/log² N for Halton by {}, against a "
      "factor {} in N (a ratio held bounded by the O(log^(d−1) N / N) and O(log^d N / N) rates keeps these "
      "factors small beside it).",
      format_number(spread_hammersley), format_number(spread_halton),
      format_number(static_cast<double>(counts.back()) / counts.front())));
  section.try_it = {"stratum discrepancy -m star -s hammersley -n 1024 --randomize none"};
  return section;
}

}  // namespace stratum::report
