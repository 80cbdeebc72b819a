/// Mitchell's random-edge discrepancy and the search lower bound of the
/// exact edge discrepancy (see edge_discrepancy.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "edge_discrepancy_detail.hpp"
#include "stratum/analysis/edge_discrepancy.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::analysis {

using edge_detail::pi;

EdgeLine random_isotropic_line(std::uint64_t seed, std::uint64_t index) {
  // The motion-invariant density dp dθ (Santaló 1976, ch. 3) restricted to
  // the lines hitting the square is uniform on {θ ∈ [0, π), p ∈ [lo(θ),
  // hi(θ)]}, the square's projection onto (cos θ, sin θ). Its θ-marginal is
  // proportional to the width hi − lo (1 to √2), so θ is not uniform: draw θ
  // uniform and p uniform on an interval of length √2 about the centre's
  // projection, and reject p outside [lo, hi] (acceptance 4/(π√2) ≈ 0.90).
  for (std::uint64_t attempt = 0;; ++attempt) {
    const double angle = pi * uniform01(seed, index, 2 * attempt);
    const double nx = std::cos(angle), ny = std::sin(angle);
    const double lo = std::min(0.0, nx) + std::min(0.0, ny), hi = std::max(0.0, nx) + std::max(0.0, ny);
    const double offset = 0.5 * (nx + ny) + std::sqrt(2.0) * (uniform01(seed, index, 2 * attempt + 1) - 0.5);
    if (offset >= lo && offset <= hi) return {angle, offset};
  }
}

double line_discrepancy(const PointView& points, const EdgeLine& line) {
  const double nx = std::cos(line.angle), ny = std::sin(line.angle);
  std::size_t below = 0, on_line = 0;
  for (std::size_t i = 0; i < points.n; ++i) {
    const double t = nx * points(i, 0) + ny * points(i, 1);
    below += t < line.offset;
    on_line += t == line.offset;
  }
  const double area = half_plane_area(nx, ny, line.offset);
  const double n = static_cast<double>(points.n);
  return std::max(static_cast<double>(below + on_line) / n - area, area - static_cast<double>(below) / n);
}

RandomEdgeDiscrepancy random_edge_discrepancy(const PointView& points, std::size_t lines, std::uint64_t seed,
                                              unsigned threads) {
  require(lines >= 1, "lines", lines, "random-edge discrepancy needs at least 1 line");
  edge_detail::require_plane_points(points);
  std::vector<double> values(lines);
  edge_detail::parallel_ranges(lines, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) values[i] = line_discrepancy(points, random_isotropic_line(seed, i));
  });
  // Summed in index order: the same result for any thread count.
  RandomEdgeDiscrepancy result;
  double sum = 0, sum_squares = 0;
  for (double v : values) {
    sum += v;
    sum_squares += v * v;
    result.max = std::max(result.max, v);
  }
  result.lines = lines;
  result.mean = sum / static_cast<double>(lines);
  result.rms = std::sqrt(sum_squares / static_cast<double>(lines));
  return result;
}

namespace {

/// The best offset for one direction: sort the projections, evaluate D at
/// each distinct one (between them the count is fixed and the area
/// monotone, so the extremes sit at the projections).
EdgeDiscrepancy best_offset(const PointView& points, double angle, std::vector<double>& projections) {
  const double nx = std::cos(angle), ny = std::sin(angle);
  projections.resize(points.n);
  for (std::size_t i = 0; i < points.n; ++i) projections[i] = nx * points(i, 0) + ny * points(i, 1);
  std::sort(projections.begin(), projections.end());
  const double n = static_cast<double>(points.n);
  EdgeDiscrepancy best{-1, {}};
  for (std::size_t first = 0; first < projections.size();) {
    std::size_t last = first + 1;
    while (last < projections.size() && projections[last] == projections[first]) ++last;
    const double area = half_plane_area(nx, ny, projections[first]);
    const double value = std::max(static_cast<double>(last) / n - area, area - static_cast<double>(first) / n);
    if (value > best.value) best = {value, {angle, projections[first]}};
    first = last;
  }
  return best;
}

}  // namespace

EdgeDiscrepancy edge_discrepancy_search(const PointView& points, std::size_t angles, unsigned threads) {
  require(angles >= 1, "angles", angles, "the search needs at least 1 direction");
  edge_detail::require_plane_points(points);
  // Directions in [0, π) suffice: D(ℓ) is the same for both half-planes.
  const double step = pi / static_cast<double>(angles);
  std::vector<EdgeDiscrepancy> coarse(angles);
  edge_detail::parallel_ranges(angles, threads, [&](std::size_t begin, std::size_t end) {
    std::vector<double> projections;
    for (std::size_t k = begin; k < end; ++k)
      coarse[k] = best_offset(points, step * static_cast<double>(k), projections);
  });
  const double coarse_best = edge_detail::best_of(coarse).value;
  std::vector<std::size_t> promising;
  for (std::size_t k = 0; k < angles; ++k)
    if (coarse[k].value >= coarse_best - 2e-3) promising.push_back(k);
  std::vector<EdgeDiscrepancy> refined(promising.size());
  edge_detail::parallel_ranges(promising.size(), threads, [&](std::size_t begin, std::size_t end) {
    std::vector<double> projections;
    for (std::size_t c = begin; c < end; ++c) {
      EdgeDiscrepancy best = coarse[promising[c]];
      double centre = best.line.angle, width = step;
      for (int round = 0; round < 3; ++round, width /= 1000) {
        const double start = centre - width;
        for (int j = 0; j <= 2000; ++j) {
          const auto candidate = best_offset(points, start + width * j / 1000.0, projections);
          if (candidate.value > best.value) best = candidate;
        }
        centre = best.line.angle;
      }
      refined[c] = best;
    }
  });
  EdgeDiscrepancy best = edge_detail::best_of(refined);
  if (best.line.angle < 0) best.line = {best.line.angle + pi, -best.line.offset};
  return best;
}

}  // namespace stratum::analysis
