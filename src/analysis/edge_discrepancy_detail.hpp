#pragma once
/// Pieces shared by the edge-discrepancy sources (edge_discrepancy*.cpp).
#include <cmath>
#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

#include "stratum/analysis/edge_discrepancy.hpp"

namespace stratum::analysis::edge_detail {

constexpr double pi = 3.14159265358979323846;

/// D of the line through (px, py) with direction (vx, vy) ≠ 0, whose
/// negative side {x : (−vy, vx)·(x − p) < 0} holds `negative` points and
/// which carries `on_line` points, out of `total`.
struct LineValue {
  double value;
  EdgeLine line;
};
inline LineValue line_value(double px, double py, double vx, double vy, std::size_t negative, std::size_t on_line,
                            std::size_t total) {
  const double length = std::hypot(vx, vy);
  const double nx = -vy / length, ny = vx / length;
  const double offset = nx * px + ny * py;
  const double area = half_plane_area(nx, ny, offset);
  const double n = static_cast<double>(total);
  const double value =
      std::max(static_cast<double>(negative + on_line) / n - area, area - static_cast<double>(negative) / n);
  double angle = std::atan2(ny, nx);
  if (angle < 0) angle += 2 * pi;
  return {value, {angle, offset}};
}

/// The points e on the square's boundary with 2p − e also on it: the chord
/// through p and e has p as its midpoint, so the area cut off is stationary
/// as the line turns about p. Also the two diagonal directions through p:
/// for a corner point those lines touch the square only at p, where the area
/// is 0 or 1 for a whole range of directions. Writes up to 10 points (x, y)
/// and returns how many; some may equal p or repeat.
inline int chord_bisector_endpoints(double px, double py, double* ex, double* ey) {
  int count = 0;
  // Square's horizontal edges y ∈ {0,1} against the reflected vertical edges x ∈ {2px, 2px − 1}.
  for (double x : {2 * px, 2 * px - 1})
    for (double y : {0.0, 1.0})
      if (x >= 0 && x <= 1 && y >= 2 * py - 1 && y <= 2 * py) ex[count] = x, ey[count] = y, ++count;
  // Square's vertical edges x ∈ {0,1} against the reflected horizontal edges y ∈ {2py, 2py − 1}.
  for (double x : {0.0, 1.0})
    for (double y : {2 * py, 2 * py - 1})
      if (y >= 0 && y <= 1 && x >= 2 * px - 1 && x <= 2 * px) ex[count] = x, ey[count] = y, ++count;
  ex[count] = px + 1, ey[count] = py + 1, ++count;
  ex[count] = px + 1, ey[count] = py - 1, ++count;
  return count;
}

/// Runs body(begin, end) over [0, count) on `threads` threads (0: all cores).
void parallel_ranges(std::size_t count, unsigned threads, const std::function<void(std::size_t, std::size_t)>& body);

/// Throws stratum::invalid_argument unless the points are 2D in [0,1]².
void require_plane_points(const PointView& points);

/// The best of per-task results, the first (lowest index) on ties.
EdgeDiscrepancy best_of(const std::vector<EdgeDiscrepancy>& results);

}  // namespace stratum::analysis::edge_detail
