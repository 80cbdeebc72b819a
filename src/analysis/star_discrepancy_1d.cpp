// The 1D star discrepancy in closed form and the dispatch to the exact method
// for each d (see src/analysis/include/stratum/analysis/star_discrepancy.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {

/// Niederreiter 1992, "Random Number Generation and Quasi-Monte Carlo
/// Methods", Theorem 2.6: for sorted x_(1) ≤ … ≤ x_(N) in [0,1],
/// D*_N = 1/(2N) + max_i |x_(i) − (2i−1)/(2N)|. It holds with ties and with
/// points at 1 (such a point lies in no [0,x), x ≤ 1).
double star_discrepancy_1d(const PointView& points) {
  require(points.d == 1, "d", points.d, "the 1D closed form needs d = 1");
  require(points.n >= 1, "n", points.n, "needs at least 1 point");
  std::vector<double> x(points.data, points.data + points.n);
  std::sort(x.begin(), x.end());
  const double two_n = 2.0 * static_cast<double>(points.n);
  double worst = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    worst = std::max(worst, std::abs(x[i] - static_cast<double>(2 * i + 1) / two_n));
  return 1.0 / two_n + worst;
}

std::size_t star_dem_max_points(std::size_t d) {
  require(d >= 3, "d", d, "the DEM size limit is for d >= 3");
  // Measured on Halton points, see the header.
  constexpr std::size_t measured[] = {14000, 2200, 650, 260, 140, 80};
  if (d <= 8) return measured[d - 3];
  const double budget = std::pow(80.0, 5.0);  // the d = 8 limit's N^{1+d/2}
  // + 1e-9: an exact root must not round down.
  return static_cast<std::size_t>(std::floor(std::pow(budget, 1.0 / (1.0 + static_cast<double>(d) / 2.0)) + 1e-9));
}

bool star_exact_feasible(std::size_t n, std::size_t d) {
  if (d <= 1) return true;
  if (d == 2) return n <= kStarExact2dMaxPoints;
  return n <= star_dem_max_points(d);
}

double star_discrepancy_exact(const PointView& points, unsigned threads) {
  if (points.d == 1) return star_discrepancy_1d(points);
  if (!star_exact_feasible(points.n, points.d)) {
    if (points.d == 2)
      throw invalid_argument(
          "n", std::to_string(points.n),
          "the exact 2D star discrepancy (O(n^2) sweep) handles n <= " + std::to_string(kStarExact2dMaxPoints) +
              "; method=bounds (Thiemard's delta-partition) gives lower and upper bounds for any n");
    throw invalid_argument(
        "d", std::to_string(points.d),
        "the exact star discrepancy for d >= 3 (Dobkin-Eppstein-Mitchell, O(n^(1+d/2))) handles n <= " +
            std::to_string(star_dem_max_points(points.d)) + " at d = " + std::to_string(points.d) +
            " (here n = " + std::to_string(points.n) +
            "); method=bounds (Thiemard's delta-partition) gives lower and upper bounds for any d");
  }
  if (points.d == 2) return star_discrepancy_2d(points, threads);
  return star_discrepancy_dem(points, threads);
}

}  // namespace stratum::analysis
