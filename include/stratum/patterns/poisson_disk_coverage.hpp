#pragma once
/// Exact tests that two or three disks of radius √r2 cover a box: the
/// certificates of the completion phase of stratum's maximal Poisson-disk
/// sampler (Ebeida et al. 2012, "A simple algorithm for maximal
/// Poisson-disk sampling in high dimensions"; see poisson_disk_grid.hpp).
/// "Yes" is always right; "no" may be wrong only when more disks are
/// needed, and the caller then splits the box.
#include <algorithm>
#include <limits>

namespace stratum::poisson_detail {

/// Two disks p, q cover the box [lo, lo + side]^D when every corner is
/// within r of p or q and every point where their bisector crosses an edge
/// of the box is within r of both: the farthest point of the box from
/// {p, q} is a corner or such a crossing, since the distance to p is convex
/// on the part of the box on p's side of the bisector.
template <unsigned D>
[[gnu::always_inline]] inline bool pair_covers(const double* lo, double side, const double* p, const double* q,
                                               double r2) noexcept {
  // Corners.
  for (unsigned corner = 0; corner < (1u << D); ++corner) {
    double dp = 0, dq = 0;
    for (unsigned j = 0; j < D; ++j) {
      const double x = lo[j] + ((corner >> j) & 1u ? side : 0.0);
      dp += (x - p[j]) * (x - p[j]);
      dq += (x - q[j]) * (x - q[j]);
    }
    if (std::min(dp, dq) > r2) return false;
  }
  // Bisector n·x = b crossing the edges along axis j.
  double n[D], b = 0;
  for (unsigned j = 0; j < D; ++j) {
    n[j] = q[j] - p[j];
    b += (q[j] * q[j] - p[j] * p[j]) / 2;
  }
  for (unsigned j = 0; j < D; ++j) {
    if (n[j] == 0) continue;
    for (unsigned fixed = 0; fixed < (1u << (D - 1)); ++fixed) {
      double x[D], rest = b;
      unsigned bit = 0;
      for (unsigned k = 0; k < D; ++k) {
        if (k == j) continue;
        x[k] = lo[k] + ((fixed >> bit++) & 1u ? side : 0.0);
        rest -= n[k] * x[k];
      }
      x[j] = rest / n[j];
      if (!(x[j] >= lo[j] && x[j] <= lo[j] + side)) continue;
      double dp = 0;
      for (unsigned k = 0; k < D; ++k) dp += (x[k] - p[k]) * (x[k] - p[k]);
      if (dp > r2) return false;
    }
  }
  return true;
}

/// In the plane: three disks cover a square when no candidate for the
/// farthest point of the square from the sites is farther than r from all
/// three: the corners, where a pair's bisector crosses an edge, and the
/// sites' circumcentre (the Voronoi vertex) when it lies in the square. The
/// distance to the nearest site is convex on each Voronoi cell, so its
/// maximum over the square is at a vertex of the cells clipped to it.
inline bool triple_covers(const double* lo, double side, const double (*site)[2], double r2) noexcept {
  const auto too_far = [&](double x, double y) {
    double nearest = std::numeric_limits<double>::infinity();
    for (unsigned i = 0; i < 3; ++i)
      nearest = std::min(nearest, (x - site[i][0]) * (x - site[i][0]) + (y - site[i][1]) * (y - site[i][1]));
    return nearest > r2;
  };
  const double hi[2] = {lo[0] + side, lo[1] + side};
  for (unsigned corner = 0; corner < 4; ++corner)
    if (too_far(corner & 1u ? hi[0] : lo[0], corner & 2u ? hi[1] : lo[1])) return false;
  double n[3][2], b[3];  // bisector of sites a and a+1: n·x = b
  for (unsigned k = 0; k < 3; ++k) {
    const double* p = site[k];
    const double* q = site[(k + 1) % 3];
    n[k][0] = q[0] - p[0];
    n[k][1] = q[1] - p[1];
    b[k] = (q[0] * q[0] + q[1] * q[1] - p[0] * p[0] - p[1] * p[1]) / 2;
    for (unsigned e = 0; e < 2; ++e) {
      if (n[k][0] != 0) {  // crossing the edge y = lo or hi
        const double y = e ? hi[1] : lo[1], x = (b[k] - n[k][1] * y) / n[k][0];
        if (x >= lo[0] && x <= hi[0] && too_far(x, y)) return false;
      }
      if (n[k][1] != 0) {  // crossing the edge x = lo or hi
        const double x = e ? hi[0] : lo[0], y = (b[k] - n[k][0] * x) / n[k][1];
        if (y >= lo[1] && y <= hi[1] && too_far(x, y)) return false;
      }
    }
  }
  const double det = n[0][0] * n[1][1] - n[0][1] * n[1][0];
  if (det != 0) {  // the circumcentre: on the bisectors of (0, 1) and (1, 2)
    const double x = (b[0] * n[1][1] - n[0][1] * b[1]) / det, y = (n[0][0] * b[1] - b[0] * n[1][0]) / det;
    if (x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1] && too_far(x, y)) return false;
  }
  return true;
}

}  // namespace stratum::poisson_detail
