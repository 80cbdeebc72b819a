/// The studies part of the compiled module, in two sections:
/// integrands/integrate/converge first, then the dimension and importance
/// studies. Each section binds its functions from its own bind_* function.
#include <limits>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/integrate_tolerance.hpp"
#include "stratum/analysis/dimension_study.hpp"
#include "stratum/analysis/importance_study.hpp"
#include "stratum/analysis/mis_study.hpp"
#include "stratum/analysis/integrands.hpp"
#include "stratum/registry/spec.hpp"
#include "stratum/util/error.hpp"

namespace py = pybind11;

namespace stratum::python {

// ============================================================================
// Section: integrands(), integrate(), converge()
// ============================================================================
namespace {
namespace sa = stratum::analysis;

py::array_t<double> to_array(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::list integrand_list() {
  py::list list;
  for (const auto& info : sa::integrands()) {
    const py::list params = params_list(info.params);
    list.append(py::dict(py::arg("name") = info.name, py::arg("description") = info.description,
                         py::arg("min_dim") = info.min_dim, py::arg("max_dim") = info.max_dim,
                         py::arg("default_dim") = info.default_dim, py::arg("properties") = info.properties,
                         py::arg("params") = params));
  }
  return list;
}

py::dict integrate(const std::string& integrand, unsigned d, const sa::IntegrandParams& params,
                   const std::string& sampler, const std::string& randomize, std::uint64_t n, unsigned runs,
                   std::uint64_t seed, unsigned threads, double confidence, std::optional<double> abs_tol,
                   std::optional<double> rel_tol, std::optional<std::uint64_t> max_n) {
  sa::IntegrationRequest request;
  request.integrand = {integrand, d, params};
  const SamplerSpec spec = combine_sampler_options(sampler, {}, randomize);
  request.sampler = {spec.name, spec.randomize, spec.params};
  request.n = n;
  request.runs = runs;
  request.seed = seed;
  request.threads = threads;
  request.confidence = confidence;
  const sa::ToleranceOptions options{abs_tol, rel_tol, max_n};
  const bool to_tolerance = options.any();
  sa::ToleranceResult tolerance;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    tolerance = sa::integrate_with(request, options);
  }
  const sa::IntegrationResult& r = tolerance.result;
  py::dict out(py::arg("integrand") = r.integrand, py::arg("sampler") = r.sampler, py::arg("randomize") = r.randomize,
               py::arg("d") = r.d, py::arg("n") = r.n, py::arg("runs") = r.runs, py::arg("estimate") = r.estimate,
               py::arg("standard_error") = r.standard_error, py::arg("standard_error_kind") = r.standard_error_kind,
               py::arg("exact") = r.exact, py::arg("error") = r.error, py::arg("seconds") = r.seconds,
               py::arg("run_estimates") = to_array(r.run_estimates), py::arg("confidence") = r.confidence,
               py::arg("interval") = py::make_tuple(r.interval_low, r.interval_high),
               py::arg("half_width") = r.half_width, py::arg("seconds_per_run") = r.seconds_per_run,
               py::arg("efficiency") = r.efficiency);
  if (to_tolerance) {
    py::list steps;
    for (const auto& step : tolerance.steps)
      steps.append(py::dict(py::arg("n") = step.n, py::arg("estimate") = step.estimate,
                            py::arg("half_width") = step.half_width, py::arg("target") = step.target,
                            py::arg("seconds") = step.seconds));
    out["tolerance"] =
        py::dict(py::arg("abs_tol") = abs_tol.value_or(0), py::arg("rel_tol") = rel_tol.value_or(0),
                 py::arg("target") = tolerance.target, py::arg("met") = tolerance.met, py::arg("steps") = steps);
  }
  return out;
}

py::dict converge(const std::string& integrand, unsigned d, const sa::IntegrandParams& params,
                  const std::vector<std::string>& samplers, const std::vector<std::uint64_t>& counts, unsigned runs,
                  std::uint64_t seed, unsigned threads, bool skip_refused_counts, double confidence) {
  sa::ConvergenceRequest request;
  request.skip_refused_counts = skip_refused_counts;
  request.confidence = confidence;
  request.integrand = {integrand, d, params};
  for (const auto& text : samplers) request.samplers.push_back(sa::parse_sampler_choice(text));
  request.counts = counts;
  request.runs = runs;
  request.seed = seed;
  request.threads = threads;
  sa::ConvergenceResult result;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    result = sa::run_convergence(request);
  }
  py::dict per_sampler;
  for (const auto& entry : result.samplers) {
    std::vector<double> mean_error, rmse, variance, seconds, efficiency;
    std::vector<std::uint64_t> sampler_counts;
    py::list skipped;
    for (const auto& skip : entry.skipped)
      skipped.append(py::dict(py::arg("n") = skip.n, py::arg("reason") = skip.reason));
    for (const auto& row : entry.rows) {
      sampler_counts.push_back(row.n);
      mean_error.push_back(row.mean_error);
      rmse.push_back(row.rmse);
      variance.push_back(row.variance);
      seconds.push_back(row.seconds);
      efficiency.push_back(row.efficiency);
    }
    per_sampler[py::str(entry.sampler.name + ":" + entry.sampler.randomize)] = py::dict(
        py::arg("name") = entry.sampler.name, py::arg("randomize") = entry.sampler.randomize,
        py::arg("n") =
            py::array_t<std::uint64_t>(static_cast<py::ssize_t>(sampler_counts.size()), sampler_counts.data()),
        py::arg("skipped") = skipped, py::arg("mean_error") = to_array(mean_error), py::arg("rmse") = to_array(rmse),
        py::arg("variance") = to_array(variance), py::arg("seconds") = to_array(seconds),
        py::arg("efficiency") = to_array(efficiency), py::arg("fitted") = entry.fitted,
        py::arg("slope") = entry.slope.slope, py::arg("slope_standard_error") = entry.slope.slope_standard_error,
        py::arg("intercept") = entry.slope.intercept,
        py::arg("slope_interval") = py::make_tuple(entry.interval.low, entry.interval.high),
        py::arg("slope_confidence") = entry.interval.confidence,
        py::arg("slope_sampling_standard_error") = entry.interval.standard_error);
  }
  py::array_t<std::uint64_t> n_array(static_cast<py::ssize_t>(counts.size()));
  std::copy(counts.begin(), counts.end(), n_array.mutable_data());
  return py::dict(py::arg("integrand") = result.integrand, py::arg("d") = result.d, py::arg("exact") = result.exact,
                  py::arg("runs") = result.runs, py::arg("n") = n_array, py::arg("samplers") = per_sampler);
}

void bind_integrate_converge(py::module_& m) {
  m.def("integrands", &integrand_list, "Every test integrand as a dict");
  m.def("integrate", &integrate, py::arg("integrand"), py::arg("d"), py::arg("params"), py::arg("sampler"),
        py::arg("randomize"), py::arg("n"), py::arg("runs"), py::arg("seed"), py::arg("threads"), py::arg("confidence"),
        py::arg("abs_tol"), py::arg("rel_tol"), py::arg("max_n"));
  m.def("converge", &converge, py::arg("integrand"), py::arg("d"), py::arg("params"), py::arg("samplers"),
        py::arg("counts"), py::arg("runs"), py::arg("seed"), py::arg("threads"), py::arg("skip_refused_counts"),
        py::arg("confidence"));
  m.attr("default_counts") = sa::default_counts;
  m.def("parse_counts", [](const std::string& text) { return sa::parse_counts(text); });
}
}  // namespace

