#pragma once
/// One parameter schema for every registry: samplers, measures, warps and
/// integrands describe each parameter once (name, type, range, default,
/// description), and one parser turns `KEY=VALUE` text into checked values.
/// The schema drives validation, `stratum describe`, `stratum samplers
/// --json`, Python's `stratum.describe` and the docs' parameter tables, so
/// the faces cannot disagree about what a parameter accepts.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace stratum {

enum class ParamType {
  integer,   ///< a 64-bit integer: "30" (signed, or unsigned when the range starts at 0 or above)
  real,      ///< a finite real: "0.5", "1e-3"
  integers,  ///< a list of integers: "1,55,133" (strata: "4x8")
  reals,     ///< a list of finite reals: "0.75,0.56"
  choice,    ///< one of a few words: "gray"
  flag,      ///< 1/0, true/false, yes/no, on/off
  text,      ///< free text
};

/// The interval a number (or every element of a list) must lie in.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< exclude min
  bool max_open = false;  ///< exclude max
  bool contains(double value) const {
    return (min_open ? value > min : value >= min) && (max_open ? value < max : value <= max);
  }
  /// Exact for every 64-bit integer (compared in long double, whose 64-bit
  /// mantissa holds them all; a double would round 2^64 - 1 up to 2^64).
  template <class Integer>
  bool contains_integer(Integer value) const {
    const auto v = static_cast<long double>(value);
    const auto lo = static_cast<long double>(min), hi = static_cast<long double>(max);
    return (min_open ? v > lo : v >= lo) && (max_open ? v < hi : v <= hi);
  }
  bool bounded() const {
    return min != -std::numeric_limits<double>::infinity() || max != std::numeric_limits<double>::infinity();
  }
};
constexpr Range closed(double min, double max) { return {min, max, false, false}; }
constexpr Range half_open(double min, double max) { return {min, max, false, true}; }  ///< [min, max)
constexpr Range open(double min, double max) { return {min, max, true, true}; }
constexpr Range left_open(double min, double max) { return {min, max, true, false}; }  ///< (min, max]
constexpr Range at_least(double min) { return {min, std::numeric_limits<double>::infinity(), false, false}; }
constexpr Range above(double min) { return {min, std::numeric_limits<double>::infinity(), true, false}; }
constexpr Range any_real() { return {}; }

/// How many elements a list takes.
struct Length {
  std::size_t min = 1;
  std::size_t max = std::numeric_limits<std::size_t>::max();
};

struct Param {
  std::string name;
  ParamType type = ParamType::text;
  std::string description;
  /// In the parameter's own syntax; empty: no default (optional, or computed
  /// by the entry as the description says).
  std::string default_value;
  Range range{};                       ///< integer, real, and every element of integers/reals
  std::vector<std::string> choices{};  ///< choice
  Length length{};                     ///< integers, reals
  char separator = ',';                ///< integers, reals
};

/// Short constructors, so a registry entry reads as its schema.
namespace params {
Param integer(std::string name, std::string description, std::string default_value, Range range);
Param real(std::string name, std::string description, std::string default_value, Range range);
Param integers(std::string name, std::string description, std::string default_value, Range range, Length length = {},
               char separator = ',');
Param reals(std::string name, std::string description, std::string default_value, Range range, Length length = {});
Param choice(std::string name, std::string description, std::string default_value, std::vector<std::string> choices);
Param flag(std::string name, std::string description, std::string default_value);
Param text(std::string name, std::string description, std::string default_value);
}  // namespace params

/// "integer", "real", "integers", "reals", "choice", "flag" or "text".
std::string_view type_name(ParamType type);
/// What a value must be, in words: "an integer in [1, 100000]",
/// "1 to 32 reals in (0, 1), separated by ','", "one of gray, natural".
std::string allowed_values(const Param& param);
/// The range in interval notation ("[1, 100000]", "(0, inf)"); empty when unbounded.
std::string range_text(const Range& range);

/// An integer parameter whose range starts at 0 or above holds a
/// std::uint64_t (seeds take all of [0, 2^64)); others a std::int64_t.
using ParamValue = std::variant<bool, std::int64_t, std::uint64_t, double, std::vector<std::int64_t>,
                                std::vector<double>, std::string>;

/// The one parser: text in the parameter's syntax to its checked value;
/// throws stratum::invalid_argument naming the parameter, the text and
/// allowed_values().
ParamValue parse_param(const Param& param, std::string_view text);

/// A numeric value (integer, real or a list of them) as reals: the form the
/// warp and integrand registries take their parameters in.
std::vector<double> as_reals(const ParamValue& value);

/// Checks numbers given already typed (Python lists, the warp API) against
/// the schema: count and range; throws as parse_param does.
void check_param(const Param& param, const std::vector<double>& values);

/// A registry entry's parameters, bound: every given value parsed and
/// checked, every default filled in. Accessors name a parameter of the
/// schema; asking for one that is not there (or by the wrong type) is a
/// programming error (std::logic_error), caught by the registry tests.
class ParamValues {
 public:
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::int64_t integer(const std::string& name) const;            ///< fits int64 (the schema's range says so)
  std::uint64_t unsigned_integer(const std::string& name) const;  ///< a non-negative integer
  double real(const std::string& name) const;                     ///< also an integer parameter, converted
  bool flag(const std::string& name) const;
  const std::string& text(const std::string& name) const;  ///< choice or text
  const std::vector<std::int64_t>& integers(const std::string& name) const;
  const std::vector<double>& reals(const std::string& name) const;

 private:
  friend ParamValues bind_params(std::string_view owner, const std::vector<Param>& schema,
                                 const std::map<std::string, std::string>& given, std::string_view option);
  const ParamValue& at(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
};

/// Binds `given` (KEY → text) to `schema`: an unknown key is an error naming
/// `option` (the CLI's: "param" for -p, "measure-param", ...), the key, and
/// what `owner` (e.g. "jittered") takes; each value is parsed by
/// parse_param; defaults fill the rest.
ParamValues bind_params(std::string_view owner, const std::vector<Param>& schema,
                        const std::map<std::string, std::string>& given, std::string_view option = "param");

/// The error for a key `owner`'s schema lacks (as bind_params throws it).
[[noreturn]] void refuse_unknown_param(std::string_view owner, const std::vector<Param>& schema, std::string_view key,
                                       std::string_view value_text, std::string_view option);

/// The parameter called `name` in `schema`, or nullptr.
const Param* find_param(const std::vector<Param>& schema, std::string_view name);

}  // namespace stratum
