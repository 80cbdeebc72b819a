// Exact star discrepancy for d ≥ 2 by the cell decomposition of Dobkin,
// Eppstein, Mitchell 1996 ("Computing the discrepancy with applications to
// supersampling patterns", ACM TOG 15(4), §4), as described by Doerr,
// Gnewuch, Wahlström 2014 ("Calculation of discrepancy measures and
// applications", §3.2.2).
//
// The space of upper corners y ∈ [0,1]^d is cut into cells Π_j [l_j, u_j],
// one coordinate at a time. In a cell every point is, relative to the cell,
//   - "counted": p_j ≤ l_j in every coordinate (inside every box of the cell),
//   - "partial in j": l_j < p_j < u_j in exactly one coordinate j and p_i ≤ l_i
//     in the others, or
//   - "out": p_j ≥ u_j in some coordinate j (in no box of the cell).
// A point is never strictly inside the cell in two coordinates: the cuts of
// coordinate c include the c-th coordinate of every point already partial in
// an earlier coordinate. The other cuts fall every `block` ≈ √N counted points,
// so each cell has O(d√N) partial points and there are O((d√N)^d) =
// O(N^{d/2}) cells.
//
// Inside a cell the count of a corner is separable: counted + Σ_j (partial
// points of coordinate j below y_j). For each coordinate j and each k, the
// biggest y_j with k partial points strictly below it is the (k+1)-th partial
// coordinate (or u_j), and the smallest y_j with k of them in [0, y_j] is the
// k-th one (or l_j). A knapsack over the coordinates then gives, for every
// count t, the biggest volume (open boxes: V − A/N) and the smallest volume
// (closed boxes: A/N − V) in O(M²) for M partial points: O(N) per cell, so
// O(N^{1+d/2}) in all. A cell whose bound max(V(u) − counted/N,
// (counted + M)/N − V(l)) cannot beat the best value so far is skipped, and
// the corner values V(u) − (counted + M)/N and counted/N − V(l), attained,
// raise the best value before the knapsack runs (the pruning of Wahlström's
// implementation of the method, described by Doerr, Gnewuch, Wahlström).
//
// Ties: a configuration's claimed count is ≤ the true count of its closed box
// and ≥ that of its open box, so it never overstates the local discrepancy;
// the tight configuration (the extreme index of each run of ties) is among
// those tried.
//
// Rounding: every volume is the product fl(…fl(fl(y_{d−1}·y_{d−2})·y_{d−3})…·y_0)·y_1)
// in this order, and every value fl(V − K) or fl(K − V) with K = fl(k·(1/N)),
// exactly as in the critical-box enumeration (star_discrepancy_grid.cpp and the
// 2D sweep). Rounding is monotone, so the knapsack's best partial product is the
// best rounded product, and the two methods return the same double.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <oneapi/tbb/blocked_range.h>
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
namespace {

using star_detail::kNoValue;
using Index = std::uint32_t;

class DemSearch {
 public:
  /// x: the counted points (every coordinate < 1), row-major n × d; total: N.
  DemSearch(const std::vector<double>& x, std::size_t n, std::size_t d, std::size_t total, double block_scale)
      : x_(x), n_(n), d_(d), counts_(n + 1) {
    const double inv_n = 1.0 / static_cast<double>(total);
    for (std::size_t k = 0; k <= n; ++k) counts_[k] = static_cast<double>(k) * inv_n;
    const double block = std::min(block_scale * std::sqrt(static_cast<double>(n)), static_cast<double>(n) + 1);
    block_ = std::max<std::size_t>(1, static_cast<std::size_t>(block));
    // The enumeration's product order: y_{d−1}, y_{d−2}, …, y_2, y_0, y_1.
    for (std::size_t j = d; j-- > 2;) order_.push_back(j);
    order_.push_back(0);
    order_.push_back(1);
  }

  double run(unsigned threads) {
    std::vector<Index> all(n_);
    for (std::size_t i = 0; i < n_; ++i) all[i] = static_cast<Index>(i);
    std::sort(all.begin(), all.end(), [&](Index a, Index b) { return at(a, 0) < at(b, 0); });
    Box box(d_);
    oneapi::tbb::task_arena arena(static_cast<int>(std::max(1u, threads)));
    arena.execute([&] { explore(0, all, Groups(d_), box, true); });
    return std::max(best_.load(), 0.0);
  }

 private:
  struct Interval {
    double lower = 0, upper = 1;
  };
  using Box = std::vector<Interval>;
  /// groups[j]: the points partial in coordinate j, sorted by coordinate j.
  using Groups = std::vector<std::vector<Index>>;

