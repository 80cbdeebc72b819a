/// Exact edge discrepancy: exact orientation predicate, half-plane area,
/// the O(N² log N) rotational sweep and the O(N³) direct enumeration.
#include "stratum/analysis/edge_discrepancy.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "edge_discrepancy_detail.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::analysis {

namespace {

// Error-free transformations (Dekker 1971; Knuth; Shewchuk 1997). Written
// without fma so that they stay exact on any x86-64 target.
inline void two_sum(double a, double b, double& sum, double& error) {
  sum = a + b;
  const double b_virtual = sum - a;
  const double a_virtual = sum - b_virtual;
  error = (a - a_virtual) + (b - b_virtual);
}
inline void two_diff(double a, double b, double& difference, double& error) {
  difference = a - b;
  const double b_virtual = a - difference;
  const double a_virtual = difference + b_virtual;
  error = (a - a_virtual) + (b_virtual - b);
}
inline void split(double a, double& high, double& low) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  high = c - (c - a);
  low = a - high;
}
inline void two_product(double a, double b, double& product, double& error) {
  product = a * b;
  double a_high, a_low, b_high, b_low;
  split(a, a_high, a_low);
  split(b, b_high, b_low);
  const double e1 = product - a_high * b_high;
  const double e2 = e1 - a_low * b_high;
  const double e3 = e2 - a_high * b_low;
  error = a_low * b_low - e3;
}

/// Sign of det[q − p, r − p] from the exact expansion of its 16 partial
/// products (each difference is split into two doubles exactly).
int exact_orientation(double px, double py, double qx, double qy, double rx, double ry) {
  double ax[2], ay[2], bx[2], by[2];
  two_diff(qx, px, ax[1], ax[0]);
  two_diff(qy, py, ay[1], ay[0]);
  two_diff(rx, px, bx[1], bx[0]);
  two_diff(ry, py, by[1], by[0]);
  double expansion[16];
  int length = 0;
  // Shewchuk's Grow-Expansion keeps the expansion non-overlapping and
  // ordered by magnitude, so its most significant non-zero term has the
  // sign of the sum.
  auto grow = [&](double term) {
    double carry = term;
    for (int i = 0; i < length; ++i) {
      double sum, error;
      two_sum(carry, expansion[i], sum, error);
      expansion[i] = error;
      carry = sum;
    }
    expansion[length++] = carry;
  };
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      double product, error;
      two_product(ax[i], by[j], product, error);
      grow(product);
      grow(error);
      two_product(ay[i], bx[j], product, error);
      grow(-product);
      grow(-error);
    }
  for (int i = length - 1; i >= 0; --i)
    if (expansion[i] != 0) return expansion[i] > 0 ? 1 : -1;
  return 0;
}

/// A point seen from the sweep's centre, its direction turned into [0, π).
struct Ray {
  double key;  ///< pseudo-angle 1 − vx/(|vx| + vy), increasing with the angle in [0, π)
  double vx, vy;
  std::uint32_t index;
  bool flipped;  ///< direction negated: the point lies behind the centre
};

/// One direction of the sweep: the rays [first, last) are collinear with the centre.
struct Group {
  std::size_t first, last;
  std::size_t negative_before;  ///< points on the negative side just before this direction
  std::size_t flipped;          ///< rays of the group that were negated
};

}  // namespace

int orientation(double px, double py, double qx, double qy, double rx, double ry) {
  const double left = (qx - px) * (ry - py);
  const double right = (qy - py) * (rx - px);
  const double det = left - right;
  // Shewchuk's (1997) bound on the error of the floating-point orient2d.
  constexpr double epsilon = 0x1.0p-53;
  constexpr double bound = (3.0 + 16.0 * epsilon) * epsilon;
  const double error = bound * (std::abs(left) + std::abs(right));
  if (det > error) return 1;
  if (-det > error) return -1;
  return exact_orientation(px, py, qx, qy, rx, ry);
}

