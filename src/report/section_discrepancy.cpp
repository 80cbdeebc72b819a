/// §10 Discrepancy: the local discrepancy Δ(x, y) = n(x,y)/N − xy as a
/// picture with the box of its supremum, the star and L2-star discrepancies
/// of a few patterns, and the Koksma–Hlawka inequality checked on test
/// functions with closed-form integral and Hardy–Krause variation
/// (Niederreiter 1992, "Random Number Generation and Quasi-Monte Carlo
/// Methods", §2; Owen 2005, "Multidimensional variation for quasi-Monte Carlo").
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "sections.hpp"
#include "stratum/analysis/koksma_hlawka.hpp"
#include "stratum/analysis/local_discrepancy.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::report {

namespace {

namespace sa = stratum::analysis;

std::string choice_label(const sa::SamplerChoice& choice) {
  return choice.randomize.empty() ? choice.name : choice.name + ":" + choice.randomize;
}

PointSet pattern_points(const sa::SamplerChoice& choice, std::uint64_t n, std::uint64_t seed, unsigned threads) {
  SamplerRequest request;
  request.n = n;
  request.d = 2;
  request.seed = seed;
  request.randomize = choice.randomize;
  request.params = choice.params;
  request.threads = threads;
  return generate_points(choice.name, request);
}

/// The count nearest to `n` that the pattern takes (the smaller on a tie):
/// an extra such as latin-square takes only some counts.
std::uint64_t usable_count(const sa::SamplerChoice& choice, std::uint64_t n) {
  const SamplerInfo& sampler = find_sampler(choice.name);
  const auto takes = [&](std::uint64_t m) {
    SamplerRequest request;
    request.n = m;
    request.d = 2;
    request.randomize = choice.randomize;
    request.params = choice.params;
    try {
      validate_request(sampler, request);
      return m >= 2;
    } catch (const invalid_argument&) {
      return false;
    }
  };
  for (std::uint64_t step = 0; step < n; ++step) {
    if (takes(n - step)) return n - step;
    if (takes(n + step)) return n + step;
  }
  throw invalid_argument("sampler", choice_label(choice),
                         "a sampler that takes about " + std::to_string(n) + " points");
}

/// The patterns compared: a few built-ins (Halton and Hammersley
/// unscrambled, as in the lecture), then the --sampler extras not already listed.
std::vector<sa::SamplerChoice> compared_patterns(const SectionContext& context) {
  std::vector<sa::SamplerChoice> patterns{{"random", "", {}},         {"jittered", "", {}},   {"n-rooks", "", {}},
                                          {"hammersley", "none", {}}, {"halton", "none", {}}, {"sobol", "owen", {}}};
  for (const auto& extra : context.extra_samplers())
    if (std::none_of(patterns.begin(), patterns.end(),
                     [&](const sa::SamplerChoice& p) { return choice_label(p) == choice_label(extra); }))
      patterns.push_back(extra);
  return patterns;
}

/// One panel of the Δ picture: the field on a grid, the points, the box.
nlohmann::json field_panel(const sa::SamplerChoice& choice, const PointSet& points, std::size_t resolution,
                           nlohmann::json& numbers) {
  const sa::PointView view{points.data.get(), points.n, points.d};
  const auto grid = sa::local_discrepancy_grid(view, resolution);
  const auto box = sa::star_discrepancy_box(view);
  std::vector<double> x(points.n), y(points.n);
  for (std::size_t i = 0; i < points.n; ++i) x[i] = points(i, 0), y[i] = points(i, 1);
  numbers = {
      {"n", points.n},      {"star", box.value},           {"box_x", box.x}, {"box_y", box.y}, {"closed", box.closed},
      {"count", box.count}, {"grid_max_abs", grid.max_abs}};
  return {{"title",
           fmt::format("{}, N = {}: D* = {}", capitalized(sampler_name(choice)), points.n, format_number(box.value))},
          {"resolution", grid.resolution},
          {"values", grid.values},
          {"x", x},
          {"y", y},
          {"box", {{"x", box.x}, {"y", box.y}, {"closed", box.closed}, {"value", box.value}}}};
}

std::string box_words(const nlohmann::json& numbers) {
  return fmt::format(
      "[0, {}) × [0, {}) with {} points where {} expected ({})", format_number(numbers["box_x"]),
      format_number(numbers["box_y"]), numbers["count"].get<std::size_t>(),
      format_number(numbers["box_x"].get<double>() * numbers["box_y"].get<double>() * numbers["n"].get<double>()),
      numbers["closed"].get<bool>() ? "too many, box closed" : "too few");
}

}  // namespace

