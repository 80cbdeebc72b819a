/// Quadrature versus Monte Carlo as the dimension grows: see
/// src/analysis/include/stratum/analysis/dimension_study.hpp.
#include "stratum/analysis/dimension_study.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <boost/math/special_functions/legendre.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>

#include "stratum/analysis/integrands.hpp"
#include "stratum/distributed.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/interrupt.hpp"
#include "stratum/memory.hpp"

namespace stratum::analysis {

namespace {

constexpr std::uint64_t max_study_n = std::uint64_t{1} << 24;

/// Neumaier's compensated sum (Neumaier 1974, "Rundungsfehleranalyse einiger
/// Verfahren zur Summation endlicher Summen"): the rounding error of a sum of
/// N terms stays O(ε) instead of O(Nε), which matters when the midpoint
/// rule's error is 1e-12.
struct CompensatedSum {
  double sum = 0, compensation = 0;
  void add(double value) {
    const double t = sum + value;
    if (std::abs(sum) >= std::abs(value)) compensation += (sum - t) + value;
    else compensation += (value - t) + sum;
    sum = t;
  }
  double value() const { return sum + compensation; }
};

/// m^d, or max_study_n + 1 when that is larger (no overflow).
std::uint64_t capped_power(unsigned m, unsigned d) {
  std::uint64_t result = 1;
  for (unsigned j = 0; j < d; ++j) {
    result *= m;
    if (result > max_study_n) return max_study_n + 1;
  }
  return result;
}

template <class Body>
void in_arena(unsigned threads, Body&& body) {
  tbb::task_arena arena(static_cast<int>(threads));
  arena.execute(body);
}

/// Mean of f over N counter-based uniform points of stream (seed, run).
double monte_carlo_estimate(const PointFunction& f, unsigned d, std::uint64_t n, std::uint64_t seed,
                            std::uint64_t run) {
  std::vector<double> x(d);
  CompensatedSum sum;
  for (std::uint64_t i = 0; i < n; ++i) {
    for (unsigned j = 0; j < d; ++j) x[j] = uniform01(seed, run, i, j);
    sum.add(f(x.data(), d));
  }
  return sum.value() / static_cast<double>(n);
}

/// Mean of f over the first N points of an Owen-scrambled (hash-based,
/// Burley 2020) Sobol' sequence, generated in chunks through the registry.
double sobol_estimate(const PointFunction& f, unsigned d, std::uint64_t n, std::uint64_t seed) {
  constexpr std::uint64_t chunk = 16384;
  CompensatedSum sum;
  for (std::uint64_t start = 0; start < n; start += chunk) {
    SamplerRequest request;
    request.n = std::min(chunk, n - start);
    request.d = d;
    request.seed = seed;
    request.start = start;
    request.randomize = "owen-hash";
    const PointSet points = generate_points("sobol", request);
    for (std::size_t i = 0; i < points.n; ++i) sum.add(f(points.data.get() + i * d, d));
  }
  return sum.value() / static_cast<double>(n);
}

}  // namespace

QuadratureRule1D midpoint_rule(unsigned m) {
  require(m >= 1, "m", m, "must be a positive integer");
  QuadratureRule1D rule;
  rule.nodes.resize(m);
  rule.weights.assign(m, 1.0 / m);
  for (unsigned k = 0; k < m; ++k) rule.nodes[k] = (k + 0.5) / m;
  return rule;
}

QuadratureRule1D gauss_legendre_rule(unsigned m) {
  require(m >= 1 && m <= max_gauss_points, "m", m, "must be in [1, 256] for Gauss-Legendre");
  // legendre_p_zeros returns the non-negative zeros of P_m in increasing
  // order (0 first when m is odd); the others are their mirror images.
  const std::vector<double> zeros = boost::math::legendre_p_zeros<double>(static_cast<int>(m));
  std::vector<std::pair<double, double>> points;  // (node on [-1,1], weight)
  for (double x : zeros) {
    const double derivative = boost::math::legendre_p_prime<double>(static_cast<int>(m), x);
    const double weight = 2 / ((1 - x * x) * derivative * derivative);
    points.emplace_back(x, weight);
    if (x != 0) points.emplace_back(-x, weight);
  }
  std::sort(points.begin(), points.end());
  QuadratureRule1D rule;
  for (const auto& [x, w] : points) {
    rule.nodes.push_back(0.5 * (x + 1));
    rule.weights.push_back(0.5 * w);
  }
  return rule;
}

QuadratureRule1D product_rule_1d(std::string_view name, unsigned m) {
  if (name == "midpoint") return midpoint_rule(m);
  if (name == "gauss") return gauss_legendre_rule(m);
  throw invalid_argument("rule", name, "allowed: midpoint, gauss");
}

double tensor_product_integral(const PointFunction& f, unsigned d, const QuadratureRule1D& rule, unsigned threads) {
  const auto m = static_cast<unsigned>(rule.nodes.size());
  require(m >= 1 && rule.weights.size() == m, "rule", m, "needs as many weights as nodes (at least one)");
  require(d >= 1, "d", d, "must be a positive integer");
  require(threads >= 1, "threads", threads, "must be a positive integer");
  const std::uint64_t n = capped_power(m, d);
  require(n <= max_study_n, "N", "m^d", "must be at most 2^24 evaluations");
  constexpr std::uint64_t block = 4096;
  const std::uint64_t blocks = (n + block - 1) / block;
  std::vector<double> block_sums(blocks);
  const distributed::Share mine = distributed::share(blocks);  // a distributed job's processes share the blocks
  in_arena(threads, [&] {
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(mine.begin, mine.end),
                      [&](const tbb::blocked_range<std::uint64_t>& r) {
                        std::vector<unsigned> digit(d);
                        std::vector<double> x(d);
                        for (std::uint64_t b = r.begin(); b != r.end(); ++b) {
                          check_interrupt();
                          const std::uint64_t first = b * block, last = std::min(n, first + block);
                          std::uint64_t rest = first;
                          for (unsigned j = 0; j < d; ++j, rest /= m) digit[j] = static_cast<unsigned>(rest % m);
                          CompensatedSum sum;
                          for (std::uint64_t i = first; i < last; ++i) {
                            double weight = 1;
                            for (unsigned j = 0; j < d; ++j) {
                              x[j] = rule.nodes[digit[j]];
                              weight *= rule.weights[digit[j]];
                            }
                            sum.add(weight * f(x.data(), d));
                            for (unsigned j = 0; j < d && ++digit[j] == m; ++j) digit[j] = 0;  // odometer
                          }
                          block_sums[b] = sum.value();
                        }
                      });
  });
  distributed::gather_shares(block_sums, blocks);
  CompensatedSum total;
  for (double s : block_sums) total.add(s);
  return total.value();
}

