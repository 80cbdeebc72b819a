/// `stratum koksma-hlawka`: the Koksma–Hlawka inequality
///   |(1/N) Σ f(p_i) − ∫f| ≤ V_HK(f) · D*_N
/// checked on a 2D point set for every test function of closed-form
/// Hardy–Krause variation (Niederreiter 1992, Thm. 2.11; koksma_hlawka.hpp),
/// one row per function; --list prints the functions alone.
#include <fmt/core.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "point_input.hpp"
#include "stratum/analysis/koksma_hlawka.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/util/error.hpp"

namespace stratum::cli {

namespace {
namespace sa = stratum::analysis;

struct KoksmaHlawkaOptions : PointInput {
  std::optional<double> star;
  bool json = false, list = false;
};

/// The caller's --star, or koksma_hlawka_star's D*_N (exact, or an upper bound).
std::pair<double, std::string> star_of(const sa::PointView& view, const KoksmaHlawkaOptions& o) {
  if (o.star) return {*o.star, "given"};
  const sa::KoksmaHlawkaStar star = sa::koksma_hlawka_star(view, static_cast<unsigned>(o.threads));
  return {star.value, star.kind};
}

void print_functions(bool json) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& f : sa::variation_test_functions()) {
    if (json)
      list.push_back({{"function", f.name},
                      {"formula", f.formula},
                      {"integral", f.integral},
                      {"variation", f.variation},
                      {"derivation", f.derivation}});
    else
      fmt::print("{:<12} {:<16} integral {:<20} V_HK {:<20} {}\n", f.name, f.formula, f.integral, f.variation,
                 f.derivation);
  }
  if (json) fmt::print("{}\n", list.dump(2));
}

void run_koksma_hlawka(const KoksmaHlawkaOptions& o) {
  if (o.list) {
    const std::string extra = !o.file.empty()        ? o.file
                              : !o.sampler.empty()   ? "--sampler " + o.sampler
                              : o.n || o.d || o.star ? "with -n, -d or --star"
                                                     : "";
    if (!extra.empty())
      throw invalid_argument("--list", extra, "prints the test functions only; give no points or D* with it");
    print_functions(o.json);
    return;
  }
  if (o.star)
    require(std::isfinite(*o.star) && *o.star >= 0 && *o.star <= 1, "star", *o.star,
            "must be in [0, 1] (the star discrepancy of the points, or an upper bound on it)");
  const PointSet points = load_points(o);
  const sa::PointView view{points.data.get(), points.n, points.d};
  require(view.d == 2, "d", view.d, "the Koksma-Hlawka test functions are 2D");
  sa::check_unit_cube(view);
  const auto [star, star_kind] = star_of(view, o);
  const std::vector<sa::KoksmaHlawkaCheck> checks = sa::koksma_hlawka_checks(view, star);
  const auto& functions = sa::variation_test_functions();  // checks[i] is functions[i]
  int holding = 0;
  for (const auto& c : checks) holding += c.holds ? 1 : 0;

  if (o.json) {
    nlohmann::json rows = nlohmann::json::array();
    for (std::size_t i = 0; i < checks.size(); ++i)
      rows.push_back({{"function", checks[i].function},
                      {"formula", functions[i].formula},
                      {"integral", functions[i].integral},
                      {"variation", functions[i].variation},
                      {"estimate", checks[i].estimate},
                      {"error", checks[i].error},
                      {"bound", checks[i].bound},
                      {"holds", checks[i].holds}});
    const std::string source = o.file.empty() ? "sampler " + o.sampler : o.file;
    fmt::print("{}\n", nlohmann::json{{"source", source},
                                      {"n", points.n},
                                      {"star", star},
                                      {"star_kind", star_kind},
                                      {"holds", holding},
                                      {"checks", rows}}
                           .dump(2));
    return;
  }
  fmt::print("N = {}, D* = {} ({}); |mean f - integral| <= V_HK(f) * D* holds for {} of {}\n", points.n, star,
             star_kind, holding, checks.size());
  fmt::print("{:<12} {:<16} {:<22} {:<22} {:<22} {}\n", "function", "formula", "estimate", "error", "bound", "holds");
  for (std::size_t i = 0; i < checks.size(); ++i)
    fmt::print("{:<12} {:<16} {:<22} {:<22} {:<22} {}\n", checks[i].function, functions[i].formula, checks[i].estimate,
               checks[i].error, checks[i].bound, checks[i].holds ? "yes" : "NO");
}
}  // namespace

void add_koksma_hlawka_command(CLI::App& app) {
  auto o = std::make_shared<KoksmaHlawkaOptions>();
  auto* command = app.add_subcommand(
      "koksma-hlawka", "Check |mean f - integral f| <= V_HK(f) D* on 2D points for test functions of known variation");
  add_point_input_options(*command, *o);
  command->add_option("--star", o->star,
                      "use this D* (or an upper bound on it) instead of computing it (exact for N <= 2^18, else "
                      "Thiemard's upper bound)");
  add_threads_option(*command, o->threads, "threads for D* (results do not depend on it)");
  command->add_flag("--list", o->list, "print the test functions (formula, integral, V_HK, its derivation) only");
  command->add_flag("--json", o->json, "print JSON");
  command->callback([o] { run_koksma_hlawka(*o); });
}

}  // namespace stratum::cli