double half_plane_area(double normal_x, double normal_y, double offset) {
  // Clip the square by the half-plane (Sutherland, Hodgman 1974), then the shoelace formula.
  static constexpr double corner_x[4] = {0, 1, 1, 0}, corner_y[4] = {0, 0, 1, 1};
  double x[8], y[8];
  int count = 0;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const double si = normal_x * corner_x[i] + normal_y * corner_y[i] - offset;
    const double sj = normal_x * corner_x[j] + normal_y * corner_y[j] - offset;
    if (si < 0) x[count] = corner_x[i], y[count] = corner_y[i], ++count;
    if ((si < 0) != (sj < 0)) {
      const double t = si / (si - sj);
      x[count] = corner_x[i] + t * (corner_x[j] - corner_x[i]);
      y[count] = corner_y[i] + t * (corner_y[j] - corner_y[i]);
      ++count;
    }
  }
  double twice = 0;
  for (int i = 0; i < count; ++i) {
    const int j = (i + 1) % count;
    twice += x[i] * y[j] - x[j] * y[i];
  }
  return std::clamp(0.5 * twice, 0.0, 1.0);
}

namespace edge_detail {

void parallel_ranges(std::size_t count, unsigned threads, const std::function<void(std::size_t, std::size_t)>& body) {
  oneapi::tbb::task_arena arena(threads == 0 ? oneapi::tbb::task_arena::automatic : static_cast<int>(threads));
  arena.execute([&] {
    oneapi::tbb::parallel_for(oneapi::tbb::blocked_range<std::size_t>(0, count),
                              [&](const oneapi::tbb::blocked_range<std::size_t>& range) {
                                check_interrupt();
                                body(range.begin(), range.end());
                              });
  });
}

void require_plane_points(const PointView& points) {
  require(points.d == 2, "d", points.d, "edge discrepancy is defined for points in the unit square (d = 2)");
  require(points.n <= (std::size_t{1} << 31), "n", points.n, "edge discrepancy takes at most 2^31 points");
  check_unit_cube(points);
}

EdgeDiscrepancy best_of(const std::vector<EdgeDiscrepancy>& results) {
  EdgeDiscrepancy best{-1, {}};
  for (const auto& result : results)
    if (result.value > best.value) best = result;
  return best;
}

}  // namespace edge_detail

namespace {

using edge_detail::line_value;

/// The best line through point `centre`: a sweep over the directions of the
/// other points, then the chord-bisecting directions located in that order.
EdgeDiscrepancy sweep_about(const PointView& points, std::size_t centre, std::vector<Ray>& rays,
                            std::vector<Group>& groups) {
  const double px = points(centre, 0), py = points(centre, 1);
  rays.clear();
  groups.clear();
  std::size_t duplicates = 0, flipped_total = 0;
  for (std::size_t q = 0; q < points.n; ++q) {
    if (q == centre) continue;
    const double dx = points(q, 0) - px, dy = points(q, 1) - py;
    if (points(q, 0) == px && points(q, 1) == py) {
      ++duplicates;
      continue;
    }
    const bool flipped = points(q, 1) < py || (points(q, 1) == py && points(q, 0) < px);
    flipped_total += flipped;
    const double vx = flipped ? -dx : dx, vy = flipped ? -dy : dy;
    rays.push_back({1 - vx / (std::abs(vx) + vy), vx, vy, static_cast<std::uint32_t>(q), flipped});
  }
  // Exact angular comparison of directions in [0, π): a before b iff cross(a, b) > 0.
  auto turn = [&](bool flip_a, std::size_t a, bool flip_b, double bx, double by) {
    const int sign = orientation(px, py, points(a, 0), points(a, 1), bx, by);
    return flip_a == flip_b ? sign : -sign;
  };
  auto before = [&](const Ray& a, const Ray& b) {
    return turn(a.flipped, a.index, b.flipped, points(b.index, 0), points(b.index, 1)) > 0;
  };
  // Sort by the rounded pseudo-angle (fast), then an insertion sort with the
  // exact comparison: it makes the order exact and costs O(N) when rounding
  // misordered only near-collinear neighbours.
  std::sort(rays.begin(), rays.end(), [](const Ray& a, const Ray& b) { return a.key < b.key; });
  for (std::size_t i = 1; i < rays.size(); ++i)
    for (std::size_t j = i; j > 0 && before(rays[j], rays[j - 1]); --j) std::swap(rays[j], rays[j - 1]);
  // At direction 0⁻ the negative side {y < p_y or (y = p_y, x < p_x)} holds exactly the flipped rays.
  std::size_t negative = flipped_total;
  const std::size_t on_centre = 1 + duplicates;
  EdgeDiscrepancy best{-1, {}};
  auto consider = [&](double vx, double vy, std::size_t below, std::size_t on_line) {
    const auto candidate = line_value(px, py, vx, vy, below, on_line, points.n);
    if (candidate.value > best.value) best = {candidate.value, candidate.line};
  };
  for (std::size_t first = 0; first < rays.size();) {
    std::size_t last = first + 1, flipped = rays[first].flipped;
    while (last < rays.size() && turn(rays[first].flipped, rays[first].index, rays[last].flipped,
                                      points(rays[last].index, 0), points(rays[last].index, 1)) == 0)
      flipped += rays[last++].flipped;
    groups.push_back({first, last, negative, flipped});
    // Turning through the group, forward points cross to the negative side and flipped ones leave it.
    consider(rays[first].vx, rays[first].vy, negative - flipped, on_centre + (last - first));
    negative = negative - flipped + ((last - first) - flipped);
    first = last;
  }
  double ex[16], ey[16];
  const int endpoints = edge_detail::chord_bisector_endpoints(px, py, ex, ey);
  for (int k = 0; k < endpoints; ++k) {
    if (ex[k] == px && ey[k] == py) continue;
    const bool flip = ey[k] < py || (ey[k] == py && ex[k] < px);
    // First group whose direction is not before the endpoint's.
    const auto position = std::partition_point(groups.begin(), groups.end(), [&](const Group& group) {
      const Ray& ray = rays[group.first];
      return turn(ray.flipped, ray.index, flip, ex[k], ey[k]) > 0;
    });
    const double vx = flip ? px - ex[k] : ex[k] - px, vy = flip ? py - ey[k] : ey[k] - py;
    if (position == groups.end()) {
      consider(vx, vy, negative, on_centre);
    } else {
      const Ray& ray = rays[position->first];
      if (turn(ray.flipped, ray.index, flip, ex[k], ey[k]) == 0)
        consider(vx, vy, position->negative_before - position->flipped, on_centre + (position->last - position->first));
      else consider(vx, vy, position->negative_before, on_centre);
    }
  }
  return best;
}

}  // namespace

