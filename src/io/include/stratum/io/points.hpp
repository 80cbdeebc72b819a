#pragma once
/// Point-set files: whitespace text, CSV and NumPy .npy (format 1.0,
/// little-endian float64, C order). Files are written through
/// io::OutputFile, so a failure never leaves a partial file.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include "stratum/util/point_set.hpp"

namespace stratum::io {

class OutputFile;

enum class PointFormat { txt, csv, npy };

/// Parses "txt", "csv" or "npy"; throws invalid_argument naming `format`.
PointFormat parse_point_format(const std::string& text);

/// Writes points to a stream (txt and csv: 17 significant digits, enough to
/// round-trip a double; npy: binary).
void write_points(std::ostream& out, const PointSet& points, PointFormat format);

/// The format an extension names (.npy, .csv, .txt), if any.
std::optional<PointFormat> point_format_of_extension(const std::filesystem::path& path);

/// The format of a table written to `output` ("" or "-": stdout) with
/// --format `format` ("": by the extension, txt otherwise). Throws
/// invalid_argument naming `format` when it contradicts the extension
/// (`-o x.npy --format txt`): stratum reads files back by their extension.
PointFormat resolve_point_format(const std::string& output, const std::string& format);

/// Writes points to `path` through an io::OutputFile (docs/outputs.md):
/// never half-written. Throws invalid_argument naming
/// `output` when the path cannot be written, or `format` when it contradicts
/// the extension.
void write_points_file(const std::filesystem::path& path, const PointSet& points, PointFormat format);

/// Writes points into a prepared output and commits it.
void write_points_file(OutputFile& output, const PointSet& points, PointFormat format);

/// Reads a point set written in any of the three formats (by extension:
/// .npy, .csv, anything else is whitespace text).
PointSet read_points_file(const std::filesystem::path& path);

}  // namespace stratum::io