Section discrepancy_section(SectionContext& context) {
  Section section = context.start();
  const std::size_t picture_n = 64, resolution = context.quick() ? 128 : 256;
  const std::uint64_t n = context.quick() ? 256 : 1024;

  // The picture: random and unscrambled Hammersley points.
  nlohmann::json panels = nlohmann::json::array();
  const sa::SamplerChoice pictured[] = {{"random", "", {}}, {"hammersley", "none", {}}};
  for (const auto& choice : pictured) {
    const PointSet points = pattern_points(choice, picture_n, context.seed(), 1);
    nlohmann::json numbers;
    panels.push_back(field_panel(choice, points, resolution, numbers));
    section.numbers["picture"][choice_label(choice)] = numbers;
  }
  const auto& random_box = section.numbers["picture"]["random"];
  const auto& hammersley_box = section.numbers["picture"]["hammersley:none"];
  section.figures.push_back(context.plot(
      "report_field", {{"columns", 2}, {"panels", panels}}, "delta",
      fmt::format("Δ(x, y) = n(x, y)/N − xy for {} points (red: too many points in [0,x)×[0,y), blue: too few); "
                  "the gold box is where |Δ| is largest (dashed: too few points, solid: too many, upper edges "
                  "included), its size is D*; one colour scale for both panels",
                  picture_n)));

  // Star and L2-star discrepancies, and the Koksma–Hlawka check.
  const auto& functions = sa::variation_test_functions();
  Table values{fmt::format("Star and L2-star discrepancy of {} points (one realization, seed {})", n, context.seed()),
               {"pattern", "D* (exact)", "L2-star"},
               {}};
  Table checks{fmt::format("Koksma–Hlawka at N = {}: measured |error| of the mean of f against the bound V(f)·D*", n),
               {"pattern"},
               {},
               "koksma-hlawka"};
  for (const auto& function : functions) checks.header.push_back(function.formula);
  Table function_table{"Test functions: closed-form integral and Hardy–Krause variation (anchored at 1)",
                       {"f", "∫f", "V_HK(f)", "derivation"},
                       {}};
  for (const auto& function : functions)
    function_table.rows.push_back({function.formula, format_number(function.integral, 6),
                                   format_number(function.variation, 6), function.derivation});

  std::size_t held = 0, total = 0;
  double tightest = -1;
  std::string tightest_where;
  std::vector<double> fractions;
  std::pair<double, std::string> lowest{2, ""}, highest{-1, ""};
  sa::MeasureRequest measure;
  measure.threads = context.threads();
  for (const auto& choice : compared_patterns(context)) {
    const std::string label = choice_label(choice);
    const PointSet points = pattern_points(choice, usable_count(choice, n), context.seed(), context.threads());
    const sa::PointView view{points.data.get(), points.n, points.d};
    const double star = sa::compute_measure("star", view, measure).value;
    const double l2 = sa::compute_measure("l2-star", view, measure).value;
    const std::string name = named_with_spec(choice);
    values.rows.push_back(
        {points.n == n ? name : fmt::format("{} (N = {})", name, points.n), format_number(star), format_number(l2)});
    if (star < lowest.first) lowest = {star, sampler_name(choice)};
    if (star > highest.first) highest = {star, sampler_name(choice)};
    nlohmann::json& entry = section.numbers["patterns"][label];
    entry = {{"n", points.n}, {"star", star}, {"l2_star", l2}};
    std::vector<std::string> row{name};
    for (const auto& check : sa::koksma_hlawka_checks(view, star)) {
      row.push_back(fmt::format("{} ≤ {}: {}", format_number(check.error), format_number(check.bound),
                                check.holds ? "holds" : "FAILS"));
      entry["koksma_hlawka"][check.function] = {
          {"estimate", check.estimate}, {"error", check.error}, {"bound", check.bound}, {"holds", check.holds}};
      ++total;
      held += check.holds;
      const double fraction = check.bound > 0 ? check.error / check.bound : 0;
      fractions.push_back(fraction);
      if (fraction > tightest) tightest = fraction, tightest_where = sampler_name(choice) + ", " + check.function;
    }
    checks.rows.push_back(std::move(row));
  }
  std::sort(fractions.begin(), fractions.end());
  const double median = fractions[fractions.size() / 2];
  section.numbers["koksma_hlawka"] = {
      {"held", held}, {"checks", total}, {"largest_fraction", tightest}, {"median_fraction", median}};
  for (const auto& function : functions)
    section.numbers["functions"][function.name] = {{"integral", function.integral}, {"variation", function.variation}};

  section.text.push_back(fmt::format(
      "For {} points the local discrepancy |Δ| peaks on the box {} for random points (D* = {}), and on {} for "
      "Hammersley points (D* = {}); the random set's D* is {}× the Hammersley set's.",
      picture_n, box_words(random_box), format_number(random_box["star"]), box_words(hammersley_box),
      format_number(hammersley_box["star"]),
      format_number(random_box["star"].get<double>() / hammersley_box["star"].get<double>())));
  section.text.push_back(
      fmt::format("At N = {} the exact star discrepancy ranges from {} ({}) to {} ({}), a factor {}.", n,
                  format_number(lowest.first), lowest.second, format_number(highest.first), highest.second,
                  format_number(highest.first / lowest.first)));
  section.text.push_back(fmt::format(
      "Koksma–Hlawka, |(1/N) Σ f(p_i) − ∫f| ≤ V_HK(f)·D*: the bound held in {} of {} (pattern, function) pairs; "
      "the measured error used at most {}% of the bound ({}) and a median {}%{}.",
      held, total, format_number(100 * tightest), tightest_where, format_number(100 * median),
      held < total    ? " (a violation: a bug in the discrepancy, the variation or the sum)"
      : tightest <= 0 ? " (every error is zero)"
                      : fmt::format(", so on these functions the bound exceeds the error by a factor {} or more",
                                    format_number(1 / tightest))));
  section.tables.push_back(std::move(values));
  section.tables.push_back(std::move(function_table));
  section.tables.push_back(std::move(checks));
  section.try_it = {"stratum discrepancy -m star -s halton -n 1024",
                    "stratum discrepancy -m l2-star -s sobol -n 1024 --randomize owen"};
  return section;
}

}  // namespace stratum::report
