/// The compiled half of the Python package: the registry exposed to numpy.
/// Point buffers are handed to numpy without a copy.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace py = pybind11;

namespace {

py::array_t<double> to_numpy(stratum::PointSet points) {
  double* data = points.data.release();
  py::capsule owner(data, [](void* p) { delete[] static_cast<double*>(p); });
  return py::array_t<double>({static_cast<py::ssize_t>(points.n), static_cast<py::ssize_t>(points.d)}, data, owner);
}

py::list sampler_list() {
  py::list list;
  for (const auto& s : stratum::samplers()) {
    py::list params;
    for (const auto& p : s.params)
      params.append(py::dict(py::arg("name") = p.name, py::arg("description") = p.description,
                             py::arg("default") = p.default_value));
    list.append(py::dict(py::arg("name") = s.name, py::arg("kind") = s.kind,
                         py::arg("description") = s.description, py::arg("min_dim") = s.min_dim,
                         py::arg("max_dim") = s.max_dim, py::arg("properties") = s.properties,
                         py::arg("randomizers") = s.randomizers, py::arg("counts") = s.counts,
                         py::arg("params") = params));
  }
  return list;
}

py::array_t<double> points(const std::string& name, std::optional<std::uint64_t> n, unsigned d, std::uint64_t seed,
                           std::uint64_t start, const std::string& randomize, std::optional<double> radius, unsigned threads,
                           const std::map<std::string, std::string>& params) {
  stratum::SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  request.start = start;
  request.randomize = randomize;
  request.radius = radius;
  request.threads = threads;
  request.params = params;
  stratum::PointSet result;
  {
    py::gil_scoped_release release;
    result = stratum::generate_points(name, request);
  }
  return to_numpy(std::move(result));
}

}  // namespace

PYBIND11_MODULE(_stratum, m) {
  m.doc() = "stratum: Monte Carlo and quasi-Monte Carlo sampling (compiled core)";
  py::register_exception<stratum::invalid_argument>(m, "InvalidArgument", PyExc_ValueError);
  m.def("samplers", &sampler_list, "Every registry sampler as a dict");
  m.def("randomizers", [] { return stratum::randomizers(); }, "Every randomizer (name, description)");
  m.def("points", &points, py::arg("name"), py::arg("n"), py::arg("d"), py::arg("seed"), py::arg("start"), py::arg("randomize"),
        py::arg("radius"), py::arg("threads"), py::arg("params"));
  m.def("max_coordinates", &stratum::max_coordinates);
  stratum::python::bind_warps(m);
  stratum::python::bind_measures(m);
  stratum::python::bind_spectra(m);
  stratum::python::bind_studies(m);
  stratum::python::bind_mitchell(m);
#ifdef STRATUM_HAS_RENDER
  stratum::python::bind_render(m);
#endif
#ifdef STRATUM_HAS_REPORT
  stratum::python::bind_report(m);
#endif
}
