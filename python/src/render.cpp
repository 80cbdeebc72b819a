/// Rendering from Python (LECTURE.md §1–3, 8, 9): only with the renderer built.
#ifdef STRATUM_HAS_RENDER
#include "bindings.hpp"

namespace stratum::python {

void bind_render(pybind11::module_& m) { (void)m; }

}  // namespace stratum::python
#endif