// ============================================================================
// Section: study_dimension(), study_importance()
// ============================================================================
namespace {
namespace sa = stratum::analysis;

template <class T>
py::array_t<T> column(const std::vector<T>& values) {
  py::array_t<T> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::dict study_dimension(unsigned min_dim, unsigned max_dim, std::uint64_t min_n, std::uint64_t max_n, unsigned runs,
                         const std::string& rule, const std::string& integrand, bool sobol, std::uint64_t seed,
                         unsigned threads) {
  sa::DimensionStudyRequest request;
  request.min_dim = min_dim, request.max_dim = max_dim, request.min_n = min_n, request.max_n = max_n;
  request.runs = runs, request.rule = rule, request.integrand = integrand, request.sobol = sobol;
  request.seed = seed, request.threads = threads;
  sa::DimensionStudy study;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    study = sa::run_dimension_study(request);
  }
  py::list series;
  for (const auto& s : study.series)
    series.append(py::dict(py::arg("d") = s.d, py::arg("exact") = s.exact, py::arg("variance") = s.variance,
                           py::arg("m") = column(s.m), py::arg("n") = column(s.n),
                           py::arg("product_error") = column(s.product_error), py::arg("mc_rmse") = column(s.mc_rmse),
                           py::arg("mc_predicted") = column(s.mc_predicted),
                           py::arg("sobol_rmse") = column(s.sobol_rmse), py::arg("product_slope") = s.product_slope,
                           py::arg("product_predicted_slope") = s.product_predicted_slope,
                           py::arg("mc_slope") = s.mc_slope, py::arg("sobol_slope") = s.sobol_slope));
  return py::dict(py::arg("rule") = study.rule, py::arg("integrand") = study.integrand, py::arg("runs") = study.runs,
                  py::arg("series") = series);
}

/// One comparison list as columns: numpy arrays keyed by field, "_a"/"_b" per method.
py::dict comparison_columns(const std::vector<sa::ImportanceComparison>& list) {
  py::dict out;
  std::vector<std::string> scene, method_a, method_b;
  std::vector<double> size, distance, exact, ratio, ratio_se, predicted_ratio, time_ratio, efficiency_ratio;
  for (const auto& c : list) {
    scene.push_back(c.scene), method_a.push_back(c.a.method), method_b.push_back(c.b.method);
    size.push_back(c.size), distance.push_back(c.distance), exact.push_back(c.exact);
    ratio.push_back(c.variance_ratio), ratio_se.push_back(c.variance_ratio_stderr);
    predicted_ratio.push_back(c.predicted_variance_ratio), time_ratio.push_back(c.time_ratio);
    efficiency_ratio.push_back(c.efficiency_ratio);
  }
  out["scene"] = scene, out["method_a"] = method_a, out["method_b"] = method_b;
  out["size"] = column(size), out["distance"] = column(distance), out["exact"] = column(exact);
  for (const char* side : {"a", "b"}) {
    std::vector<double> estimate, estimate_se, variance, variance_se, predicted, seconds, efficiency;
    for (const auto& c : list) {
      const sa::MethodResult& m = side[0] == 'a' ? c.a : c.b;
      estimate.push_back(m.estimate), estimate_se.push_back(m.estimate_stderr), variance.push_back(m.variance);
      variance_se.push_back(m.variance_stderr), predicted.push_back(m.predicted_variance);
      seconds.push_back(m.seconds_per_sample), efficiency.push_back(m.efficiency);
    }
    const std::string suffix = std::string("_") + side;
    out[py::str("estimate" + suffix)] = column(estimate);
    out[py::str("estimate_stderr" + suffix)] = column(estimate_se);
    out[py::str("variance" + suffix)] = column(variance);
    out[py::str("variance_stderr" + suffix)] = column(variance_se);
    out[py::str("predicted_variance" + suffix)] = column(predicted);
    out[py::str("seconds_per_sample" + suffix)] = column(seconds);
    out[py::str("efficiency" + suffix)] = column(efficiency);
  }
  out["variance_ratio"] = column(ratio), out["variance_ratio_stderr"] = column(ratio_se);
  out["predicted_variance_ratio"] = column(predicted_ratio), out["time_ratio"] = column(time_ratio);
  out["efficiency_ratio"] = column(efficiency_ratio);
  return out;
}

py::dict study_importance(unsigned runs, std::uint64_t samples, const std::vector<double>& sizes,
                          const std::vector<double>& distances, double radiance, std::uint64_t seed, unsigned threads) {
  sa::ImportanceStudyRequest request;
  request.runs = runs, request.samples = samples, request.sizes = sizes, request.distances = distances;
  request.radiance = radiance, request.seed = seed, request.threads = threads;
  sa::ImportanceStudy study;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    study = sa::run_importance_study(request);
  }
  return py::dict(py::arg("runs") = study.runs, py::arg("samples") = study.samples,
                  py::arg("hemisphere") = comparison_columns(study.hemisphere),
                  py::arg("light") = comparison_columns(study.light));
}