  double at(Index i, std::size_t j) const { return x_[static_cast<std::size_t>(i) * d_ + j]; }

  /// The cuts of coordinate c: every partial point's c-th coordinate and every
  /// block-th counted point's, then 1; all > 0, increasing.
  std::vector<double> cuts(std::size_t c, const std::vector<Index>& inside, const Groups& groups) const {
    std::vector<double> result;
    for (std::size_t j = 0; j < c; ++j)
      for (Index i : groups[j]) result.push_back(at(i, c));
    for (std::size_t k = block_; k < inside.size(); k += block_) result.push_back(at(inside[k], c));
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    result.erase(result.begin(), std::upper_bound(result.begin(), result.end(), 0.0));
    if (result.empty() || result.back() < 1.0) result.push_back(1.0);
    return result;
  }

  /// Splits coordinate c into cells; `inside` are the points counted so far,
  /// sorted by coordinate c.
  void explore(std::size_t c, const std::vector<Index>& inside, const Groups& groups, const Box& box, bool parallel) {
    const std::vector<double> cut = cuts(c, inside, groups);
    const auto by_next = [&](Index a, Index b) { return at(a, c + 1) < at(b, c + 1); };
    // Cells [k_begin, k_end) in increasing order: the counted points of a cell
    // are a prefix of `inside` that only grows, so the children's input (that
    // prefix sorted by coordinate c + 1) is kept by merging in each new batch.
    auto run = [&](std::size_t k_begin, std::size_t k_end) {
      Scratch scratch;
      std::vector<Index> prefix, batch, merged;
      std::size_t have = 0;
      for (std::size_t k = k_begin; k < k_end; ++k) {
        const double lower = k == 0 ? 0.0 : cut[k - 1], upper = cut[k];
        const auto below = [&](Index i, double v) { return at(i, c) < v; };
        const auto not_above = [&](double v, Index i) { return v < at(i, c); };
        // inside[0, counted) ≤ lower < inside[counted, strict) < upper.
        const auto counted =
            static_cast<std::size_t>(std::upper_bound(inside.begin(), inside.end(), lower, not_above) - inside.begin());
        const auto strict = static_cast<std::size_t>(
            std::lower_bound(inside.begin() + static_cast<std::ptrdiff_t>(counted), inside.end(), upper, below) -
            inside.begin());
        Box sub = box;
        sub[c] = {lower, upper};
        if (c + 1 == d_) {
          evaluate(inside, counted, strict, groups, sub, scratch);
          continue;
        }
        if (counted > have) {
          batch.assign(inside.begin() + static_cast<std::ptrdiff_t>(have),
                       inside.begin() + static_cast<std::ptrdiff_t>(counted));
          std::sort(batch.begin(), batch.end(), by_next);
          merged.resize(prefix.size() + batch.size());
          std::merge(prefix.begin(), prefix.end(), batch.begin(), batch.end(), merged.begin(), by_next);
          prefix.swap(merged);
          have = counted;
        }
        Groups next(d_);
        for (std::size_t j = 0; j < c; ++j)
          for (Index i : groups[j])
            if (at(i, c) <= lower) next[j].push_back(i);
        next[c].assign(inside.begin() + static_cast<std::ptrdiff_t>(counted),
                       inside.begin() + static_cast<std::ptrdiff_t>(strict));
        explore(c + 1, prefix, next, sub, false);
      }
    };
    if (parallel) {
      oneapi::tbb::parallel_for(oneapi::tbb::blocked_range<std::size_t>(0, cut.size(), 4),
                                [&](const oneapi::tbb::blocked_range<std::size_t>& r) {
                                  check_interrupt();
                                  run(r.begin(), r.end());
                                });
    } else {
      run(0, cut.size());
    }
  }

  struct Scratch {
    std::vector<std::vector<double>> partial;  // per coordinate, sorted
    std::vector<double> big, small, next_big, next_small;
  };

