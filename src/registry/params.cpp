#include "stratum/registry/params.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "stratum/util/error.hpp"

namespace stratum {

namespace params {
Param integer(std::string name, std::string description, std::string default_value, Range range) {
  return {.name = std::move(name),
          .type = ParamType::integer,
          .description = std::move(description),
          .default_value = std::move(default_value),
          .range = range};
}
Param real(std::string name, std::string description, std::string default_value, Range range) {
  return {.name = std::move(name),
          .type = ParamType::real,
          .description = std::move(description),
          .default_value = std::move(default_value),
          .range = range};
}
Param integers(std::string name, std::string description, std::string default_value, Range range, Length length,
               char separator) {
  return {.name = std::move(name),
          .type = ParamType::integers,
          .description = std::move(description),
          .default_value = std::move(default_value),
          .range = range,
          .length = length,
          .separator = separator};
}
Param reals(std::string name, std::string description, std::string default_value, Range range, Length length) {
  return {.name = std::move(name),
          .type = ParamType::reals,
          .description = std::move(description),
          .default_value = std::move(default_value),
          .range = range,
          .length = length};
}
Param choice(std::string name, std::string description, std::string default_value, std::vector<std::string> choices) {
  return {.name = std::move(name),
          .type = ParamType::choice,
          .description = std::move(description),
          .default_value = std::move(default_value),
          .choices = std::move(choices)};
}
Param flag(std::string name, std::string description, std::string default_value) {
  return {.name = std::move(name),
          .type = ParamType::flag,
          .description = std::move(description),
          .default_value = std::move(default_value)};
}
Param text(std::string name, std::string description, std::string default_value) {
  return {.name = std::move(name),
          .type = ParamType::text,
          .description = std::move(description),
          .default_value = std::move(default_value)};
}
}  // namespace params

std::string_view type_name(ParamType type) {
  switch (type) {
    case ParamType::integer:
      return "integer";
    case ParamType::real:
      return "real";
    case ParamType::integers:
      return "integers";
    case ParamType::reals:
      return "reals";
    case ParamType::choice:
      return "choice";
    case ParamType::flag:
      return "flag";
    case ParamType::text:
      return "text";
  }
  return "text";
}

/// A bound as the user would write it: integers without a decimal point,
/// infinities as "inf".
static std::string bound_text(double value) {
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  int exponent = 0;
  if (std::fabs(value) >= 0x1p32 && std::fabs(std::frexp(value, &exponent)) == 0.5)
    return (value < 0 ? "-2^" : "2^") + std::to_string(exponent - 1);
  if (value == std::floor(value) && std::fabs(value) < 1e18) return std::to_string(static_cast<long long>(value));
  return to_message_string(value);
}

std::string range_text(const Range& range) {
  if (!range.bounded()) return "";
  const bool open_min = range.min_open || std::isinf(range.min), open_max = range.max_open || std::isinf(range.max);
  return std::string(open_min ? "(" : "[") + bound_text(range.min) + ", " + bound_text(range.max) +
         (open_max ? ")" : "]");
}

static std::string join(const std::vector<std::string>& items, std::string_view separator = ", ") {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : std::string(separator)) + item;
  return text;
}

static std::string in_range(const Range& range) {
  const std::string interval = range_text(range);
  return interval.empty() ? "" : " in " + interval;
}

static std::string length_text(const Length& length) {
  if (length.min == length.max) return std::to_string(length.min);
  if (length.max == std::numeric_limits<std::size_t>::max()) return std::to_string(length.min) + " or more";
  return std::to_string(length.min) + " to " + std::to_string(length.max);
}

std::string allowed_values(const Param& param) {
  switch (param.type) {
    case ParamType::integer:
      return "must be an integer" + in_range(param.range);
    case ParamType::real:
      return "must be a finite real" + in_range(param.range);
    case ParamType::integers:
    case ParamType::reals:
      return "must be " + length_text(param.length) +
             (param.type == ParamType::integers ? " integers" : " finite reals") + in_range(param.range) +
             ", separated by '" + std::string(1, param.separator) + "'" + (param.separator == ',' ? "" : " or ','");
    case ParamType::choice:
      return "must be one of " + join(param.choices);
    case ParamType::flag:
      return "must be a flag: 1/0, true/false, yes/no or on/off";
    case ParamType::text:
      return "must be text";
  }
  return "";
}

[[noreturn]] static void refuse(const Param& param, std::string_view text) {
  throw invalid_argument(param.name, text.empty() ? "''" : text, allowed_values(param));
}

/// A list's element at fault, by index: a table of a million values is not
/// echoed whole.
[[noreturn]] static void refuse_element(const Param& param, std::size_t index, std::string_view text) {
  const std::string element = param.type == ParamType::integers ? "must be an integer" : "must be a finite real";
  throw invalid_argument(param.name + "[" + std::to_string(index) + "]", text.empty() ? "''" : text,
                         element + in_range(param.range) + " (" + param.name + " takes " + length_text(param.length) +
                             (param.type == ParamType::integers ? " integers" : " reals") + ")");
}

