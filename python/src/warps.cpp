/// The warp registry for Python (stratum.warps, stratum.warp, stratum.warp_pdf,
/// stratum.warp_invert). Parameters arrive flattened from
/// python/stratum/warps.py; shapes are checked here against the warp's
/// dimensions, and the registry checks u in [0,1) and finiteness.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "stratum/util/error.hpp"
#include "stratum/warp_registry.hpp"

namespace py = pybind11;

namespace stratum::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::list warp_list() {
  py::list list;
  for (const auto& w : warps()) {
    const py::list params = params_list(w.params);
    list.append(py::dict(py::arg("name") = w.name, py::arg("description") = w.description, py::arg("domain") = w.domain,
                         py::arg("measure") = w.measure, py::arg("area_preserving") = w.area_preserving,
                         py::arg("params") = params));
  }
  return list;
}

/// Rows of an (n, dim) array, or of an (n,) array when dim is 1.
std::size_t rows_of(const Array& x, unsigned dim, const char* what, const std::string& map) {
  const std::string shape_text = [&] {
    std::string text = "(";
    for (py::ssize_t k = 0; k < x.ndim(); ++k) text += (k ? ", " : "") + std::to_string(x.shape(k));
    return text + (x.ndim() == 1 ? ",)" : ")");
  }();
  const bool ok = (x.ndim() == 2 && x.shape(1) == dim) || (x.ndim() == 1 && dim == 1);
  if (!ok)
    throw invalid_argument(what, "array of shape " + shape_text,
                           map + " takes shape (n, " + std::to_string(dim) + ")" + (dim == 1 ? " or (n,)" : ""));
  return static_cast<std::size_t>(x.shape(0));
}

/// The result as (n, dim), or (n,) when the input was one-dimensional and dim is 1.
Array to_array(std::vector<double> values, std::size_t n, unsigned dim, bool flat) {
  Array out =
      flat ? Array(static_cast<py::ssize_t>(n)) : Array({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(dim)});
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

Array sample(const std::string& name, const Array& u, const WarpParams& params) {
  const auto warp = make_warp(name, params);
  const std::size_t n = rows_of(u, warp->input_dim(), "u", name);
  std::vector<double> p;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    p = warp_sample(*warp, u.data(), n);
  }
  return to_array(std::move(p), n, warp->output_dim(), u.ndim() == 1 && warp->output_dim() == 1);
}

Array pdf(const std::string& name, const Array& p, const WarpParams& params) {
  const auto warp = make_warp(name, params);
  const std::size_t n = rows_of(p, warp->output_dim(), "p", name);
  std::vector<double> density;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    density = warp_pdf(*warp, p.data(), n);
  }
  return to_array(std::move(density), n, 1, true);
}

Array invert(const std::string& name, const Array& p, const WarpParams& params) {
  const auto warp = make_warp(name, params);
  const std::size_t n = rows_of(p, warp->output_dim(), "p", name);
  std::vector<double> u;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    u = warp_invert(*warp, p.data(), n);
  }
  return to_array(std::move(u), n, warp->input_dim(), p.ndim() == 1 && warp->input_dim() == 1);
}

}  // namespace

void bind_warps(py::module_& m) {
  m.def("_warps", &warp_list, "Every registry warp as a dict");
  m.def("_warp_sample", &sample, py::arg("name"), py::arg("u"), py::arg("params"));
  m.def("_warp_pdf", &pdf, py::arg("name"), py::arg("p"), py::arg("params"));
  m.def("_warp_invert", &invert, py::arg("name"), py::arg("p"), py::arg("params"));
}

}  // namespace stratum::python