  /// One cell of the last coordinate (c = d − 1): the knapsack over coordinates.
  void evaluate(const std::vector<Index>& inside, std::size_t counted, std::size_t strict, const Groups& groups,
                const Box& box, Scratch& s) {
    const std::size_t last = d_ - 1;
    s.partial.resize(d_);
    std::size_t total = 0;
    for (std::size_t j = 0; j < last; ++j) {
      s.partial[j].clear();
      for (Index i : groups[j])
        if (at(i, last) <= box[last].lower) s.partial[j].push_back(at(i, j));
      total += s.partial[j].size();
    }
    s.partial[last].clear();
    for (std::size_t k = counted; k < strict; ++k) s.partial[last].push_back(at(inside[k], last));
    total += s.partial[last].size();

    // The corners u (every partial point inside) and l (only the counted
    // ones) are boxes of this cell: their values are attained. The biggest box
    // counts at least `counted`, the smallest at most counted + total: bounds.
    double upper_volume = box[order_[0]].upper, lower_volume = box[order_[0]].lower;
    for (std::size_t r = 1; r < d_; ++r) {
      upper_volume = upper_volume * box[order_[r]].upper;
      lower_volume = lower_volume * box[order_[r]].lower;
    }
    raise_best(std::max(upper_volume - counts_[counted + total], counts_[counted] - lower_volume));
    const double seen = best_.load(std::memory_order_relaxed);
    const bool open = upper_volume - counts_[counted] > seen;
    const bool closed = counts_[counted + total] - lower_volume > seen;
    if (!open && !closed) return;

    // big[t]: the biggest volume of an open box with t partial points below
    // it; small[t]: the smallest of a closed box holding t of them.
    const std::size_t first = order_[0];
    const auto& p0 = s.partial[first];
    s.big.clear();
    s.small.clear();
    if (open) {
      s.big.assign(p0.begin(), p0.end());
      s.big.push_back(box[first].upper);
    }
    if (closed) {
      s.small.assign(1, box[first].lower);
      s.small.insert(s.small.end(), p0.begin(), p0.end());
    }
    for (std::size_t r = 1; r < d_; ++r) {
      const std::size_t j = order_[r];
      const auto& p = s.partial[j];
      if (open) {
        s.next_big.assign(s.big.size() + p.size(), kNoValue);
        for (std::size_t k = 0; k <= p.size(); ++k) {
          const double wide = k < p.size() ? p[k] : box[j].upper;
          double* out = s.next_big.data() + k;
          const double* in = s.big.data();
          for (std::size_t t = 0; t < s.big.size(); ++t) out[t] = std::max(out[t], in[t] * wide);
        }
        s.big.swap(s.next_big);
      }
      if (closed) {
        s.next_small.assign(s.small.size() + p.size(), std::numeric_limits<double>::infinity());
        for (std::size_t k = 0; k <= p.size(); ++k) {
          const double narrow = k == 0 ? box[j].lower : p[k - 1];
          double* out = s.next_small.data() + k;
          const double* in = s.small.data();
          for (std::size_t t = 0; t < s.small.size(); ++t) out[t] = std::min(out[t], in[t] * narrow);
        }
        s.small.swap(s.next_small);
      }
    }
    double value = kNoValue;
    for (std::size_t t = 0; t < s.big.size(); ++t) value = std::max(value, s.big[t] - counts_[counted + t]);
    for (std::size_t t = 0; t < s.small.size(); ++t) value = std::max(value, counts_[counted + t] - s.small[t]);
    raise_best(value);
  }

  void raise_best(double value) {
    double seen = best_.load(std::memory_order_relaxed);
    while (value > seen && !best_.compare_exchange_weak(seen, value, std::memory_order_relaxed)) {
    }
  }

  const std::vector<double>& x_;
  std::size_t n_, d_;
  std::vector<double> counts_;  // counts_[k] = fl(k/N)
  std::size_t block_ = 1;
  std::vector<std::size_t> order_;
  std::atomic<double> best_{kNoValue};
};

}  // namespace

double star_discrepancy_dem(const PointView& points, unsigned threads, double block_scale) {
  require(points.d >= 2, "d", points.d, "the DEM method needs d >= 2");
  require(points.n >= 1, "n", points.n, "needs at least 1 point");
  require(block_scale > 0 && std::isfinite(block_scale), "block_scale", block_scale, "must be > 0");
  // Points with a coordinate equal to 1 lie in no box [0,y), y ≤ 1: they count in N only.
  std::vector<double> counted;
  std::size_t n = 0;
  for (std::size_t i = 0; i < points.n; ++i) {
    bool inside = true;
    for (std::size_t j = 0; j < points.d; ++j) inside = inside && points(i, j) < 1.0;
    if (!inside) continue;
    for (std::size_t j = 0; j < points.d; ++j) counted.push_back(points(i, j));
    ++n;
  }
  require(n < std::numeric_limits<Index>::max(), "n", points.n, "too many points");
  DemSearch search(counted, n, points.d, points.n, block_scale);
  return search.run(threads);
}

}  // namespace stratum::analysis
