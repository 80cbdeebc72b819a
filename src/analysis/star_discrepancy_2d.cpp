// Exact 2D star discrepancy by a sweep in x with a sorted list of y's.
//
// At a corner abscissa a (a point's x, or 1) let y_0 ≤ … ≤ y_{m−1} be the
// y's of the points left of it, V_k = w·a·y_k and K_k = k/N. Then
//   open   (V − A/N over [0,a)×[0,y_k)):  max_k V_k − K_k, and w·a − K_m at b = 1;
//   closed (A/N − V over [0,a]×[0,y_k]):  max_k K_{k+1} − V_k  (the list now
//          holding the points with x ≤ a).
// With ties in y the extreme index of each run of equal y's wins the max, which
// is the true count; the other indices give values below it, never above.
// One pass over the list gives both terms. Every value is computed as
// fl(fl(fl(w·a)·y) − K_k) or fl(K_k − fl(fl(w·a)·y)) with K_k = fl(k·(1/N)),
// without fused multiply-adds (contraction is off in this file), so that the
// other exact methods (star_discrepancy_dem.cpp), which evaluate the same
// expressions on the same boxes, return the same double.
// Total O(N²) arithmetic on arrays that stay in cache; the insertions are
// memmoves. Slabs of the x-sweep run in parallel, each starting from its own
// sorted copy of the y's to its left (Niederreiter 1972's critical boxes;
// the sweep formulation follows Bundschuh & Zhu 1993, "A method for exact
// calculation of the discrepancy of low-dimensional finite point sets I").
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "star_discrepancy_sweep.hpp"
#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

// Products and differences rounded one at a time (see the top of the file).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#elif defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

