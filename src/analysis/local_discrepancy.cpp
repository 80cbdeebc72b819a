/// The local discrepancy picture and the box of the supremum (local_discrepancy.hpp).
#include "stratum/analysis/local_discrepancy.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "stratum/util/error.hpp"

namespace stratum::analysis {

namespace {

/// The cell k of [0,1] split into `cells` with k/cells ≤ v < (k+1)/cells,
/// decided by the same comparison as the count (v < k/cells), so rounding
/// in v·cells cannot move a point across a corner; `cells` for v ≥ 1.
std::size_t cell_of(double v, std::size_t cells) {
  const double r = static_cast<double>(cells);
  if (!(v < 1)) return cells;
  auto k = static_cast<std::size_t>(std::clamp(std::floor(v * r), 0.0, r - 1));
  while (k > 0 && v < static_cast<double>(k) / r) --k;
  while (k + 1 < cells && v >= static_cast<double>(k + 1) / r) ++k;
  return k;
}

}  // namespace

LocalDiscrepancyGrid local_discrepancy_grid(const PointView& points, std::size_t resolution) {
  require(points.d == 2, "d", points.d, "the local discrepancy picture needs 2D points");
  require(resolution >= 1 && resolution <= 4096, "resolution", resolution, "must be in [1, 4096]");
  require(points.n >= 1, "n", points.n, "needs at least one point");  // n(x, y)/N
  const std::size_t r = resolution, side = r + 1;
  // counts[(b+1)·side + (a+1)] = points in cell (a, b); then 2D prefix sums
  // turn it into the count of [0, i/R) × [0, j/R) at index j·side + i.
  std::vector<double> counts(side * side, 0.0);
  for (std::size_t k = 0; k < points.n; ++k) {
    const std::size_t a = cell_of(points(k, 0), r), b = cell_of(points(k, 1), r);
    if (a < r && b < r) counts[(b + 1) * side + (a + 1)] += 1;
  }
  for (std::size_t j = 1; j < side; ++j)
    for (std::size_t i = 1; i < side; ++i)
      counts[j * side + i] += counts[(j - 1) * side + i] + counts[j * side + i - 1] - counts[(j - 1) * side + i - 1];
  LocalDiscrepancyGrid grid;
  grid.resolution = r;
  grid.values.resize(side * side);
  const double n = static_cast<double>(points.n), step = 1.0 / static_cast<double>(r);
  for (std::size_t j = 0; j < side; ++j)
    for (std::size_t i = 0; i < side; ++i) {
      const double delta = counts[j * side + i] / n - (static_cast<double>(i) * step) * (static_cast<double>(j) * step);
      grid.values[j * side + i] = delta;
      grid.max_abs = std::max(grid.max_abs, std::fabs(delta));
    }
  return grid;
}

StarDiscrepancyBox star_discrepancy_box(const PointView& points) {
  require(points.d == 2, "d", points.d, "the star-discrepancy box needs 2D points");
  require(points.n >= 1, "n", points.n, "needs at least one point");
  const std::size_t n = points.n;
  const double total = static_cast<double>(n);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return points(a, 0) < points(b, 0); });
  // Candidate corners: every point coordinate below 1, and 1.
  std::vector<double> xs, ys;
  for (std::size_t k = 0; k < n; ++k) {
    if (points(k, 0) < 1) xs.push_back(points(k, 0));
    if (points(k, 1) < 1) ys.push_back(points(k, 1));
  }
  xs.push_back(1);
  ys.push_back(1);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());

  StarDiscrepancyBox best;
  std::vector<double> left;    // sorted y of points with x < X (the open box's columns)
  std::vector<double> closed;  // sorted y of points with x ≤ X, both coordinates < 1
  std::size_t next = 0;        // first point in `order` with x ≥ X
  for (const double X : xs) {
    while (next < n && points(order[next], 0) < X) {
      const double y = points(order[next], 1);
      left.insert(std::upper_bound(left.begin(), left.end(), y), y);
      ++next;
    }
    closed.clear();
    for (double y : left)
      if (y < 1) closed.push_back(y);
    for (std::size_t k = next; k < n && points(order[k], 0) == X && X < 1; ++k) {
      const double y = points(order[k], 1);  // a point on the box's right edge
      if (y < 1) closed.insert(std::upper_bound(closed.begin(), closed.end(), y), y);
    }
    std::size_t open_count = 0, closed_count = 0;
    for (const double Y : ys) {
      while (open_count < left.size() && left[open_count] < Y) ++open_count;
      while (closed_count < closed.size() && closed[closed_count] <= Y) ++closed_count;
      const double volume = X * Y;
      const double too_few = volume - static_cast<double>(open_count) / total;
      const double too_many = static_cast<double>(closed_count) / total - volume;
      if (too_few > best.value) best = {too_few, X, Y, false, open_count};
      if (too_many > best.value) best = {too_many, X, Y, true, closed_count};
    }
  }
  return best;
}

}  // namespace stratum::analysis