/// A list (or a number given as a list) of the wrong length.
[[noreturn]] static void refuse_count(const Param& param, std::size_t count) {
  throw invalid_argument(param.name, "(" + std::to_string(count) + (count == 1 ? " value)" : " values)"),
                         allowed_values(param));
}

/// Shortest text that reads back as the same double.
static std::string number_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

/// Whole-text integer, decimal, optional leading '-'.
static bool parse_integer_text(std::string_view text, std::int64_t& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && ptr == end;
}

/// Whole-text finite real; under- and overflow (1e-400, 1e999) are refused
/// rather than rounded to 0 or inf, and so are subnormal results (1e-320),
/// which keep too few digits to read back as what was written.
static bool parse_real_text(std::string_view text, double& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value, std::chars_format::general);
  return error == std::errc() && ptr == end && std::isfinite(value) && std::fpclassify(value) != FP_SUBNORMAL;
}

/// A number too small for a double's full precision (1e-320) or so small it
/// reads as 0 (1e-400): said as such, since "must be in (0, inf)" would not
/// explain why 1e-320 is refused.
static bool underflows(std::string_view text) {
  double value = 0;
  const auto [ptr, error] = std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
  if (ptr != text.data() + text.size()) return false;
  if (error == std::errc()) return std::fpclassify(value) == FP_SUBNORMAL;
  if (error != std::errc::result_out_of_range) return false;
  // Out of range either way (from_chars leaves the value unset): too small
  // when the exponent is negative, or, without one, when the digits start
  // after the point ("0.000…01"); too large otherwise.
  const std::size_t e = text.find_first_of("eE");
  if (e != std::string_view::npos) return e + 1 < text.size() && text[e + 1] == '-';
  const std::string_view digits = text.substr(text[0] == '-' ? 1 : 0);
  return digits.starts_with("0.") || digits.starts_with(".");
}

[[noreturn]] static void refuse_underflow(const std::string& name, std::string_view text) {
  throw invalid_argument(name, text,
                         "is below the smallest normal double, 2.2e-308, so it would not read back as "
                         "written: give 0 or a larger value");
}

/// Items between separators; a list whose separator is not ',' takes ','
/// too ("4x8" or "4,8"), as lists of numbers are written everywhere else.
static std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> items;
  std::size_t begin = 0;
  const char separators[] = {separator, ',', '\0'};
  while (true) {
    const std::size_t end = text.find_first_of(separators, begin);
    items.push_back(text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin));
    if (end == std::string_view::npos) return items;
    begin = end + 1;
  }
}

ParamValue parse_param(const Param& param, std::string_view text) {
  switch (param.type) {
    case ParamType::integer: {
      if (param.range.min >= 0) {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, error] = std::from_chars(text.data(), end, value);
        if (error != std::errc() || ptr != end || !param.range.contains_integer(value)) refuse(param, text);
        return value;
      }
      std::int64_t value = 0;
      if (!parse_integer_text(text, value) || !param.range.contains_integer(value)) refuse(param, text);
      return value;
    }
    case ParamType::real: {
      double value = 0;
      if (underflows(text)) refuse_underflow(param.name, text);
      if (!parse_real_text(text, value) || !param.range.contains(value)) refuse(param, text);
      return value;
    }
    case ParamType::integers: {
      if (text.empty()) refuse(param, text);
      std::vector<std::int64_t> values;
      for (std::string_view item : split(text, param.separator)) {
        std::int64_t value = 0;
        if (!parse_integer_text(item, value) || !param.range.contains_integer(value))
          refuse_element(param, values.size(), item);
        values.push_back(value);
      }
      if (values.size() < param.length.min || values.size() > param.length.max) refuse_count(param, values.size());
      return values;
    }
    case ParamType::reals: {
      if (text.empty()) refuse(param, text);
      std::vector<double> values;
      for (std::string_view item : split(text, param.separator)) {
        double value = 0;
        if (underflows(item)) refuse_underflow(param.name + "[" + std::to_string(values.size()) + "]", item);
        if (!parse_real_text(item, value) || !param.range.contains(value)) refuse_element(param, values.size(), item);
        values.push_back(value);
      }
      if (values.size() < param.length.min || values.size() > param.length.max) refuse_count(param, values.size());
      return values;
    }
    case ParamType::choice:
      if (std::find(param.choices.begin(), param.choices.end(), text) == param.choices.end()) refuse(param, text);
      return std::string(text);
    case ParamType::flag: {
      std::string lower(text);
      std::transform(lower.begin(), lower.end(), lower.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (lower == "1" || lower == "true" || lower == "yes" || lower == "on") return true;
      if (lower == "0" || lower == "false" || lower == "no" || lower == "off") return false;
      refuse(param, text);
    }
    case ParamType::text:
      return std::string(text);
  }
  refuse(param, text);
}

