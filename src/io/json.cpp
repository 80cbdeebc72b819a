#include "stratum/io/json.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "stratum/util/error.hpp"

namespace stratum::io {

namespace {

/// "line L, column C (near '...')" for byte `at` of `text`.
std::string place(const std::string& text, std::size_t at) {
  at = std::min(at, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  // Up to 20 characters either side, within the line.
  std::size_t from = at > 20 ? at - 20 : 0;
  for (std::size_t i = at; i > from; --i)
    if (text[i - 1] == '\n') {
      from = i;
      break;
    }
  const std::size_t to = std::min(text.size(), at + 20);
  std::string near;
  for (std::size_t i = from; i < to && text[i] != '\n'; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    near += c >= 0x20 && c < 0x7f ? static_cast<char>(c) : '?';
  }
  std::string out = "line " + std::to_string(line) + ", column " + std::to_string(column);
  if (!near.empty()) out += " (near '" + near + "')";
  return out;
}

/// The byte of the quote that closes the string opened at `open` (escaped
/// characters skipped), or text.size() when it is never closed: the two
/// scanners below skip strings with it.
std::size_t string_end(const std::string& text, std::size_t open) {
  for (std::size_t i = open + 1; i < text.size(); ++i) {
    if (text[i] == '\\') ++i;
    else if (text[i] == '"') return i;
  }
  return text.size();
}

/// The byte where nesting first exceeds `max_depth`, or npos (strings skipped).
std::size_t too_deep(const std::string& text, std::size_t max_depth) {
  std::size_t depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      i = string_end(text, i);
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::string::npos;
}

/// The first number of `text` (outside strings) that overflows a double
/// (1e999): its byte and its text; npos when none does.
std::pair<std::size_t, std::string> overflowing_number(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      i = string_end(text, i);
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i + 1;
      while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.' ||
                                   text[end] == 'e' || text[end] == 'E' || text[end] == '+' || text[end] == '-'))
        ++end;
      const std::string number = text.substr(i, end - i);
      if (std::isinf(std::strtod(number.c_str(), nullptr))) return {i, number};
      i = end - 1;
    }
  }
  return {std::string::npos, ""};
}

}  // namespace

nlohmann::json parse_json(const std::string& text, const std::string& argument, const std::string& origin,
                          std::size_t max_depth) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw invalid_argument(argument, origin,
                           text.empty() ? "is empty: it must hold a JSON document"
                                        : "holds only white space: it must hold a JSON document");
  const std::size_t deep = too_deep(text, max_depth);
  if (deep != std::string::npos)
    throw invalid_argument(
        argument, origin,
        "nests arrays and objects deeper than " + std::to_string(max_depth) + " levels at " + place(text, deep));
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann's reason without its "[json.exception...] parse error at line L, column C: " prefix.
    std::string reason = e.what();
    const auto colon = reason.find(": ", reason.find("column"));
    reason = colon == std::string::npos ? std::string("syntax error") : reason.substr(colon + 2);
    if (reason.size() > 120) reason = reason.substr(0, 117) + "...";
    const std::size_t byte = e.byte > 0 ? e.byte - 1 : 0;
    throw invalid_argument(argument, origin, "is not valid JSON at " + place(text, byte) + ": " + reason);
  } catch (const nlohmann::json::out_of_range&) {
    const auto [at, number] = overflowing_number(text);
    if (at == std::string::npos)
      throw invalid_argument(argument, origin, "has a number that is not finite in double precision");
    throw invalid_argument(argument, origin,
                           "has the number " + (number.size() > 40 ? number.substr(0, 37) + "..." : number) + " at " +
                               place(text, at) + ", which is not finite in double precision");
  }
}

std::string json_excerpt(const nlohmann::json& value, std::size_t limit) {
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > limit) text = text.substr(0, limit) + "...";
  return text;
}

}  // namespace stratum::io
