/// Multiple importance sampling study: see src/analysis/include/stratum/analysis/mis_study.hpp.
#include "stratum/analysis/mis_study.hpp"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "stratum/distributed.hpp"
#include "stratum/estimators/mis.hpp"
#include "stratum/estimators/running_stats.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::analysis {

namespace {

constexpr double pi = std::numbers::pi;
const std::array<std::string, 4> method_names{"light", "bsdf", "balance", "power"};

/// The lobe and the light as functions of t = cos θ (everything is
/// symmetric about the normal, so φ never matters and is not sampled).
struct Setup {
  double e = 0, c = 0;  ///< exponent, cos α
  double lobe(double t) const { return (e + 1) / (2 * pi) * std::pow(t, e); }
  double light() const { return 1 / (2 * pi * (1 - c)); }
  bool on_light(double t) const { return t >= c; }
};

/// ∫_c^1 g(t) dt by 8-point Gauss–Legendre on panels that shrink
/// geometrically towards t = 1, where a sharp lobe (t^1000) has its mass.
template <class G>
double graded_integral(double c, const G& g) {
  static const std::array<double, 8> x{-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                       -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                       0.7966664774136267,  0.9602898564975363};
  static const std::array<double, 8> w{0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                       0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double sum = 0, left = c;
  for (int k = 1; k <= 81; ++k) {
    const double right = k == 81 ? 1.0 : 1 - (1 - c) * std::pow(0.75, k);
    const double mid = (left + right) / 2, half = (right - left) / 2;
    for (int i = 0; i < 8; ++i) sum += w[i] * half * g(mid + half * x[i]);
    left = right;
  }
  return sum;
}

/// Variance of w·f/p under p for one strategy ("light" or "bsdf") and a weight w(t).
template <class Weight>
double strategy_variance(const Setup& s, bool light, const Weight& weight) {
  const auto pdf = [&](double t) { return light ? s.light() : s.lobe(t); };
  const double second = graded_integral(s.c, [&](double t) {
    const double wf = weight(t) * s.lobe(t);
    return wf == 0 ? 0.0 : 2 * pi * wf * wf / pdf(t);  // 0 where the lobe underflows (t^1000 at small t)
  });
  const double first = graded_integral(s.c, [&](double t) { return 2 * pi * weight(t) * s.lobe(t); });
  return second - first * first;
}

/// The weight of a strategy's sample, equal sample counts on both sides
/// (the heuristics of estimators/mis.hpp, which the measured runs use too).
double heuristic_weight(double self, double other, bool power, double beta) {
  return power ? estimators::power_heuristic(1, self, 1, other, beta)
               : estimators::balance_heuristic(1, self, 1, other);
}

/// One replicate's mean and per-sample variance.
struct Replicate {
  double mean = 0, variance = 0;
};

Replicate run_replicate(const Setup& s, int method, std::uint64_t samples, double beta, std::uint64_t stream,
                        std::uint64_t run) {
  const auto light_t = [&](std::uint64_t i) { return 1 - uniform01(stream, run, i, 0) * (1 - s.c); };
  const auto lobe_t = [&](std::uint64_t i) { return std::pow(uniform01(stream, run, i, 1), 1 / (s.e + 1)); };
  if (method < 2) {
    estimators::RunningStats stats;
    for (std::uint64_t i = 0; i < samples; ++i) {
      if (method == 0) {
        stats.add(s.lobe(light_t(i)) / s.light());
      } else {
        stats.add(s.on_light(lobe_t(i)) ? 1.0 : 0.0);
      }
    }
    return {stats.mean(), stats.variance()};
  }
  const double m = static_cast<double>(samples / 2);
  estimators::MisEstimator mis(m, m, method == 2 ? estimators::MisHeuristic::balance : estimators::MisHeuristic::power,
                               beta);
  for (std::uint64_t i = 0; i < samples / 2; ++i) {
    const double a = light_t(i);
    mis.add_a(s.lobe(a), s.light(), s.lobe(a));
    const double b = lobe_t(i);
    const bool lit = s.on_light(b);
    mis.add_b(lit ? s.lobe(b) : 0.0, s.lobe(b), lit ? s.light() : 0.0);
  }
  return {mis.estimate(), static_cast<double>(samples) * mis.variance()};
}

}  // namespace

void validate(const MisStudyRequest& request) {
  require(!request.exponents.empty() && request.exponents.size() <= 64, "exponents", request.exponents.size(),
          "give 1 to 64 Phong exponents");
  for (double e : request.exponents)
    require(std::isfinite(e) && e >= 0 && e <= 100000, "exponent", e, "Phong exponents must be in [0, 100000]");
  require(!request.angles.empty() && request.angles.size() <= 64, "angles", request.angles.size(),
          "give 1 to 64 light half-angles");
  for (double a : request.angles)
    require(std::isfinite(a) && a > 0 && a <= 90, "angle", a, "light half-angles must be in (0, 90] degrees");
  require(request.runs >= 2 && request.runs <= 100000, "runs", request.runs, "must be in [2, 100000]");
  require(request.samples >= 4 && request.samples % 2 == 0 && request.samples <= (std::uint64_t{1} << 32), "samples",
          request.samples, "must be even, in [4, 2^32] (the MIS methods take half from each strategy)");
  require(std::isfinite(request.beta) && request.beta > 0 && request.beta <= 16, "beta", request.beta,
          "must be in (0, 16]");
  require(request.threads >= 1 && request.threads <= 1024, "threads", request.threads, "must be in [1, 1024]");
}

double mis_predicted_variance(const std::string& method, double exponent, double angle_degrees, double beta) {
  const Setup s{exponent, std::cos(angle_degrees * pi / 180)};
  // The single strategies in closed form (no cancellation when I ≈ 1):
  // with q = 1 − c^(e+1) = I, bsdf's estimator is the indicator of the cap,
  // Var = q (1 − q); light's second moment is ∫_cap p_bsdf² / p_light dω =
  // (1 − c)(e + 1)² (1 − c^(2e+1)) / (2e + 1).
  const double tail = std::exp((exponent + 1) * std::log(s.c));  // c^(e+1)
  const double q = -std::expm1((exponent + 1) * std::log(s.c));
  if (method == "light")
    return (1 - s.c) * (exponent + 1) * (exponent + 1) * -std::expm1((2 * exponent + 1) * std::log(s.c)) /
               (2 * exponent + 1) -
           q * q;
  if (method == "bsdf") return q * tail;
  const bool power = method == "power";
  if (!power && method != "balance")
    throw invalid_argument("method", method, "must be one of light, bsdf, balance, power");
  // N/2 samples of each strategy: N · (V_l/(N/2) + V_b/(N/2)) = 2 (V_l + V_b).
  const double v_light =
      strategy_variance(s, true, [&](double t) { return heuristic_weight(s.light(), s.lobe(t), power, beta); });
  const double v_bsdf =
      strategy_variance(s, false, [&](double t) { return heuristic_weight(s.lobe(t), s.light(), power, beta); });
  return 2 * (v_light + v_bsdf);
}

MisStudy run_mis_study(const MisStudyRequest& request) {
  validate(request);
  const std::size_t cases = request.exponents.size() * request.angles.size(), runs = request.runs;
  const std::size_t per_case = method_names.size() * runs;
  // Tasks (case, method, run): mean and per-sample variance each.
  std::vector<double> results(2 * cases * per_case);
  const distributed::Dealt mine = distributed::dealt(cases * per_case);  // a distributed job's share
  tbb::task_arena arena(static_cast<int>(request.threads));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, mine.size(), [&](std::size_t j) {
      check_interrupt();
      const std::size_t task = mine[j];
      const std::size_t k = task / per_case, method = (task % per_case) / runs, run = task % runs;
      const Setup s{request.exponents[k / request.angles.size()],
                    std::cos(request.angles[k % request.angles.size()] * pi / 180)};
      const Replicate r = run_replicate(s, static_cast<int>(method), request.samples, request.beta,
                                        hash64(request.seed, k, method), run);
      results[2 * task] = r.mean, results[2 * task + 1] = r.variance;
    });
  });
  distributed::gather_dealt(results, cases * per_case);

  MisStudy study{request.runs, request.samples, request.beta, {}};
  for (std::size_t k = 0; k < cases; ++k) {
    MisCase c;
    c.exponent = request.exponents[k / request.angles.size()];
    c.angle = request.angles[k % request.angles.size()];
    c.exact = -std::expm1((c.exponent + 1) * std::log(std::cos(c.angle * pi / 180)));
    for (std::size_t m = 0; m < method_names.size(); ++m) {
      estimators::RunningStats means, variances;
      for (std::size_t r = 0; r < runs; ++r) {
        const std::size_t task = k * per_case + m * runs + r;
        means.add(results[2 * task]);
        variances.add(results[2 * task + 1]);
      }
      c.methods.push_back({method_names[m], means.mean(), std::sqrt(means.variance() / double(runs)), variances.mean(),
                           std::sqrt(variances.variance() / double(runs)),
                           mis_predicted_variance(method_names[m], c.exponent, c.angle, request.beta)});
    }
    const double light = c.methods[0].predicted_variance, bsdf = c.methods[1].predicted_variance;
    c.best_single = light <= bsdf ? "light" : "bsdf";
    const double best = std::min(light, bsdf);
    const auto over_best = [&](double v) { return best > 0 ? v / best : std::numeric_limits<double>::infinity(); };
    c.balance_over_best = over_best(c.methods[2].predicted_variance);
    c.power_over_best = over_best(c.methods[3].predicted_variance);
    c.balance_bound = 2 * best + c.exact * c.exact;
    study.cases.push_back(std::move(c));
  }
  return study;
}

}  // namespace stratum::analysis
