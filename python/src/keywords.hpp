#pragma once
/// A binding's keyword arguments, read one by one into the C++ types the
/// library takes. Only the Python type is checked here (an integer, a
/// string, a path, a bool) and whether the value fits the C++ type; every
/// range and rule is the library's own check, as for the CLI. An argument
/// that no read asked for is an error naming it.
#include <pybind11/pybind11.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <string>

#include "stratum/util/error.hpp"

namespace stratum::python {

class Keywords {
 public:
  explicit Keywords(const pybind11::kwargs& kwargs) : kwargs_(kwargs) {}

  /// An integer (Python's or numpy's; never a bool or a float) into `out`;
  /// absent: `out` is kept.
  template <class Int>
  void integer(const char* name, Int& out) {
    if (const auto value = take(name)) out = static_cast<Int>(integer_in(name, *value, low<Int>(), high<Int>()));
  }
  /// The same where None (or absence) means "not given".
  template <class Int>
  void integer(const char* name, std::optional<Int>& out) {
    const auto value = take(name);
    if (value && !value->is_none()) out = static_cast<Int>(integer_in(name, *value, low<Int>(), high<Int>()));
  }
  /// A real number (int or float, numpy's too; never a bool or a string);
  /// absent or None: `out` is kept (an optional stays "not given").
  void real(const char* name, double& out);
  void real(const char* name, std::optional<double>& out);
  /// A string; where `optional`, None reads as "".
  void text(const char* name, std::string& out, bool optional = false);
  /// A string, where None (or absence) means "not given".
  void text(const char* name, std::optional<std::string>& out);
  /// A path (str or os.PathLike); None reads as "".
  void path(const char* name, std::string& out);
  /// True or False.
  void flag(const char* name, bool& out);
  /// A seed: exactly the integers in [0, 2^64) (parse_seed's rule).
  void seed(const char* name, std::uint64_t& out);
  /// Threads by the one thread rule (resolve_threads: 0 = every core).
  void threads(const char* name, unsigned& out);
  /// Throws naming the first argument no read asked for.
  void finish() const;

 private:
  template <class Int>
  static constexpr std::int64_t low() {
    return std::int64_t(std::numeric_limits<Int>::min());
  }
  template <class Int>
  static constexpr std::int64_t high() {
    return std::numeric_limits<Int>::max() > std::uint64_t(std::numeric_limits<std::int64_t>::max())
               ? std::numeric_limits<std::int64_t>::max()
               : std::int64_t(std::numeric_limits<Int>::max());
  }
  std::optional<pybind11::object> take(const char* name);
  static std::int64_t integer_in(const char* name, const pybind11::object& value, std::int64_t low, std::int64_t high);

  const pybind11::kwargs& kwargs_;
  std::set<std::string> read_;
};

}  // namespace stratum::python
