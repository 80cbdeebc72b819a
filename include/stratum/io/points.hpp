#pragma once
/// Point-set files: whitespace text, CSV and NumPy .npy (format 1.0,
/// little-endian float64, C order). Files are written to a temporary name
/// and renamed, so a failure never leaves a partial file.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "stratum/registry.hpp"

namespace stratum::io {

enum class PointFormat { txt, csv, npy };

/// Parses "txt", "csv" or "npy"; throws invalid_argument naming `format`.
PointFormat parse_point_format(const std::string& text);

/// Writes points to a stream (txt and csv: 17 significant digits, enough to
/// round-trip a double; npy: binary).
void write_points(std::ostream& out, const PointSet& points, PointFormat format);

/// Writes points to `path` atomically (temporary file in the same directory,
/// then rename). Throws invalid_argument naming `output` when the path cannot
/// be written.
void write_points_file(const std::filesystem::path& path, const PointSet& points, PointFormat format);

/// Reads a point set written in any of the three formats (by extension:
/// .npy, .csv, anything else is whitespace text).
PointSet read_points_file(const std::filesystem::path& path);

}  // namespace stratum::io