std::vector<std::string> dimension_integrand_names() {
  std::vector<std::string> names{"sine-product"};
  for (const IntegrandInfo& info : integrands())
    if (info.max_dim >= 2 &&
        std::find(info.properties.begin(), info.properties.end(), "smooth") != info.properties.end())
      names.push_back(info.name);
  return names;
}

DimensionIntegrand dimension_integrand(std::string_view name, unsigned d) {
  require(d >= 1, "d", d, "must be a positive integer");
  if (name == "sine-product") {
    constexpr double pi = std::numbers::pi;
    DimensionIntegrand integrand;
    integrand.name = "sine-product";
    integrand.description = "prod_j (pi/2) sin(pi x_j): smooth, integral 1";
    integrand.f = [](const double* x, unsigned dim) {
      double product = 1;
      for (unsigned j = 0; j < dim; ++j) product *= 0.5 * pi * std::sin(pi * x[j]);
      return product;
    };
    integrand.exact = 1;
    // E[((π/2) sin πx)²] = π²/8 per axis.
    integrand.variance = std::pow(pi * pi / 8, static_cast<double>(d)) - 1;
    return integrand;
  }
  const auto names = dimension_integrand_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string allowed = "allowed (smooth integrands):";
    for (const auto& known : names) allowed += " " + known;
    throw invalid_argument("integrand", name, allowed);
  }
  // A smooth family of the integrand registry with its default parameters.
  std::shared_ptr<const Integrand> registered = make_integrand(name, d);
  DimensionIntegrand integrand;
  integrand.name = std::string(name);
  integrand.description = find_integrand(name).description;
  integrand.exact = registered->exact();
  integrand.f = [registered](const double* x, unsigned) {
    double value = 0;
    registered->evaluate(x, 1, &value);
    return value;
  };
  return integrand;
}