EdgeDiscrepancy edge_discrepancy(const PointView& points, unsigned threads) {
  edge_detail::require_plane_points(points);
  std::vector<EdgeDiscrepancy> per_point(points.n);
  edge_detail::parallel_ranges(points.n, threads, [&](std::size_t begin, std::size_t end) {
    std::vector<Ray> rays;
    std::vector<Group> groups;
    rays.reserve(points.n);
    for (std::size_t i = begin; i < end; ++i) per_point[i] = sweep_about(points, i, rays, groups);
  });
  return edge_detail::best_of(per_point);
}

EdgeDiscrepancy edge_discrepancy_naive(const PointView& points, unsigned threads) {
  edge_detail::require_plane_points(points);
  const std::size_t n = points.n;
  std::vector<EdgeDiscrepancy> per_point(n);
  // Counts the sides of the line through point i and (x, y) by n orientation tests.
  auto evaluate = [&](std::size_t i, double x, double y, EdgeDiscrepancy& best) {
    const double px = points(i, 0), py = points(i, 1);
    std::size_t negative = 0, on_line = 0;
    for (std::size_t q = 0; q < n; ++q) {
      const int side = orientation(px, py, x, y, points(q, 0), points(q, 1));
      negative += side < 0;
      on_line += side == 0;
    }
    const auto candidate = line_value(px, py, x - px, y - py, negative, on_line, n);
    if (candidate.value > best.value) best = {candidate.value, candidate.line};
  };
  edge_detail::parallel_ranges(n, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      EdgeDiscrepancy best{-1, {}};
      const double px = points(i, 0), py = points(i, 1);
      for (std::size_t j = i + 1; j < n; ++j)
        if (points(j, 0) != px || points(j, 1) != py) evaluate(i, points(j, 0), points(j, 1), best);
      double ex[16], ey[16];
      const int endpoints = edge_detail::chord_bisector_endpoints(px, py, ex, ey);
      for (int k = 0; k < endpoints; ++k)
        if (ex[k] != px || ey[k] != py) evaluate(i, ex[k], ey[k], best);
      per_point[i] = best;
    }
  });
  return edge_detail::best_of(per_point);
}

}  // namespace stratum::analysis