namespace stratum::analysis {
namespace star_detail {
namespace {

#if defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
#define STRATUM_STAR_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define STRATUM_STAR_CLONES
#endif

using vec8 = double __attribute__((vector_size(64)));

/// The two one-sided maxima of one scan.
struct Extremes {
  double open = kNoValue;
  double closed = kNoValue;
};

/// Over k in [begin, end), with V_k = slope·ys[k]:
///   open = max V_k − counts[k],  closed = max counts[k + shift] − V_k.
STRATUM_STAR_CLONES Extremes scan_range(const double* ys, std::size_t begin, std::size_t end, double slope,
                                        const double* counts, std::size_t shift) {
  Extremes e;
  std::size_t k = begin;
  if (end - begin >= 8) {
    vec8 vopen = vec8{} + kNoValue, vclosed = vec8{} + kNoValue;
    const vec8 s = vec8{} + slope;
    for (; k + 8 <= end; k += 8) {
      vec8 y, below, through;
      std::memcpy(&y, ys + k, sizeof y);
      std::memcpy(&below, counts + k, sizeof below);
      std::memcpy(&through, counts + k + shift, sizeof through);
      const vec8 v = s * y;
      const vec8 o = v - below, c = through - v;
      vopen = o > vopen ? o : vopen;
      vclosed = c > vclosed ? c : vclosed;
    }
    for (int lane = 0; lane < 8; ++lane) {
      e.open = std::max(e.open, vopen[lane]);
      e.closed = std::max(e.closed, vclosed[lane]);
    }
  }
  for (; k < end; ++k) {
    const double v = slope * ys[k];
    e.open = std::max(e.open, v - counts[k]);
    e.closed = std::max(e.closed, counts[k + shift] - v);
  }
  return e;
}

using Points = std::vector<std::pair<double, double>>;

/// Sweeps the groups of equal x [group_begin, group_end), starting from the
/// y's of every point before the first group; `final_corner` adds a = 1.
/// counts[k] = fl(k/N) for k ≤ points.size() + 1.
SweepTerms sweep_groups(const Points& points, const std::vector<std::size_t>& starts, std::size_t group_begin,
                        std::size_t group_end, bool final_corner, double weight, const double* counts) {
  const std::size_t first = group_begin < starts.size() ? starts[group_begin] : points.size();
  std::vector<double> ys;
  ys.reserve(points.size());
  for (std::size_t i = 0; i < first; ++i) ys.push_back(points[i].second);
  std::sort(ys.begin(), ys.end());

  SweepTerms r;
  for (std::size_t g = group_begin; g < group_end; ++g) {
    const std::size_t i0 = starts[g];
    const std::size_t i1 = g + 1 < starts.size() ? starts[g + 1] : points.size();
    const double slope = weight * points[i0].first;
    const std::size_t m = ys.size();
    r.open = std::max(r.open, slope - counts[m]);  // b = 1
    if (i1 - i0 == 1) {
      // One new point: the closed scan over the list with it inserted at q is
      // the scan of the old list with the counts above q shifted by one.
      const double y = points[i0].second;
      const auto q = static_cast<std::size_t>(std::upper_bound(ys.begin(), ys.end(), y) - ys.begin());
      const Extremes below = scan_range(ys.data(), 0, q, slope, counts, 1);
      const Extremes above = scan_range(ys.data(), q, m, slope, counts, 2);
      r.open = std::max({r.open, below.open, above.open});
      r.closed = std::max({r.closed, below.closed, counts[q + 1] - slope * y, above.closed});
      ys.insert(ys.begin() + static_cast<std::ptrdiff_t>(q), y);
    } else {
      r.open = std::max(r.open, scan_range(ys.data(), 0, m, slope, counts, 1).open);
      for (std::size_t i = i0; i < i1; ++i)
        ys.insert(std::upper_bound(ys.begin(), ys.end(), points[i].second), points[i].second);
      r.closed = std::max(r.closed, scan_range(ys.data(), 0, ys.size(), slope, counts, 1).closed);
    }
  }
  if (final_corner) {
    const Extremes e = scan_range(ys.data(), 0, ys.size(), weight, counts, 1);
    r.open = std::max({r.open, e.open, weight - counts[ys.size()]});
  }
  return r;
}

}  // namespace

SweepTerms sweep_2d(const Points& points, double weight, double inv_n, unsigned threads) {
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (i == 0 || points[i].first != points[i - 1].first) starts.push_back(i);

  // Slab c ends near point index m·sqrt((c+1)/C): the scan work up to index i
  // grows as i², so the slabs get equal work.
  constexpr std::size_t kMinPointsToSplit = 4096;
  const std::size_t chunks =
      threads <= 1 || points.size() < kMinPointsToSplit ? 1 : std::min<std::size_t>(8 * threads, 256);
  std::vector<std::size_t> bounds{0};
  for (std::size_t c = 1; c < chunks; ++c) {
    const auto target = static_cast<std::size_t>(static_cast<double>(points.size()) *
                                                 std::sqrt(static_cast<double>(c) / static_cast<double>(chunks)));
    const auto g = static_cast<std::size_t>(std::lower_bound(starts.begin(), starts.end(), target) - starts.begin());
    bounds.push_back(std::max(g, bounds.back()));
  }
  bounds.push_back(starts.size());

  // counts[k] = fl(k/N), shared by every slab (indices up to m + 1).
  std::vector<double> counts(points.size() + 2);
  for (std::size_t k = 0; k < counts.size(); ++k) counts[k] = static_cast<double>(k) * inv_n;

  std::vector<SweepTerms> parts(chunks);
  auto run = [&](std::size_t c) {
    check_interrupt();
    parts[c] = sweep_groups(points, starts, bounds[c], bounds[c + 1], c + 1 == chunks, weight, counts.data());
  };
  if (chunks == 1) {
    run(0);
  } else {
    oneapi::tbb::task_arena arena(static_cast<int>(threads));
    arena.execute([&] { oneapi::tbb::parallel_for(std::size_t{0}, chunks, run); });
  }
  SweepTerms total;
  for (const auto& part : parts) {
    total.open = std::max(total.open, part.open);
    total.closed = std::max(total.closed, part.closed);
  }
  return total;
}

}  // namespace star_detail

double star_discrepancy_2d(const PointView& points, unsigned threads) {
  require(points.d == 2, "d", points.d, "the 2D sweep needs d = 2");
  require(points.n >= 1, "n", points.n, "needs at least 1 point");
  std::vector<std::pair<double, double>> counted;
  counted.reserve(points.n);
  for (std::size_t i = 0; i < points.n; ++i)
    if (points(i, 0) < 1.0 && points(i, 1) < 1.0) counted.emplace_back(points(i, 0), points(i, 1));
  std::sort(counted.begin(), counted.end());
  const auto terms = star_detail::sweep_2d(counted, 1.0, 1.0 / static_cast<double>(points.n), threads);
  return std::max({terms.open, terms.closed, 0.0});
}

}  // namespace stratum::analysis
