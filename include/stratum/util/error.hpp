#pragma once
/// Errors for bad parameters. Every message names the argument, the value
/// given and what is allowed, so the CLI and Python can pass it on verbatim.
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace stratum {

/// Thrown at construction time when a parameter is out of range.
class invalid_argument : public std::invalid_argument {
 public:
  invalid_argument(std::string_view argument, std::string_view value, std::string_view allowed)
      : std::invalid_argument(compose(argument, value, allowed)), argument_(argument) {}
  /// The parameter at fault (e.g. "n", "d", "radius").
  const std::string& argument() const noexcept { return argument_; }

 private:
  static std::string compose(std::string_view argument, std::string_view value,
                             std::string_view allowed) {
    std::ostringstream out;
    out << "invalid " << argument << " = " << value << ": " << allowed;
    return out.str();
  }
  std::string argument_;
};

/// Formats any streamable value for an error message.
template <class T>
std::string to_message_string(const T& value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

/// Throws invalid_argument unless `condition` holds.
template <class T>
void require(bool condition, std::string_view argument, const T& value, std::string_view allowed) {
  if (!condition) throw invalid_argument(argument, to_message_string(value), allowed);
}

}  // namespace stratum
