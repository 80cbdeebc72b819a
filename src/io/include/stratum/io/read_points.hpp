#pragma once
/// Strict reading of point-set files for measurement (`stratum discrepancy
/// FILE`): every row must have the same number of columns, every field must
/// be a finite number, and the message for a bad file names the line (text)
/// or the row and column (.npy) at fault. The lenient reader in points.hpp
/// stays as it is for round trips of files stratum wrote itself.
#include <filesystem>
#include <string>

#include "stratum/util/point_set.hpp"

namespace stratum::io {

/// Reads points from `path`, chosen by extension:
/// - `.npy`: NumPy format 1.0–3.0, little-endian float64 ('<f8'), C order,
///   shape (n, d) or (n,) (then d = 1);
/// - `.csv`: comma-separated numbers, one point per line;
/// - anything else: whitespace-separated numbers, one point per line.
/// In text files, blank lines and lines starting with '#' are skipped.
/// Throws stratum::invalid_argument naming `input` and what is wrong: a file
/// that cannot be opened or holds no points, a line whose column count
/// differs from the first point's (naming the line), a field that is not a
/// number (line and column), NaN or ±Inf (line or row, and column), a bad or
/// truncated .npy header or body. Range checks ([0, 1]) are the measures'.
PointSet read_points_strict(const std::filesystem::path& path);

/// Where point `row` (from 0) of a file read_points_strict read is, for a
/// message: "line L" of a text file (counting the blank and '#' lines it
/// skipped), "row R" of a .npy file.
std::string point_location(const std::filesystem::path& path, std::size_t row);

/// Throws invalid_argument naming `path`, the line (point_location) and the
/// column of the first coordinate of `points` outside [0, 1], as a measure
/// needs them: the measure's own message could name only the point's index.
void check_unit_cube(const PointSet& points, const std::filesystem::path& path);

}  // namespace stratum::io
