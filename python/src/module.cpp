/// The compiled half of the Python package: the registry exposed to numpy.
/// Point buffers are handed to numpy without a copy.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "stratum/memory.hpp"
#include "stratum/registry.hpp"
#include "stratum/registry/spec.hpp"
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
    const py::list params = stratum::python::params_list(s.params);
    const stratum::SamplerFlags& f = s.flags;
    const py::dict flags(py::arg("index_addressable") = f.index_addressable, py::arg("progressive") = f.progressive,
                         py::arg("frames_continue") = f.frames_continue, py::arg("self_randomized") = f.self_randomized,
                         py::arg("zero_two_net") = f.zero_two_net, py::arg("space_time") = f.space_time,
                         py::arg("prefix_unbiased") = f.prefix_unbiased);
    list.append(
        py::dict(py::arg("name") = s.name, py::arg("kind") = s.kind, py::arg("description") = s.description,
                 py::arg("min_dim") = s.min_dim, py::arg("max_dim") = s.max_dim, py::arg("flags") = flags,
                 py::arg("properties") = stratum::property_words(s), py::arg("randomizers") = s.randomizers,
                 py::arg("randomizer_family") = std::string(stratum::randomizer_family_name(s.randomization.family)),
                 py::arg("counts") = s.counts, py::arg("params") = params));
  }
  return list;
}

/// `sampler` is a spec (docs/samplers.md); `params` and `randomize` are folded
/// in as the CLI folds in -p and --randomize (a key or randomizer given twice
/// is an error naming both).
py::array_t<double> points(const std::string& sampler, std::optional<std::uint64_t> n, unsigned d, std::uint64_t seed,
                           std::uint64_t start, const std::string& randomize, std::optional<double> radius,
                           std::int64_t threads, const std::map<std::string, std::string>& params) {
  std::vector<std::string> items;
  for (const auto& [key, value] : params) items.push_back(key + "=" + value);
  const stratum::SamplerSpec spec = stratum::combine_sampler_options(sampler, items, randomize);
  stratum::SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  request.start = start;
  request.randomize = spec.randomize;
  request.radius = radius;
  request.threads = stratum::resolve_threads(threads);
  request.params = spec.params;
  stratum::PointSet result;
  {
    stratum::python::InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    result = stratum::generate_points(spec.name, request);
  }
  return to_numpy(std::move(result));
}

}  // namespace

PYBIND11_MODULE(_stratum, m) {
  m.doc() = "stratum: Monte Carlo and quasi-Monte Carlo sampling (compiled core)";
  py::register_exception<stratum::invalid_argument>(m, "InvalidArgument", PyExc_ValueError);
  py::register_exception<stratum::memory_error>(m, "MemoryLimitError", PyExc_MemoryError);
  stratum::python::register_interrupted(m);  // Ctrl-C in a long call: KeyboardInterrupt
  m.def("samplers", &sampler_list, "Every registry sampler as a dict");
  m.def(
      "randomizers", [] { return stratum::randomizers(); }, "Every randomizer (name, description)");
  m.def("points", &points, py::arg("sampler"), py::arg("n"), py::arg("d"), py::arg("seed"), py::arg("start"),
        py::arg("randomize"), py::arg("radius"), py::arg("threads"), py::arg("params"));
  m.def("max_coordinates", &stratum::max_coordinates);
  m.def(
      "parse_spec",
      [](const std::string& text) {
        const stratum::SamplerSpec spec = stratum::parse_sampler_spec(text);
        return py::dict(py::arg("name") = spec.name, py::arg("params") = spec.params,
                        py::arg("randomize") = spec.randomize);
      },
      py::arg("spec"), "A sampler spec NAME[(KEY=VALUE,...)][:RANDOMIZER] as a dict, checked against the registry");
  m.def(
      "format_spec",
      [](const std::string& name, const std::map<std::string, std::string>& params, const std::string& randomize) {
        return stratum::format_sampler_spec({name, params, randomize});
      },
      py::arg("name"), py::arg("params"), py::arg("randomize"), "The canonical text of a sampler spec");
  m.def("split_spec_list", &stratum::split_sampler_list, py::arg("text"),
        "A list of specs split on the commas outside parentheses");
  m.def("resolve_threads", &stratum::resolve_threads, py::arg("threads"),
        "The thread rule of every face: 0 = every core, else 1..1024");
  m.def("parse_seed", &stratum::parse_seed, py::arg("text"), "A seed: exactly the integers in [0, 2^64)");
  stratum::python::bind_schema(m);
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
