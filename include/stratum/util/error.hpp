#pragma once
/// Errors for bad parameters. Every message names the argument, the value
/// given and what is allowed, so the CLI and Python can pass it on verbatim.
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace stratum {

/// `text` as a message can show it: control bytes, DEL and bytes that are
/// not valid UTF-8 (a binary file read as text) written as \xNN (\t, \n, \r
/// by name), so a message never carries raw bytes to a terminal; valid
/// UTF-8 (a file name in any script) is kept.
inline std::string printable(std::string_view text) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string shown;
  shown.reserve(text.size());
  auto escape = [&](unsigned char c) {
    if (c == '\t') shown += "\\t";
    else if (c == '\n') shown += "\\n";
    else if (c == '\r') shown += "\\r";
    else shown += std::string{'\\', 'x', hex[c >> 4], hex[c & 15]};
  };
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if (c < 0x20 || c == 0x7f) escape(c);
      else shown += static_cast<char>(c);
      ++i;
      continue;
    }
    // The length of a well-formed UTF-8 sequence led by c (RFC 3629: no
    // overlong forms, no surrogates, nothing above U+10FFFF); 0 if none.
    const std::size_t length = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
    bool good = length != 0 && i + length <= text.size();
    for (std::size_t k = 1; good && k < length; ++k) good = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
    if (good && length >= 3) {
      const auto second = static_cast<unsigned char>(text[i + 1]);
      good = !(c == 0xe0 && second < 0xa0) && !(c == 0xed && second >= 0xa0) && !(c == 0xf0 && second < 0x90) &&
             !(c == 0xf4 && second >= 0x90);
    }
    if (!good) {
      escape(c);
      ++i;
      continue;
    }
    shown.append(text.substr(i, length));
    i += length;
  }
  return shown;
}

/// Thrown at construction time when a parameter is out of range.
class invalid_argument : public std::invalid_argument {
 public:
  invalid_argument(std::string_view argument, std::string_view value, std::string_view allowed)
      : std::invalid_argument(compose(argument, value, allowed)), argument_(argument) {}
  /// The parameter at fault (e.g. "n", "d", "radius").
  const std::string& argument() const noexcept { return argument_; }

 private:
  static std::string compose(std::string_view argument, std::string_view value, std::string_view allowed) {
    std::ostringstream out;
    out << "invalid " << argument << " = " << printable(value) << ": " << allowed;
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
