#pragma once
/// Quadrature versus Monte Carlo as the dimension grows (LECTURE.md §6).
///
/// A product rule with m points per axis spends N = m^d evaluations; a rule
/// of order r on each axis (error O(m^-r) for a smooth integrand) therefore
/// has error O(N^(-r/d)) in d dimensions: the exponent shrinks with d. Monte
/// Carlo's root-mean-square error is σ/√N whatever d is (Metropolis, Ulam
/// 1949, "The Monte Carlo method"), so past d ≈ 2r Monte Carlo wins. The
/// study measures both on the same smooth integrand for a range of d and N,
/// and optionally randomized QMC (Owen-scrambled Sobol'), whose RMSE on a
/// smooth integrand falls faster than N^(-1/2) (Owen 1997, "Scrambled net
/// variance for integrals of smooth functions").
///
/// Two product rules:
///  - "midpoint": the composite midpoint rule, nodes (k + 1/2)/m, weights
///    1/m. Order r = 2 (error −(h²/24)∫f'' + O(h⁴)), so the error decays as
///    N^(−2/d): the lecture's N^(−1/d) picture with r = 2.
///  - "gauss": m-point Gauss–Legendre on [0,1] (nodes from Boost.Math's
///    legendre_p_zeros, weights 2/((1−x²)P'_m(x)²) mapped to [0,1], the
///    construction boost/math/quadrature/gauss.hpp uses for untabulated
///    orders). Exact for polynomials of degree < 2m in each variable;
///    on an analytic integrand its error falls geometrically in m =
///    N^(1/d), i.e. like exp(−c N^(1/d)): still a curse of dimension.
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace stratum::analysis {

/// One-dimensional rule on [0, 1]: nodes and weights (weights sum to 1).
struct QuadratureRule1D {
  std::vector<double> nodes;
  std::vector<double> weights;
};

/// Composite midpoint rule with m ≥ 1 points.
QuadratureRule1D midpoint_rule(unsigned m);

/// m-point Gauss–Legendre rule on [0, 1], 1 ≤ m ≤ max_gauss_points.
QuadratureRule1D gauss_legendre_rule(unsigned m);
inline constexpr unsigned max_gauss_points = 256;

/// The rule called `name` ("midpoint" or "gauss") with m points; throws
/// stratum::invalid_argument for other names.
QuadratureRule1D product_rule_1d(std::string_view name, unsigned m);

/// A function on [0,1]^d: f(x, d) with x pointing to d coordinates.
using PointFunction = std::function<double(const double* x, unsigned d)>;

/// Σ over the tensor grid of `rule`^d of Π weights · f(node): N = m^d
/// evaluations, in fixed blocks reduced in a fixed order (Neumaier sums), so
/// the result does not depend on the thread count.
double tensor_product_integral(const PointFunction& f, unsigned d, const QuadratureRule1D& rule, unsigned threads = 1);

/// A smooth test integrand on [0,1]^d with its exact integral and, where
/// known, its exact variance under the uniform distribution (so the Monte
/// Carlo RMSE σ/√N is known too).
struct DimensionIntegrand {
  std::string name;
  std::string description;
  PointFunction f;
  double exact = 0;
  double variance = std::numeric_limits<double>::quiet_NaN();  ///< NaN: unknown (every face shows it as its "none")
};

/// Names accepted by dimension_integrand().
std::vector<std::string> dimension_integrand_names();

/// The integrand `name` in d dimensions. "sine-product": Π_j (π/2) sin(π x_j),
/// integral 1, variance (π²/8)^d − 1; its midpoint sums have the closed form
/// (π / (2m sin(π/(2m))))^d. The smooth families of the integrand registry
/// (src/analysis/include/stratum/analysis/integrands.hpp: genz-oscillatory, genz-product-peak,
/// genz-corner-peak, genz-gaussian) are accepted by name with their default
/// parameters; their variance is left unknown.
DimensionIntegrand dimension_integrand(std::string_view name, unsigned d);

struct DimensionStudyRequest {
  unsigned min_dim = 1;
  unsigned max_dim = 10;
  std::uint64_t min_n = 16;        ///< smallest N (evaluations) per estimate
  std::uint64_t max_n = 1u << 18;  ///< largest N
  unsigned runs = 16;              ///< independent MC (and RQMC) repetitions per (d, N)
  std::string rule = "midpoint";   ///< "midpoint" or "gauss"
  std::string integrand = "sine-product";
  bool sobol = true;  ///< also Owen-scrambled (hash-based) Sobol' replicates
  std::uint64_t seed = 0;
  unsigned threads = 1;
};

/// Validates a request (names, ranges, runs) and throws
/// stratum::invalid_argument naming the argument.
void validate(const DimensionStudyRequest& request);

/// Points per axis of the product rule for dimension d: distinct m with
/// m^d in [min_n, max_n], m ≈ 2^(k/d) (about one value per doubling of N);
/// for "gauss" also m ≤ max_gauss_points.
std::vector<unsigned> points_per_axis(const DimensionStudyRequest& request, unsigned d);

/// Results for one dimension; vectors are indexed like n.
struct DimensionSeries {
  unsigned d = 0;
  double exact = 0;
  double variance = std::numeric_limits<double>::quiet_NaN();  ///< exact Var f, NaN when unknown (JSON null)
  std::vector<unsigned> m;                                     ///< points per axis
  std::vector<std::uint64_t> n;                                ///< N = m^d
  std::vector<double> product_error;                           ///< |Q − I|
  std::vector<double> mc_rmse;                                 ///< over `runs` independent MC estimates
  std::vector<double> mc_predicted;                            ///< σ/√N (NaN when σ unknown)
  std::vector<double> sobol_rmse;                              ///< empty unless request.sobol
  double product_slope = 0;            ///< least-squares log-log slope (NaN if < 2 usable points)
  double product_predicted_slope = 0;  ///< −r/d for the midpoint rule (r = 2); NaN for gauss
  double mc_slope = 0;
  double sobol_slope = 0;
};

struct DimensionStudy {
  std::string rule;
  std::string integrand;
  unsigned runs = 0;
  std::vector<DimensionSeries> series;
};

/// Runs the study: for every d and N, the product rule once, `runs` MC
/// estimates (uniform counter-based points) and, optionally, `runs`
/// Owen-scrambled Sobol' estimates. Parallel over (d, N, run) with oneTBB;
/// the result depends only on the request, not on the thread count.
DimensionStudy run_dimension_study(const DimensionStudyRequest& request);

/// Least-squares slope of log(y) against log(x) over points with y > floor;
/// NaN when fewer than two remain.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y, double floor = 0);

}  // namespace stratum::analysis
