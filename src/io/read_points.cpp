#include "stratum/io/read_points.hpp"

#include <fmt/format.h>

#include <algorithm>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "stratum/util/error.hpp"

namespace stratum::io {

namespace {

[[noreturn]] void bad_input(const std::filesystem::path& path, const std::string& why) {
  throw invalid_argument("input", path.string(), why);
}

/// The value of `key` in a .npy header dict ("{'descr': '<f8', ...}"): the
/// text after "'key':" up to the next top-level comma or closing brace.
std::string header_value(const std::string& header, const std::string& key) {
  const auto at = header.find("'" + key + "'");
  if (at == std::string::npos) return {};
  auto start = header.find(':', at);
  if (start == std::string::npos) return {};
  ++start;
  while (start < header.size() && header[start] == ' ') ++start;
  std::size_t end = start;
  int depth = 0;
  for (; end < header.size(); ++end) {
    const char c = header[end];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth == 0 && (c == ',' || c == '}')) break;
  }
  return header.substr(start, end - start);
}

/// "(3, 2)" → {3, 2}; "(5,)" → {5}; empty on a malformed tuple.
std::vector<std::uint64_t> parse_shape(const std::string& text) {
  std::vector<std::uint64_t> shape;
  if (text.size() < 2 || text.front() != '(' || text.back() != ')') return {};
  std::size_t i = 1;
  while (i + 1 < text.size()) {
    while (i + 1 < text.size() && (text[i] == ' ' || text[i] == ',')) ++i;
    if (i + 1 >= text.size()) break;
    if (text[i] < '0' || text[i] > '9') return {};  // strtoull would take "-16" as 2^64 - 16
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text.c_str() + i, &end, 10);
    if (end == text.c_str() + i || errno == ERANGE) return {};
    shape.push_back(value);
    i = static_cast<std::size_t>(end - text.c_str());
  }
  return shape;
}

PointSet read_npy_strict(std::ifstream& in, const std::filesystem::path& path) {
  char preamble[10];
  in.read(preamble, 10);
  if (!in || std::memcmp(preamble, "\x93NUMPY", 6) != 0) bad_input(path, "is not a .npy file (no \\x93NUMPY magic)");
  const int version = static_cast<unsigned char>(preamble[6]);
  if (version < 1 || version > 3) bad_input(path, fmt::format("has .npy format version {}, allowed 1 to 3", version));
  std::size_t header_length = static_cast<unsigned char>(preamble[8]) | (static_cast<unsigned char>(preamble[9]) << 8);
  std::size_t offset = 10;
  if (version >= 2) {  // versions 2 and 3 have a 4-byte length
    char more[2];
    in.read(more, 2);
    header_length |= (static_cast<std::size_t>(static_cast<unsigned char>(more[0])) << 16) |
                     (static_cast<std::size_t>(static_cast<unsigned char>(more[1])) << 24);
    offset = 12;
  }
  std::error_code ec;
  const auto file_size = std::filesystem::file_size(path, ec);
  if (ec || offset + header_length > file_size) bad_input(path, "has a truncated .npy header");
  std::string header(header_length, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header_length));
  if (!in) bad_input(path, "has a truncated .npy header");
  // Parts of the header shown in a message: one line, no raw bytes, and
  // "(none)" for a key the header lacks.
  auto shown = [&](const char* key) {
    const std::string value = header_value(header, key);
    return value.empty() ? std::string("(none)") : printable(value.substr(0, 80));
  };
  const std::string descr = header_value(header, "descr");
  if (descr != "'<f8'")
    bad_input(path, fmt::format("holds dtype {}, allowed '<f8' (little-endian float64)", shown("descr")));
  if (header_value(header, "fortran_order") != "False")
    bad_input(path, fmt::format("is in Fortran order (fortran_order {}), allowed: C order (numpy.ascontiguousarray)",
                                shown("fortran_order")));
  const std::vector<std::uint64_t> shape = parse_shape(header_value(header, "shape"));
  if (shape.empty() || shape.size() > 2)
    bad_input(path, fmt::format("has shape {}, allowed (n, d) or (n,) of non-negative integers", shown("shape")));
  const std::uint64_t n = shape[0], d = shape.size() == 2 ? shape[1] : 1;
  if (n == 0 || d == 0) bad_input(path, fmt::format("holds no points (shape ({}, {}))", n, d));
  const std::uint64_t body = file_size - offset - header_length;
  if (body % 8 != 0 || d > body / 8 || n > body / 8 / d || n * d * 8 != body)
    bad_input(path, fmt::format("has {} data bytes, shape ({}, {}) needs {}", body, n, d,
                                n <= body && d <= body ? fmt::format("{}", n * d * 8) : std::string("more")));
  PointSet points;
  points.n = n;
  points.d = d;
  points.data.reset(new double[n * d]);
  in.read(reinterpret_cast<char*>(points.data.get()), static_cast<std::streamsize>(n * d * sizeof(double)));
  if (!in) bad_input(path, "is truncated");
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < d; ++j)
      if (!std::isfinite(points(i, j)))
        bad_input(path, fmt::format("point[{}][{}] is {}: coordinates must be finite numbers", i, j, points(i, j)));
  return points;
}

