/// Test functions with closed-form integral and Hardy–Krause variation, and
/// the Koksma–Hlawka check (koksma_hlawka.hpp).
#include "stratum/analysis/koksma_hlawka.hpp"

#include <cmath>
#include <numbers>

#include "stratum/util/error.hpp"

namespace stratum::analysis {

namespace {

constexpr double e = std::numbers::e;
constexpr double pi = std::numbers::pi;

/// ∫∫ e^(xy) = ∫_0^1 (e^x − 1)/x dx = Σ_{k≥1} 1/(k·k!) (term-wise
/// integration of the exponential series); 20 terms reach double precision.
double exp_product_integral() {
  double sum = 0, factorial = 1;
  for (int k = 1; k <= 20; ++k) {
    factorial *= k;
    sum += 1.0 / (k * factorial);
  }
  return sum;
}

}  // namespace

double product_variation(double variation_g, double g_at_1, double variation_h, double h_at_1) {
  return (variation_g + std::fabs(g_at_1)) * (variation_h + std::fabs(h_at_1)) - std::fabs(g_at_1 * h_at_1);
}

const std::vector<VariationTestFunction>& variation_test_functions() {
  static const std::vector<VariationTestFunction> functions{
      {"xy", "x·y", 0.25, product_variation(1, 1, 1, 1), "product of increasing x, y: (V(x) + 1)² − 1 with V(x) = 1",
       [](double x, double y) { return x * y; }},
      {"exp-sum", "e^(x+y)", (e - 1) * (e - 1), product_variation(e - 1, e, e - 1, e),
       "product of increasing e^x, e^y: (e − 1 + e)² − e²", [](double x, double y) { return std::exp(x + y); }},
      {"rational", "1/((1+x)(1+y))", std::numbers::ln2 * std::numbers::ln2, product_variation(0.5, 0.5, 0.5, 0.5),
       "product of decreasing 1/(1+x), 1/(1+y): (1/2 + 1/2)² − 1/4",
       [](double x, double y) { return 1 / ((1 + x) * (1 + y)); }},
      {"sin-product", "sin(πx)·sin(πy)", 4 / (pi * pi), product_variation(2, 0, 2, 0),
       "product of sin(πx) (variation 2, zero at 1): 2·2",
       [](double x, double y) { return std::sin(pi * x) * std::sin(pi * y); }},
      {"exp-product", "e^(xy)", exp_product_integral(), 3 * (e - 1),
       "∂²f/∂x∂y = (1+xy)e^(xy) > 0: Vitali f(1,1) − f(1,0) − f(0,1) + f(0,0) = e − 1; faces e^x, e^y add e − 1 each",
       [](double x, double y) { return std::exp(x * y); }},
  };
  return functions;
}

KoksmaHlawkaStar koksma_hlawka_star(const PointView& points, unsigned threads) {
  const MeasureResult star = compute_measure("star", points, {{}, threads});
  if (star.kind == "bounds") return {star.upper.value_or(star.value), "upper bound"};
  return {star.value, "exact"};
}

std::vector<KoksmaHlawkaCheck> koksma_hlawka_checks(const PointView& points, double star_discrepancy) {
  require(points.d == 2, "d", points.d, "the Koksma–Hlawka test functions are 2D");
  check_unit_cube(points);
  require(std::isfinite(star_discrepancy) && star_discrepancy >= 0 && star_discrepancy <= 1, "star_discrepancy",
          star_discrepancy, "must be in [0, 1]");
  std::vector<KoksmaHlawkaCheck> checks;
  for (const auto& function : variation_test_functions()) {
    long double sum = 0;
    for (std::size_t i = 0; i < points.n; ++i) sum += function.f(points(i, 0), points(i, 1));
    KoksmaHlawkaCheck check;
    check.function = function.name;
    check.estimate = static_cast<double>(sum / static_cast<long double>(points.n));
    check.error = std::fabs(check.estimate - function.integral);
    check.bound = function.variation * star_discrepancy;
    // The sum is accumulated in long double; 1e-12 covers the rounding of
    // the estimate and of the closed forms, far below any bound here.
    check.holds = check.error <= check.bound + 1e-12;
    checks.push_back(std::move(check));
  }
  return checks;
}

}  // namespace stratum::analysis
