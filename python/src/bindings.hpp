#pragma once
/// The compiled module's parts, one source file each (python/src/*.cpp).
#include <pybind11/pybind11.h>

#include <vector>

#include "stratum/registry/params.hpp"

namespace stratum::python {
void bind_schema(pybind11::module_& m);  // schema.cpp: _describe
/// One parameter of the schema as a dict (name, type, description, default,
/// range, choices, length, separator): every listing's "params".
pybind11::dict param_dict(const Param& param);
pybind11::list params_list(const std::vector<Param>& params);
void bind_warps(pybind11::module_& m);     // warps.cpp: warp, warp_pdf, warp_invert, warps
void bind_measures(pybind11::module_& m);  // measures.cpp: measure, measures, scipy-compatible discrepancy
void bind_spectra(pybind11::module_& m);   // spectra.cpp: periodogram, radial power, anisotropy
void bind_studies(pybind11::module_& m);   // studies.cpp: integrands, integrate, converge, studies
void bind_mitchell(pybind11::module_& m);  // mitchell.cpp: study_mitchell
#ifdef STRATUM_HAS_RENDER
void bind_render(pybind11::module_& m);  // render.cpp: render, compare (renderer built only)
#endif
#ifdef STRATUM_HAS_REPORT
void bind_report(pybind11::module_& m);  // report.cpp: report, report_sections
#endif
}  // namespace stratum::python
