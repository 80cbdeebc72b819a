/// stratum.study_mitchell: Mitchell's (1992) comparison of patterns by
/// random-edge discrepancy, returned as a dict of plain Python values.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "stratum/analysis/convergence.hpp"
#include "stratum/analysis/mitchell_study.hpp"

namespace py = pybind11;

namespace stratum::python {

namespace {

py::dict mean_and_error(const analysis::MeanAndError& value) {
  return py::dict(py::arg("mean") = value.mean, py::arg("se") = value.error);
}

py::dict study_mitchell(const std::vector<std::size_t>& counts, std::size_t realizations, std::size_t lines,
                        std::uint64_t seed, unsigned threads, const std::vector<std::string>& extras) {
  analysis::MitchellStudyOptions options;
  options.counts = counts;
  options.realizations = realizations;
  options.lines = lines;
  options.seed = seed;
  options.threads = threads;
  for (const auto& extra : extras) {
    const auto choice = analysis::parse_sampler_choice(extra);
    options.extra_patterns.push_back({extra, choice.name, choice.params, choice.randomize});
  }
  analysis::MitchellStudy study;
  {
    InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
    study = analysis::run_mitchell_study(options);
  }
  py::list patterns;
  for (std::size_t p = 0; p < study.patterns.size(); ++p) {
    const auto& pattern = study.patterns[p];
    py::list cells;
    for (std::size_t requested : counts) {
      const auto& cell = study.cell(analysis::mitchell_pattern_id(pattern), requested);
      cells.append(py::dict(py::arg("requested") = cell.requested, py::arg("n") = cell.n,
                            py::arg("rms") = mean_and_error(cell.rms), py::arg("mean") = mean_and_error(cell.mean),
                            py::arg("max") = mean_and_error(cell.max), py::arg("rms_values") = cell.rms_values));
    }
    const auto& spectrum = study.spectra[p];
    patterns.append(
        py::dict(py::arg("label") = pattern.label, py::arg("sampler") = pattern.sampler,
                 py::arg("params") = pattern.params, py::arg("cells") = cells,
                 py::arg("spectrum") = py::dict(py::arg("n") = spectrum.n, py::arg("frequency") = spectrum.frequency,
                                                py::arg("power") = spectrum.power),
                 py::arg("example") = spectrum.example));
  }
  return py::dict(py::arg("study") = "mitchell", py::arg("measure") = "edge-random", py::arg("lines") = lines,
                  py::arg("realizations") = realizations, py::arg("seed") = seed, py::arg("counts") = counts,
                  py::arg("patterns") = patterns, py::arg("notes") = study.notes,
                  py::arg("table") = analysis::mitchell_table(study));
}

}  // namespace

void bind_mitchell(py::module_& m) {
  m.def("study_mitchell", &study_mitchell, py::arg("counts"), py::arg("realizations"), py::arg("lines"),
        py::arg("seed"), py::arg("threads"), py::arg("extras"),
        "Mitchell's comparison of patterns by random-edge discrepancy");
}

}  // namespace stratum::python