/// Splits a text line into fields: at commas (CSV, each field trimmed; an
/// empty field is kept so it can be reported) or at whitespace.
std::vector<std::string> split_fields(const std::string& line, bool csv) {
  std::vector<std::string> fields;
  auto trim = [](const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return std::string();
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
  };
  if (csv) {
    std::size_t start = 0;
    for (;;) {
      const auto comma = line.find(',', start);
      fields.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    return fields;
  }
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) fields.push_back(line.substr(i, j - i));
    i = j;
  }
  return fields;
}

PointSet read_text_strict(std::ifstream& in, const std::filesystem::path& path, bool csv) {
  std::vector<double> values;
  std::size_t d = 0, n = 0, line_number = 0, first_line = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    if (line_number == 1 && line.starts_with("\xef\xbb\xbf")) line.erase(0, 3);  // a UTF-8 byte order mark
    // Blank is what split_fields splits at (a line of '\v' or '\f' too: it
    // holds no field, and once counted as a point of 0 values).
    const auto first = std::find_if(line.begin(), line.end(), [](unsigned char c) { return !std::isspace(c); });
    if (first == line.end() || *first == '#') continue;
    const std::vector<std::string> fields = split_fields(line, csv);
    if (first_line == 0) {
      d = fields.size();
      first_line = line_number;
    }
    if (fields.size() != d)
      bad_input(path, fmt::format("line {} has {} values, line {} (the first point) has {}: rows must all have the "
                                  "same length",
                                  line_number, fields.size(), first_line, d));
    for (std::size_t column = 0; column < fields.size(); ++column) {
      const std::string& field = fields[column];
      char* end = nullptr;
      const double value = std::strtod(field.c_str(), &end);
      if (field.empty() || end != field.c_str() + field.size())
        bad_input(path, fmt::format("line {}, column {} is '{}': not a number", line_number, column + 1,
                                    printable(field.substr(0, 80))));
      if (!std::isfinite(value))
        bad_input(path, fmt::format("line {}, column {} is '{}': coordinates must be finite numbers", line_number,
                                    column + 1, printable(field.substr(0, 80))));
      values.push_back(value);
    }
    ++n;
  }
  if (n == 0) bad_input(path, "holds no points (the file is empty or has only blank and '#' lines)");
  PointSet points;
  points.n = n;
  points.d = d;
  points.data.reset(new double[n * d]);
  std::copy(values.begin(), values.end(), points.data.get());
  return points;
}

}  // namespace

std::string point_location(const std::filesystem::path& path, std::size_t row) {
  if (path.extension() == ".npy") return fmt::format("row {}", row);
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::size_t line_number = 0, points = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line_number == 1 && line.starts_with("\xef\xbb\xbf")) line.erase(0, 3);
    const auto first = std::find_if(line.begin(), line.end(), [](unsigned char c) { return !std::isspace(c); });
    if (first == line.end() || *first == '#') continue;
    if (points++ == row) return fmt::format("line {}", line_number);
  }
  return fmt::format("point {}", row);
}

void check_unit_cube(const PointSet& points, const std::filesystem::path& path) {
  for (std::size_t i = 0; i < points.n; ++i)
    for (std::size_t j = 0; j < points.d; ++j)
      if (!(points(i, j) >= 0 && points(i, j) <= 1))
        bad_input(path, fmt::format("{}, column {} is {}: coordinates must be in [0, 1]", point_location(path, i),
                                    j + 1, points(i, j)));
}

PointSet read_points_strict(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) bad_input(path, "is a directory, not a point file");
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    bad_input(path, "is not a regular file (a FIFO or device would never end): give a point file");
  std::ifstream in(path, std::ios::binary);
  if (!in) bad_input(path, "cannot be opened (no such file or no permission)");
  const std::string extension = path.extension().string();
  if (extension == ".npy") return read_npy_strict(in, path);
  return read_text_strict(in, path, extension == ".csv");
}

}  // namespace stratum::io
