/// The parameter schema in Python: one dict per parameter for every listing
/// (samplers(), measures(), warps(), integrands()) and describe(name).
#include <pybind11/stl.h>

#include <cmath>
#include <limits>

#include "bindings.hpp"
#include "stratum/analysis/catalogue.hpp"

namespace py = pybind11;

namespace stratum::python {
namespace {

py::object bound(double value) { return std::isinf(value) ? py::object(py::none()) : py::object(py::float_(value)); }

/// A parsed value as the Python object it reads as.
py::object python_value(const ParamValue& value) {
  return std::visit([](const auto& v) -> py::object { return py::cast(v); }, value);
}

}  // namespace

py::dict param_dict(const Param& param) {
  py::dict out;
  out["name"] = param.name;
  out["type"] = std::string(type_name(param.type));
  out["description"] = param.description;
  out["default"] =
      param.default_value.empty() ? py::object(py::none()) : python_value(parse_param(param, param.default_value));
  const bool list = param.type == ParamType::integers || param.type == ParamType::reals;
  const bool numeric = list || param.type == ParamType::integer || param.type == ParamType::real;
  if (numeric) {
    if (param.range.bounded()) {
      py::dict range;
      range["min"] = bound(param.range.min);
      range["max"] = bound(param.range.max);
      range["min_open"] = param.range.min_open;
      range["max_open"] = param.range.max_open;
      out["range"] = range;
    } else {
      out["range"] = py::none();
    }
  }
  if (param.type == ParamType::choice) out["choices"] = param.choices;
  if (list) {
    py::dict length;
    length["min"] = param.length.min;
    length["max"] = param.length.max == std::numeric_limits<std::size_t>::max()
                        ? py::object(py::none())
                        : py::object(py::int_(param.length.max));
    out["length"] = length;
    out["separator"] = std::string(1, param.separator);
  }
  return out;
}

py::list params_list(const std::vector<Param>& params) {
  py::list list;
  for (const auto& param : params) list.append(param_dict(param));
  return list;
}

void bind_schema(py::module_& m) {
  m.def(
      "_describe",
      [](const std::string& name, const std::string& kind) {
        py::list out;
        for (const auto& entry : analysis::find_in_catalogue(name, kind)) {
          py::dict item;
          item["kind"] = entry.kind;
          item["name"] = entry.name;
          item["description"] = entry.description;
          item["params"] = params_list(*entry.params);
          out.append(item);
        }
        return out;
      },
      py::arg("name"), py::arg("kind") = "");
}

}  // namespace stratum::python