std::vector<unsigned> points_per_axis(const DimensionStudyRequest& request, unsigned d) {
  const unsigned m_cap = request.rule == "gauss" ? max_gauss_points : std::numeric_limits<unsigned>::max();
  std::vector<unsigned> result;
  std::uint64_t last = 0;
  for (unsigned m = 1; m <= m_cap; ++m) {
    const std::uint64_t n = capped_power(m, d);
    if (n > request.max_n) break;
    if (n < request.min_n) continue;
    if (last == 0 || n >= 2 * last) {  // about one m per doubling of N
      result.push_back(m);
      last = n;
    }
  }
  return result;
}

void validate(const DimensionStudyRequest& request) {
  require(request.min_dim >= 1 && request.min_dim <= 64, "min_dim", request.min_dim, "must be in [1, 64]");
  require(request.max_dim >= request.min_dim && request.max_dim <= 64, "max_dim", request.max_dim,
          "must be in [min_dim, 64]");
  require(request.min_n >= 1, "min_n", request.min_n, "must be a positive integer");
  require(request.max_n >= request.min_n && request.max_n <= max_study_n, "max_n", request.max_n,
          "must be in [min_n, 16777216]");
  require(request.runs >= 2 && request.runs <= 100000, "runs", request.runs, "must be in [2, 100000]");
  require(request.threads >= 1 && request.threads <= 1024, "threads", request.threads, "must be in [1, 1024]");
  (void)product_rule_1d(request.rule, 1);
  (void)dimension_integrand(request.integrand, request.min_dim);
  (void)dimension_integrand(request.integrand, request.max_dim);  // the registry's dimension range
  for (unsigned d = request.min_dim; d <= request.max_dim; ++d)
    if (points_per_axis(request, d).empty())
      throw invalid_argument("n", std::to_string(request.min_n) + ":" + std::to_string(request.max_n),
                             "must contain some m^d for every d; d = " + std::to_string(d) + " has none");
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y, double floor) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (!(y[i] > floor) || !(x[i] > 0) || !std::isfinite(y[i])) continue;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    ++count;
  }
  if (count < 2) return std::numeric_limits<double>::quiet_NaN();
  const double c = static_cast<double>(count);
  const double denominator = c * sxx - sx * sx;
  if (!(denominator > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (c * sxy - sx * sy) / denominator;
}

DimensionStudy run_dimension_study(const DimensionStudyRequest& request) {
  validate(request);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  DimensionStudy study{request.rule, request.integrand, request.runs, {}};
  struct Task {
    std::size_t series, point;
    unsigned run;
    bool sobol;
  };
  std::vector<Task> tasks;
  std::vector<DimensionIntegrand> integrands;
  for (unsigned d = request.min_dim; d <= request.max_dim; ++d) {
    DimensionSeries series;
    series.d = d;
    integrands.push_back(dimension_integrand(request.integrand, d));
    series.exact = integrands.back().exact;
    series.variance = integrands.back().variance;
    series.m = points_per_axis(request, d);
    for (unsigned m : series.m) series.n.push_back(capped_power(m, d));
    const std::size_t k = series.n.size();
    series.product_error.assign(k, nan);
    series.mc_rmse.assign(k, 0);
    series.mc_predicted.assign(k, nan);
    if (request.sobol) series.sobol_rmse.assign(k, 0);
    for (std::size_t i = 0; i < k; ++i) {
      if (std::isfinite(series.variance))
        series.mc_predicted[i] = std::sqrt(series.variance / static_cast<double>(series.n[i]));
      for (unsigned r = 0; r < request.runs; ++r) {
        tasks.push_back({study.series.size(), i, r, false});
        if (request.sobol) tasks.push_back({study.series.size(), i, r, true});
      }
    }
    study.series.push_back(std::move(series));
  }
  // Squared errors per task, stored by index and summed serially below:
  // the result does not depend on scheduling, nor on how a distributed job
  // shares the tasks out.
  if (request.sobol) {  // the memory guard: each Sobol' task holds its n x d points (Monte Carlo streams them)
    double largest = 0;
    std::string which;
    for (const DimensionSeries& series : study.series)
      for (const std::uint64_t n : series.n)
        if (double(n) * series.d > largest)
          largest = double(n) * series.d, which = std::to_string(n) + " x " + std::to_string(series.d);
    const double concurrent = std::min<double>(request.threads, double(tasks.size()));
    require_memory(concurrent * largest * sizeof(double),
                   to_message_string(concurrent) + " Sobol' runs at once of up to " + which + " points");
  }
  std::vector<double> squared_error(tasks.size());
  const distributed::Dealt mine = distributed::dealt(tasks.size());  // round-robin: every series shared
  in_arena(request.threads, [&] {
    tbb::parallel_for(std::size_t{0}, mine.size(), [&](std::size_t j) {
      check_interrupt();
      const std::size_t t = mine[j];
      const Task& task = tasks[t];
      const DimensionSeries& series = study.series[task.series];
      const std::uint64_t n = series.n[task.point];
      const std::uint64_t stream = hash64(request.seed, series.d, n, task.sobol ? 1 : 0);
      const double estimate = task.sobol
                                  ? sobol_estimate(integrands[task.series].f, series.d, n, hash64(stream, task.run))
                                  : monte_carlo_estimate(integrands[task.series].f, series.d, n, stream, task.run);
      squared_error[t] = (estimate - series.exact) * (estimate - series.exact);
    });
  });
  distributed::gather_dealt(squared_error, tasks.size());
  for (std::size_t s = 0; s < study.series.size(); ++s) {
    DimensionSeries& series = study.series[s];
    for (std::size_t i = 0; i < series.m.size(); ++i) {
      const QuadratureRule1D rule = product_rule_1d(request.rule, series.m[i]);
      series.product_error[i] =
          std::abs(tensor_product_integral(integrands[s].f, series.d, rule, request.threads) - series.exact);
    }
  }
  for (std::size_t t = 0; t < tasks.size(); ++t) {
    DimensionSeries& series = study.series[tasks[t].series];
    (tasks[t].sobol ? series.sobol_rmse : series.mc_rmse)[tasks[t].point] += squared_error[t] / request.runs;
  }
  for (DimensionSeries& series : study.series) {
    for (double& v : series.mc_rmse) v = std::sqrt(v);
    for (double& v : series.sobol_rmse) v = std::sqrt(v);
    std::vector<double> n(series.n.begin(), series.n.end());
    // Below ~1000 ε the error is rounding, not the rule: leave it out of the fit.
    const double floor = 1e3 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(series.exact));
    series.product_slope = log_log_slope(n, series.product_error, floor);
    series.product_predicted_slope = request.rule == "midpoint" ? -2.0 / series.d : nan;
    series.mc_slope = log_log_slope(n, series.mc_rmse);
    series.sobol_slope = request.sobol ? log_log_slope(n, series.sobol_rmse) : nan;
  }
  return study;
}

}  // namespace stratum::analysis
