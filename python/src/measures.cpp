/// The measure registry for Python (stratum.measure, stratum.measures,
/// stratum.discrepancy) and scipy's discrepancy functions
/// (stratum.qmc.discrepancy, stratum.qmc.update_discrepancy). Shapes and
/// types are checked in python/stratum/measures.py; this side takes C-ordered
/// float64 arrays and releases the GIL while computing.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "stratum/analysis/koksma_hlawka.hpp"
#include "stratum/analysis/l2_discrepancy.hpp"
#include "stratum/analysis/local_discrepancy.hpp"
#include "stratum/analysis/measures.hpp"
#include "stratum/util/error.hpp"

namespace py = pybind11;

namespace stratum::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
namespace sa = stratum::analysis;

sa::PointView view_of(const Array& x) {
  if (x.ndim() != 2)
    throw invalid_argument("x", "an array of " + std::to_string(x.ndim()) + " dimensions", "must have shape (n, d)");
  return {x.data(), static_cast<std::size_t>(x.shape(0)), static_cast<std::size_t>(x.shape(1))};
}

py::list measure_list() {
  py::list list;
  for (const auto& m : sa::measures()) {
    const py::list params = params_list(m.params);
    list.append(py::dict(py::arg("name") = m.name, py::arg("description") = m.description,
                         py::arg("min_dim") = m.min_dim, py::arg("max_dim") = m.max_dim, py::arg("params") = params));
  }
  return list;
}

py::dict measure(const Array& x, const std::string& name, unsigned threads,
                 const std::map<std::string, std::string>& params) {
  const sa::PointView view = view_of(x);
  sa::MeasureResult result;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    result = sa::compute_measure(name, view, {params, threads});
  }
  py::object lower = result.lower ? py::object(py::float_(*result.lower)) : py::object(py::none());
  py::object upper = result.upper ? py::object(py::float_(*result.upper)) : py::object(py::none());
  return py::dict(py::arg("value") = result.value, py::arg("kind") = result.kind, py::arg("lower") = lower,
                  py::arg("upper") = upper, py::arg("extras") = result.extras);
}

/// scipy's convention: CD, WD and MD squared, L2-star as the root (of a
/// possibly negative square under iterative=True, giving NaN as scipy does).
double scipy_discrepancy(const Array& x, const std::string& method, bool iterative, unsigned threads) {
  const sa::PointView view = view_of(x);
  sa::L2Kind kind = sa::L2Kind::centered;
  if (method == "L2-star") kind = sa::L2Kind::star;
  else if (method == "WD") kind = sa::L2Kind::wrap_around;
  else if (method == "MD") kind = sa::L2Kind::mixture;
  else if (method != "CD") throw invalid_argument("method", method, "allowed: CD, WD, MD, L2-star");
  sa::L2Options options;
  options.threads = threads;
  options.iterative = iterative;
  double squared = 0;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    squared = sa::l2_discrepancy_squared(kind, view, options);
  }
  return kind == sa::L2Kind::star ? std::sqrt(squared) : squared;
}

/// Δ on the (R+1)×(R+1) grid of corners as an array [j, i] (y = j/R, x = i/R).
py::array_t<double> local_discrepancy(const Array& x, std::int64_t resolution) {
  const sa::PointView view = view_of(x);
  require(view.d == 2, "d", view.d, "the local discrepancy needs 2D points");
  require(resolution >= 1 && resolution <= 4096, "resolution", resolution, "must be in [1, 4096]");
  sa::check_unit_cube(view);
  sa::LocalDiscrepancyGrid grid;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    grid = sa::local_discrepancy_grid(view, static_cast<std::size_t>(resolution));
  }
  const auto side = static_cast<py::ssize_t>(grid.resolution + 1);
  py::array_t<double> out({side, side});
  std::copy(grid.values.begin(), grid.values.end(), out.mutable_data());
  return out;
}

py::dict function_dict(const sa::VariationTestFunction& f) {
  return py::dict(py::arg("function") = f.name, py::arg("formula") = f.formula, py::arg("integral") = f.integral,
                  py::arg("variation") = f.variation, py::arg("derivation") = f.derivation);
}

py::list variation_test_functions() {
  py::list list;
  for (const auto& f : sa::variation_test_functions()) list.append(function_dict(f));
  return list;
}

/// One dict per test function: its description and the check against the
/// caller's D* (measures.py computes D* from the registry when not given).
py::list koksma_hlawka(const Array& x, double star) {
  const sa::PointView view = view_of(x);
  std::vector<sa::KoksmaHlawkaCheck> checks;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    checks = sa::koksma_hlawka_checks(view, star);
  }
  const auto& functions = sa::variation_test_functions();  // checks[i] is functions[i]
  py::list list;
  for (std::size_t i = 0; i < checks.size(); ++i) {
    py::dict row = function_dict(functions[i]);
    row["estimate"] = checks[i].estimate;
    row["error"] = checks[i].error;
    row["bound"] = checks[i].bound;
    row["holds"] = checks[i].holds;
    list.append(row);
  }
  return list;
}

/// (D*, "exact" | "upper bound"): the D* koksma_hlawka checks with by default.
py::tuple koksma_hlawka_star(const Array& x, unsigned threads) {
  const sa::PointView view = view_of(x);
  sa::KoksmaHlawkaStar star;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    star = sa::koksma_hlawka_star(view, threads);
  }
  return py::make_tuple(star.value, star.kind);
}

double update_centered(const Array& x_new, const Array& sample, double initial) {
  const sa::PointView view = view_of(sample);
  if (x_new.ndim() != 1 || static_cast<std::size_t>(x_new.shape(0)) != view.d)
    throw invalid_argument("x_new", "an array of shape mismatching the sample", "must have shape (d,)");
  return sa::l2_centered_update(x_new.data(), view, initial);
}

}  // namespace

void bind_measures(py::module_& m) {
  m.def("measures", &measure_list, "Every registry measure as a dict");
  m.def("measure", &measure, py::arg("x"), py::arg("name"), py::arg("threads"), py::arg("params"));
  m.def("scipy_discrepancy", &scipy_discrepancy, py::arg("x"), py::arg("method"), py::arg("iterative"),
        py::arg("threads"));
  m.def("local_discrepancy", &local_discrepancy, py::arg("x"), py::arg("resolution"));
  m.def("variation_test_functions", &variation_test_functions);
  m.def("koksma_hlawka", &koksma_hlawka, py::arg("x"), py::arg("star"));
  m.def("koksma_hlawka_star", &koksma_hlawka_star, py::arg("x"), py::arg("threads"));
  m.def("update_centered_discrepancy", &update_centered, py::arg("x_new"), py::arg("sample"), py::arg("initial"));
}

}  // namespace stratum::python
