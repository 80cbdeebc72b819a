#pragma once
/// JSON read from users' files with limits: nesting depth capped before
/// nlohmann::json sees the text (a deeply nested value would overflow the
/// stack when printed or checked), errors with line, column and a short
/// excerpt, and values in messages shortened.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace stratum::io {

/// The deepest nesting of arrays and objects accepted.
inline constexpr std::size_t json_max_depth = 256;

/// Parses `text`; throws stratum::invalid_argument(argument, origin, ...) for
/// invalid JSON or nesting deeper than `max_depth`, naming line and column.
nlohmann::json parse_json(const std::string& text, const std::string& argument, const std::string& origin,
                          std::size_t max_depth = json_max_depth);

/// `value` printed compactly for a message, cut to about `limit` characters.
std::string json_excerpt(const nlohmann::json& value, std::size_t limit = 60);

}  // namespace stratum::io
