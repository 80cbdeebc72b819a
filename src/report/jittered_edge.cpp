#include "jittered_edge.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "stratum/util/hash.hpp"

namespace stratum::report {

HalfPlane random_edge_half_plane(std::uint64_t seed) {
  const double angle = 2 * std::numbers::pi * uniform01(seed, 2);
  return {{uniform01(seed, 0), uniform01(seed, 1)}, {std::cos(angle), std::sin(angle)}};
}

double half_plane_area(const HalfPlane& plane, double x0, double y0, double x1, double y1) {
  using Point = std::array<double, 2>;
  const Point box[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  const auto side = [&](const Point& q) {
    return (q[0] - plane.point[0]) * plane.normal[0] + (q[1] - plane.point[1]) * plane.normal[1];
  };
  std::vector<Point> polygon;
  for (int k = 0; k < 4; ++k) {
    const Point& a = box[k];
    const Point& b = box[(k + 1) % 4];
    const double sa = side(a), sb = side(b);
    if (sa < 0) polygon.push_back(a);
    if ((sa < 0) != (sb < 0)) {
      const double t = sa / (sa - sb);
      polygon.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  double twice = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Point& a = polygon[k];
    const Point& b = polygon[(k + 1) % polygon.size()];
    twice += a[0] * b[1] - a[1] * b[0];
  }
  return std::abs(twice) / 2;
}

namespace {

/// Calls `visit(a)` with each cell's covered fraction.
template <class Visit>
void for_each_cell_fraction(const HalfPlane& plane, std::uint64_t n, Visit visit) {
  const double h = 1.0 / double(n), cell = h * h;
  for (std::uint64_t i = 0; i < n; ++i)
    for (std::uint64_t j = 0; j < n; ++j) {
      const double x0 = double(i) * h, y0 = double(j) * h;
      visit(half_plane_area(plane, x0, y0, x0 + h, y0 + h) / cell);
    }
}

}  // namespace

double jittered_edge_variance(const HalfPlane& plane, std::uint64_t n) {
  double sum = 0;
  for_each_cell_fraction(plane, n, [&](double a) { sum += a * (1 - a); });
  const double cells = double(n) * double(n);
  return sum / (cells * cells);
}

std::uint64_t cut_cells(const HalfPlane& plane, std::uint64_t n) {
  std::uint64_t count = 0;
  // Fractions within 1e-12 of 0 or 1 are rounding of a cell the line only touches.
  for_each_cell_fraction(plane, n, [&](double a) { count += a > 1e-12 && a < 1 - 1e-12; });
  return count;
}

}  // namespace stratum::report
