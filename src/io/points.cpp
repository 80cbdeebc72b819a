#include "stratum/io/points.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "stratum/io/output_file.hpp"
#include "stratum/util/error.hpp"

namespace stratum::io {

PointFormat parse_point_format(const std::string& text) {
  if (text == "txt") return PointFormat::txt;
  if (text == "csv") return PointFormat::csv;
  if (text == "npy") return PointFormat::npy;
  throw invalid_argument("format", text, "must be txt, csv or npy");
}

static void write_npy(std::ostream& out, const PointSet& points) {
  std::string header =
      fmt::format("{{'descr': '<f8', 'fortran_order': False, 'shape': ({}, {}), }}", points.n, points.d);
  // Magic (6) + version (2) + length (2) + header + newline, padded to 64 bytes.
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header.push_back('\n');
  const auto length = static_cast<std::uint16_t>(header.size());
  out.write("\x93NUMPY\x01\x00", 8);
  const char length_bytes[2] = {static_cast<char>(length & 0xff), static_cast<char>(length >> 8)};
  out.write(length_bytes, 2);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  out.write(reinterpret_cast<const char*>(points.data.get()),
            static_cast<std::streamsize>(points.n * points.d * sizeof(double)));
}

static void write_text(std::ostream& out, const PointSet& points, char separator) {
  fmt::memory_buffer buffer;
  for (std::size_t i = 0; i < points.n; ++i) {
    for (std::size_t j = 0; j < points.d; ++j) {
      if (j) buffer.push_back(separator);
      fmt::format_to(std::back_inserter(buffer), "{}", points(i, j));  // shortest round-trip form
    }
    buffer.push_back('\n');
    if (buffer.size() > (1u << 20)) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

void write_points(std::ostream& out, const PointSet& points, PointFormat format) {
  switch (format) {
    case PointFormat::npy:
      write_npy(out, points);
      break;
    case PointFormat::csv:
      write_text(out, points, ',');
      break;
    case PointFormat::txt:
      write_text(out, points, ' ');
      break;
  }
}

std::optional<PointFormat> point_format_of_extension(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".npy") return PointFormat::npy;
  if (extension == ".csv") return PointFormat::csv;
  if (extension == ".txt") return PointFormat::txt;
  return std::nullopt;
}

static const char* format_name(PointFormat format) {
  switch (format) {
    case PointFormat::npy:
      return "npy";
    case PointFormat::csv:
      return "csv";
    case PointFormat::txt:
      break;
  }
  return "txt";
}

PointFormat resolve_point_format(const std::string& output, const std::string& format) {
  const bool to_file = !output.empty() && output != "-";
  const auto by_extension = to_file ? point_format_of_extension(output) : std::nullopt;
  if (format.empty()) return by_extension.value_or(PointFormat::txt);
  const PointFormat chosen = parse_point_format(format);
  if (by_extension && *by_extension != chosen)
    throw invalid_argument("format", format,
                           fmt::format("does not match the output {} (a .{} file): leave --format out, or name the "
                                       "file .{}, which is how stratum reads it back",
                                       output, format_name(*by_extension), format_name(chosen)));
  if (to_file && !by_extension && chosen != PointFormat::txt)  // any other name is read back as text
    throw invalid_argument("format", format,
                           fmt::format("needs an output name ending in .{0} (not {1}): stratum reads a file as .{0} "
                                       "by its extension, any other name as whitespace text",
                                       format_name(chosen), output));
  return chosen;
}

void write_points_file(OutputFile& output, const PointSet& points, PointFormat format) {
  output.write([&](std::ostream& out) { write_points(out, points, format); });
  output.commit();
}

void write_points_file(const std::filesystem::path& path, const PointSet& points, PointFormat format) {
  resolve_point_format(path.string(), format_name(format));
  OutputFile output("output", path.string());
  output.prepare();
  write_points_file(output, points, format);
}

static PointSet read_npy(std::ifstream& in, const std::string& name) {
  char magic[10];
  in.read(magic, 10);
  if (!in || std::memcmp(magic, "\x93NUMPY", 6) != 0) throw invalid_argument("input", name, "is not a .npy file");
  std::size_t header_length = static_cast<unsigned char>(magic[8]) | (static_cast<unsigned char>(magic[9]) << 8);
  if (magic[6] != 1) {  // versions 2 and 3 have a 4-byte length
    char more[2];
    in.read(more, 2);
    header_length |= (static_cast<std::size_t>(static_cast<unsigned char>(more[0])) << 16) |
                     (static_cast<std::size_t>(static_cast<unsigned char>(more[1])) << 24);
  }
  std::string header(header_length, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header_length));
  if (header.find("'<f8'") == std::string::npos || header.find("'fortran_order': False") == std::string::npos)
    throw invalid_argument("input", name, "must hold a C-ordered little-endian float64 array");
  std::size_t n = 0, d = 1;
  const auto open = header.find('('), close = header.find(')');
  if (open == std::string::npos || close == std::string::npos)
    throw invalid_argument("input", name, "has no shape in its .npy header");
  const std::string shape = header.substr(open + 1, close - open - 1);
  if (std::sscanf(shape.c_str(), "%zu, %zu", &n, &d) < 1) throw invalid_argument("input", name, "has a bad shape");
  PointSet points;
  points.n = n;
  points.d = d;
  points.data.reset(new double[n * d]);
  in.read(reinterpret_cast<char*>(points.data.get()), static_cast<std::streamsize>(n * d * sizeof(double)));
  if (!in) throw invalid_argument("input", name, "is truncated");
  return points;
}

PointSet read_points_file(const std::filesystem::path& path) {
  refuse_special_file("input", path.string());  // a FIFO or /dev/zero would never end
  std::ifstream in(path, std::ios::binary);
  if (!in) throw invalid_argument("input", path.string(), "cannot be opened");
  if (path.extension() == ".npy") return read_npy(in, path.string());
  std::vector<double> values;
  std::size_t d = 0, n = 0;
  std::string line;
  while (std::getline(in, line)) {
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream fields(line);
    std::size_t count = 0;
    std::string field;
    while (fields >> field) {
      char* end = nullptr;
      const double value = std::strtod(field.c_str(), &end);
      if (end == field.c_str() || *end != '\0')
        throw invalid_argument("input", path.string(), fmt::format("line {} has a non-number '{}'", n + 1, field));
      values.push_back(value);
      ++count;
    }
    if (count == 0) continue;
    if (d == 0) d = count;
    if (count != d)
      throw invalid_argument("input", path.string(),
                             fmt::format("line {} has {} values, expected {}", n + 1, count, d));
    ++n;
  }
  if (n == 0) throw invalid_argument("input", path.string(), "holds no points");
  PointSet points;
  points.n = n;
  points.d = d;
  points.data.reset(new double[n * d]);
  std::copy(values.begin(), values.end(), points.data.get());
  return points;
}

}  // namespace stratum::io
