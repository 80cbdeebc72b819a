#pragma once
// Brute-force distances: the oracle for the grid-accelerated searches of the
// blue-noise patterns (Poisson disk, best candidate, neighbour grid).
#include <algorithm>
#include <cmath>
#include <vector>

namespace stratum::testing {

/// Squared distance, toroidal (wrap-around) when periodic.
inline double distance2(const double* a, const double* b, unsigned d, bool periodic) {
  double sum = 0;
  for (unsigned j = 0; j < d; ++j) {
    double delta = std::abs(a[j] - b[j]);
    if (periodic) delta = std::min(delta, 1 - delta);
    sum += delta * delta;
  }
  return sum;
}

/// Smallest pairwise distance of row-major points, O(n²).
inline double min_distance(const std::vector<double>& points, unsigned d, bool periodic) {
  double best = 1e300;
  const std::size_t n = points.size() / d;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      best = std::min(best, distance2(&points[a * d], &points[b * d], d, periodic));
  return std::sqrt(best);
}

}  // namespace stratum::testing
