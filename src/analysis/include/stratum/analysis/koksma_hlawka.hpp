#pragma once
/// The Koksma–Hlawka inequality made checkable (LECTURE.md §10):
///
///   | (1/N) Σ f(p_i) − ∫ f |  ≤  V_HK(f) · D*_N,
///
/// with D*_N the star discrepancy over anchored boxes [0,x) and V_HK the
/// variation in the sense of Hardy and Krause anchored at 1 (Hlawka 1961,
/// "Funktionen von beschränkter Variation in der Theorie der
/// Gleichverteilung"; Niederreiter 1992, Thm 2.11; Owen 2005,
/// "Multidimensional variation for quasi-Monte Carlo", eq. (9)–(12)):
///
///   V_HK(f) = Σ_{∅≠u⊆{1..d}} V_Vitali(f restricted to the face x_j = 1, j ∉ u).
///
/// For a product f = Π_j g_j of univariate functions of bounded variation the
/// Vitali quasi-differences factor, so the Vitali variation over the
/// coordinates u is Π_{j∈u} V(g_j) · Π_{j∉u} |g_j(1)|, and summing over u
///
///   V_HK(Π g_j) = Π_j (V(g_j) + |g_j(1)|) − Π_j |g_j(1)|.
///
/// For a monotone g, V(g) = |g(1) − g(0)|. For a smooth f whose mixed
/// derivative ∂²f/∂x∂y keeps one sign, V_Vitali = |f(1,1) − f(1,0) − f(0,1) +
/// f(0,0)| (the integral of |∂²f/∂x∂y|), and each face term is the 1D
/// variation of f(·,1) and f(1,·).
///
/// The test functions below are smooth and free of indicators, each with a
/// closed-form integral and V_HK derived this way.
#include <string>
#include <vector>

#include "stratum/analysis/measures.hpp"  // PointView

namespace stratum::analysis {

/// A 2D test function with its exact integral and Hardy–Krause variation.
struct VariationTestFunction {
  std::string name;        ///< "xy", "exp-sum", ...
  std::string formula;     ///< as shown on the page
  double integral = 0;     ///< ∫_{[0,1]²} f
  double variation = 0;    ///< V_HK(f), anchored at 1
  std::string derivation;  ///< how V_HK was obtained, one line
  double (*f)(double x, double y) = nullptr;
};

/// x·y, e^(x+y), 1/((1+x)(1+y)), sin(πx)·sin(πy) (products: the product
/// formula above) and e^(xy) (mixed derivative (1+xy)e^(xy) > 0).
const std::vector<VariationTestFunction>& variation_test_functions();

/// V_HK of g(x)·h(y) from V(g), V(h), g(1), h(1) (the product formula, d = 2).
double product_variation(double variation_g, double g_at_1, double variation_h, double h_at_1);

/// One side of the inequality for one point set and one function.
struct KoksmaHlawkaCheck {
  std::string function;
  double estimate = 0;  ///< (1/N) Σ f(p_i)
  double error = 0;     ///< |estimate − integral|
  double bound = 0;     ///< V_HK(f) · D*_N
  bool holds = false;   ///< error ≤ bound (up to 1e-12 relative rounding of the sum)
};

/// The D*_N the inequality is checked with, when the caller has none: the
/// registry's `star` measure, exact where it is (2D: N ≤ 2^18), above that
/// Thiémard's upper bound (the inequality stays true with any upper bound).
struct KoksmaHlawkaStar {
  double value = 0;
  std::string kind;  ///< "exact" or "upper bound"
};
KoksmaHlawkaStar koksma_hlawka_star(const PointView& points, unsigned threads);

/// Evaluates every test function on `points` (2D, in [0,1]) and compares
/// with V_HK(f) · `star_discrepancy` (the caller's D*_N of the same points).
std::vector<KoksmaHlawkaCheck> koksma_hlawka_checks(const PointView& points, double star_discrepancy);

}  // namespace stratum::analysis
