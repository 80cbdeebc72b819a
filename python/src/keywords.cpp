#include "keywords.hpp"

#include "stratum/registry/spec.hpp"

namespace py = pybind11;

namespace stratum::python {

namespace {
std::string shown(const py::handle& value) {
  std::string text = py::repr(value);
  return text.size() <= 80 ? text : text.substr(0, 77) + "...";
}
bool is_bool(const py::handle& value) {
  return PyBool_Check(value.ptr()) || std::string(py::str(py::type::handle_of(value).attr("__name__"))) == "bool_";
}
/// `value` as a Python int when it is an integer (Python's or numpy's:
/// operator.index; never a bool), else nullopt.
std::optional<py::object> as_int(const py::handle& value) {
  if (is_bool(value) || !PyIndex_Check(value.ptr())) return std::nullopt;
  py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!index) throw py::error_already_set();
  return index;
}
/// The same when it also fits 64 signed bits.
std::optional<std::int64_t> as_int64(const py::handle& value) {
  const auto index = as_int(value);
  if (!index) return std::nullopt;
  int overflow = 0;
  const long long n = PyLong_AsLongLongAndOverflow(index->ptr(), &overflow);
  if (overflow != 0) return std::nullopt;
  return n;
}
/// The library's refusal `e` of `library_value` (how the value reached it)
/// told of `value` as the caller gave it, under this binding's `name`.
invalid_argument as_given(const invalid_argument& e, const char* name, const py::handle& value,
                          const std::string& library_value) {
  const std::string prefix = "invalid " + e.argument() + " = " + printable(library_value) + ": ";
  const std::string message = e.what();
  const std::string allowed = message.starts_with(prefix) ? message.substr(prefix.size()) : message;
  return invalid_argument(name, shown(value), allowed);
}
}  // namespace

std::optional<py::object> Keywords::take(const char* name) {
  read_.insert(name);
  if (!kwargs_.contains(name)) return std::nullopt;
  return py::reinterpret_borrow<py::object>(kwargs_[name]);
}

std::int64_t Keywords::integer_in(const char* name, const py::object& value, std::int64_t low, std::int64_t high) {
  const auto n = as_int64(value);
  if (!n || *n < low || *n > high)
    throw invalid_argument(name, shown(value),
                           "must be an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
  return *n;
}

void Keywords::real(const char* name, double& out) {
  std::optional<double> given;
  real(name, given);
  if (given) out = *given;
}

void Keywords::real(const char* name, std::optional<double>& out) {
  const auto value = take(name);
  if (!value || value->is_none()) return;
  const py::object numbers = py::module_::import("numbers");
  if (is_bool(*value) || !py::isinstance(*value, numbers.attr("Real")))
    throw invalid_argument(name, shown(*value), "must be a real number");
  out = value->cast<double>();
}

void Keywords::text(const char* name, std::string& out, bool optional) {
  const auto value = take(name);
  if (!value) return;
  if (optional && value->is_none()) {
    out.clear();
  } else {
    if (!py::isinstance<py::str>(*value))
      throw invalid_argument(name, shown(*value), optional ? "must be a string or None" : "must be a string");
    out = value->cast<std::string>();
  }
}

void Keywords::text(const char* name, std::optional<std::string>& out) {
  const auto value = take(name);
  if (!value || value->is_none()) return;
  if (!py::isinstance<py::str>(*value)) throw invalid_argument(name, shown(*value), "must be a string or None");
  out = value->cast<std::string>();
}

void Keywords::path(const char* name, std::string& out) {
  const auto value = take(name);
  if (!value) return;
  if (value->is_none()) {
    out.clear();
    return;
  }
  const py::object os = py::module_::import("os");
  if (!py::isinstance<py::str>(*value) && !py::isinstance(*value, os.attr("PathLike")))
    throw invalid_argument(name, shown(*value), "must be a path or None");
  const py::object text = os.attr("fspath")(*value);
  if (!py::isinstance<py::str>(text)) throw invalid_argument(name, shown(*value), "must be a path given as text");
  out = text.cast<std::string>();
}

void Keywords::flag(const char* name, bool& out) {
  const auto value = take(name);
  if (!value) return;
  if (!PyBool_Check(value->ptr())) throw invalid_argument(name, shown(*value), "must be True or False");
  out = value->cast<bool>();
}

void Keywords::seed(const char* name, std::uint64_t& out) {
  const auto value = take(name);
  if (!value) return;
  // Any integer's digits go to the library's rule (parse_seed), which refuses
  // negative and too large ones; what is not an integer reaches it as text it
  // refuses (the message shows the repr).
  const auto index = as_int(*value);
  const std::string text = index ? std::string(py::str(*index)) : "not-a-number";
  try {
    out = parse_seed(text);
  } catch (const invalid_argument& e) {
    throw as_given(e, name, *value, text);
  }
}

void Keywords::threads(const char* name, unsigned& out) {
  const auto value = take(name);
  if (!value) return;
  // Integers beyond 64 bits reach the rule as -1: refused by it alike.
  const std::int64_t n = as_int64(*value).value_or(-1);
  try {
    out = resolve_threads(n);
  } catch (const invalid_argument& e) {
    throw as_given(e, name, *value, std::to_string(n));
  }
}

void Keywords::finish() const {
  for (const auto& item : kwargs_) {
    const std::string key = py::str(item.first);
    if (!read_.contains(key)) throw invalid_argument("keyword", key, "is not an argument of this call");
  }
}

}  // namespace stratum::python
