/// The lecture report from Python: stratum.report(...) runs the same
/// sections as `stratum report` (only with the renderer built).
#ifdef STRATUM_HAS_REPORT
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "stratum/report/report.hpp"

namespace py = pybind11;

namespace stratum::python {

void bind_report(py::module_& m) {
  m.def("report_sections", [] {
    py::list sections;
    for (const auto& s : report::report_sections())
      sections.append(py::dict(py::arg("id") = s.id, py::arg("lecture") = s.lecture, py::arg("title") = s.title));
    return sections;
  });
  m.def("lecture_slides", [] {
    py::list slides;
    for (const auto& s : report::lecture_slides())
      slides.append(py::dict(py::arg("lecture") = s.lecture, py::arg("title") = s.title, py::arg("formula") = s.formula,
                             py::arg("section") = s.section, py::arg("anchor") = s.anchor));
    return slides;
  });
  m.def(
      "report",
      [](const std::string& directory, bool quick, const std::vector<std::string>& samplers,
         const std::vector<std::string>& only, unsigned threads, std::uint64_t seed, const std::string& cache,
         bool verbose) {
        report::ReportOptions options;
        options.directory = directory;
        options.quick = quick;
        options.extra_samplers = samplers;
        options.only = only;
        options.threads = threads;
        options.seed = seed;
        options.cache_dir = cache;
        report::ReportResult result;
        {
          InterruptibleRelease release;  // Ctrl-C: KeyboardInterrupt
          result = report::write_report(options, [verbose](const std::string& line) {
            if (verbose) std::fprintf(stderr, "stratum report: %s\n", line.c_str());
          });
        }
        py::dict numbers;
        for (const auto& section : result.sections)
          numbers[py::str(section.id)] = py::module_::import("json").attr("loads")(section.numbers.dump());
        return py::make_tuple(result.index, numbers, result.seconds);
      },
      py::arg("directory"), py::arg("quick"), py::arg("samplers"), py::arg("only"), py::arg("threads"), py::arg("seed"),
      py::arg("cache"), py::arg("verbose"));
}

}  // namespace stratum::python
#endif