/// The MIS study as columns (one row per (exponent, angle), exponents outer),
/// each method's fields suffixed by its name: variance_light, ...
py::dict study_mis(const std::vector<double>& exponents, const std::vector<double>& angles, unsigned runs,
                   std::uint64_t samples, double beta, std::uint64_t seed, unsigned threads) {
  sa::MisStudyRequest request;
  request.exponents = exponents, request.angles = angles, request.runs = runs, request.samples = samples;
  request.beta = beta, request.seed = seed, request.threads = threads;
  sa::MisStudy study;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    study = sa::run_mis_study(request);
  }
  std::vector<double> exponent, angle, exact, balance_over_best, power_over_best, balance_bound;
  std::vector<std::string> best;
  for (const auto& c : study.cases) {
    exponent.push_back(c.exponent), angle.push_back(c.angle), exact.push_back(c.exact);
    balance_over_best.push_back(c.balance_over_best), power_over_best.push_back(c.power_over_best);
    balance_bound.push_back(c.balance_bound), best.push_back(c.best_single);
  }
  py::dict out(py::arg("runs") = study.runs, py::arg("samples") = study.samples, py::arg("beta") = study.beta,
               py::arg("exponent") = column(exponent), py::arg("angle") = column(angle),
               py::arg("exact") = column(exact), py::arg("best_single") = best,
               py::arg("balance_over_best") = column(balance_over_best),
               py::arg("power_over_best") = column(power_over_best), py::arg("balance_bound") = column(balance_bound));
  for (std::size_t m = 0; m < (study.cases.empty() ? 0 : study.cases.front().methods.size()); ++m) {
    std::vector<double> estimate, estimate_se, variance, variance_se, predicted;
    for (const auto& c : study.cases) {
      const sa::MisMethodResult& r = c.methods[m];
      estimate.push_back(r.estimate), estimate_se.push_back(r.estimate_stderr), variance.push_back(r.variance);
      variance_se.push_back(r.variance_stderr), predicted.push_back(r.predicted_variance);
    }
    const std::string suffix = "_" + study.cases.front().methods[m].method;
    out[py::str("estimate" + suffix)] = column(estimate);
    out[py::str("estimate_stderr" + suffix)] = column(estimate_se);
    out[py::str("variance" + suffix)] = column(variance);
    out[py::str("variance_stderr" + suffix)] = column(variance_se);
    out[py::str("predicted_variance" + suffix)] = column(predicted);
  }
  return out;
}

void bind_dimension_importance(py::module_& m) {
  m.def("study_mis", &study_mis, py::arg("exponents"), py::arg("angles"), py::arg("runs"), py::arg("samples"),
        py::arg("beta"), py::arg("seed"), py::arg("threads"));
  m.def("study_dimension", &study_dimension, py::arg("min_dim"), py::arg("max_dim"), py::arg("min_n"), py::arg("max_n"),
        py::arg("runs"), py::arg("rule"), py::arg("integrand"), py::arg("sobol"), py::arg("seed"), py::arg("threads"));
  m.def("study_importance", &study_importance, py::arg("runs"), py::arg("samples"), py::arg("sizes"),
        py::arg("distances"), py::arg("radiance"), py::arg("seed"), py::arg("threads"));
  m.def("rectangle_irradiance", [](const std::array<double, 3>& corner, const std::array<double, 3>& edge_u,
                                   const std::array<double, 3>& edge_v, double radiance) {
    return sa::rectangle_irradiance({corner, edge_u, edge_v, radiance});
  });
}
}  // namespace

void bind_studies(py::module_& m) {
  bind_integrate_converge(m);    // section "estimators"
  bind_dimension_importance(m);  // section "studies"
}

}  // namespace stratum::python