std::vector<double> as_reals(const ParamValue& value) {
  if (const auto* v = std::get_if<std::int64_t>(&value)) return {static_cast<double>(*v)};
  if (const auto* v = std::get_if<std::uint64_t>(&value)) return {static_cast<double>(*v)};
  if (const auto* v = std::get_if<double>(&value)) return {*v};
  if (const auto* v = std::get_if<std::vector<std::int64_t>>(&value)) return {v->begin(), v->end()};
  if (const auto* v = std::get_if<std::vector<double>>(&value)) return *v;
  throw std::logic_error("as_reals: the value is not numeric");
}

void check_param(const Param& param, const std::vector<double>& values) {
  const bool list = param.type == ParamType::integers || param.type == ParamType::reals;
  const bool number = param.type == ParamType::integer || param.type == ParamType::real;
  if (!list && !number)
    throw std::logic_error("check_param: " + param.name + " is a " + std::string(type_name(param.type)));
  const Length length = list ? param.length : Length{1, 1};
  const bool integral = param.type == ParamType::integer || param.type == ParamType::integers;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double value = values[i];
    const bool good = std::isfinite(value) && param.range.contains(value) && (!integral || value == std::floor(value));
    if (good) continue;
    if (list) refuse_element(param, i, number_text(value));
    refuse(param, number_text(value));
  }
  if (values.size() < length.min || values.size() > length.max) refuse_count(param, values.size());
}

const Param* find_param(const std::vector<Param>& schema, std::string_view name) {
  for (const auto& param : schema)
    if (param.name == name) return &param;
  return nullptr;
}

const ParamValue& ParamValues::at(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end())
    throw std::logic_error("parameter '" + name + "' is not bound (not in the schema, or no default)");
  return it->second;
}

template <class T>
static const T& typed(const ParamValue& value, const std::string& name, std::string_view wanted) {
  if (const T* typed_value = std::get_if<T>(&value)) return *typed_value;
  throw std::logic_error("parameter '" + name + "' is not read as " + std::string(wanted));
}

std::int64_t ParamValues::integer(const std::string& name) const {
  const ParamValue& value = at(name);
  if (const auto* unsigned_value = std::get_if<std::uint64_t>(&value)) {
    if (*unsigned_value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
      throw std::logic_error("parameter '" + name + "' exceeds int64: read it with unsigned_integer");
    return static_cast<std::int64_t>(*unsigned_value);
  }
  return typed<std::int64_t>(value, name, "an integer");
}
std::uint64_t ParamValues::unsigned_integer(const std::string& name) const {
  const ParamValue& value = at(name);
  if (const auto* signed_value = std::get_if<std::int64_t>(&value)) {
    if (*signed_value < 0) throw std::logic_error("parameter '" + name + "' may be negative: read it with integer");
    return static_cast<std::uint64_t>(*signed_value);
  }
  return typed<std::uint64_t>(value, name, "an unsigned integer");
}
double ParamValues::real(const std::string& name) const {
  const ParamValue& value = at(name);
  if (const auto* integral = std::get_if<std::int64_t>(&value)) return static_cast<double>(*integral);
  if (const auto* integral = std::get_if<std::uint64_t>(&value)) return static_cast<double>(*integral);
  return typed<double>(value, name, "a real");
}
bool ParamValues::flag(const std::string& name) const { return typed<bool>(at(name), name, "a flag"); }
const std::string& ParamValues::text(const std::string& name) const {
  return typed<std::string>(at(name), name, "text");
}
const std::vector<std::int64_t>& ParamValues::integers(const std::string& name) const {
  return typed<std::vector<std::int64_t>>(at(name), name, "integers");
}
const std::vector<double>& ParamValues::reals(const std::string& name) const {
  return typed<std::vector<double>>(at(name), name, "reals");
}

void refuse_unknown_param(std::string_view owner, const std::vector<Param>& schema, std::string_view key,
                          std::string_view value_text, std::string_view option) {
  std::vector<std::string> names;
  for (const auto& known : schema) names.push_back(known.name);
  throw invalid_argument(option, std::string(key) + "=" + std::string(value_text),
                         std::string(owner) + (names.empty() ? " takes no parameters" : " takes " + join(names)));
}

ParamValues bind_params(std::string_view owner, const std::vector<Param>& schema,
                        const std::map<std::string, std::string>& given, std::string_view option) {
  ParamValues bound;
  for (const auto& [key, text] : given) {
    const Param* param = find_param(schema, key);
    if (!param) refuse_unknown_param(owner, schema, key, text, option);
    bound.values_[key] = parse_param(*param, text);
  }
  for (const auto& param : schema)
    if (!bound.has(param.name) && !param.default_value.empty())
      bound.values_[param.name] = parse_param(param, param.default_value);
  return bound;
}

}  // namespace stratum
