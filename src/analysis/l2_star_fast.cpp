/// The L2-star pair sum P = Σ_{i,j} Π_k (1 − max(x_ik, x_jk)) in
/// O(N log^(d−1) N) for d ≤ 3, after Heinrich (1996), "Efficient algorithms
/// for computing the L2-discrepancy", Math. Comp. 65: sort the points by the
/// first coordinate, so that for i before j the first factor is 1 − x_j;
/// what remains is a dominance sum over the other coordinates.
///
/// One coordinate y (d = 2): for a fixed j,
///   Σ_{i before j} (1 − max(y_i, y_j)) = (1 − y_j)·#{i: y_i ≤ y_j} + Σ_{i: y_i > y_j} (1 − y_i),
/// a count and a sum of (1 − y_i) over the earlier points: merge sort by y
/// gives them for every j in O(N log N) (as inversion counting does).
///
/// Two coordinates y, z (d = 3): divide and conquer over the x order (CDQ).
/// For i in the left half and j in the right half, split by y:
///   y_i ≤ y_j: (1 − y_j)·[(1 − z_j)·#{z_i ≤ z_j} + Σ_{z_i > z_j} (1 − z_i)]
///   y_i > y_j: (1 − z_j)·Σ_{z_i ≤ z_j} (1 − y_i) + Σ_{z_i > z_j} (1 − y_i)(1 − z_i)
/// two sweeps over y (ascending and descending) with Fenwick trees over the z
/// ranks within the node; the halves are merged by y (and by z) as in merge sort. Ties need no care: when
/// y_i = y_j (or z_i = z_j) both branches give the same value.
/// Sums are kept in long double (64-bit mantissa) because the discrepancy is
/// a small difference of O(1) terms.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "stratum/analysis/l2_discrepancy.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {

namespace {

using real = long double;

/// Fenwick (binary indexed) tree of long-double sums over ranks 0..n−1.
class Fenwick {
 public:
  explicit Fenwick(std::size_t n) : tree_(n + 1, 0.0L) {}
  /// Adds `value` at `rank`; only the first `size` ranks are in use (a
  /// node of the divide and conquer uses ranks 0..size−1).
  void add(std::size_t rank, real value, std::size_t size) {
    for (std::size_t i = rank + 1; i <= size; i += i & (~i + 1)) tree_[i] += value;
  }
  /// Sum over ranks 0..rank.
  real prefix(std::size_t rank) const {
    real sum = 0.0L;
    for (std::size_t i = rank + 1; i > 0; i -= i & (~i + 1)) sum += tree_[i];
    return sum;
  }

 private:
  std::vector<real> tree_;
};

/// The points sorted by the first coordinate (ascending), as columns.
std::vector<std::vector<double>> sorted_by_first(const PointView& p) {
  std::vector<std::pair<double, std::size_t>> keyed(p.n);
  for (std::size_t i = 0; i < p.n; ++i) keyed[i] = {p(i, 0), i};
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::vector<double>> columns(p.d, std::vector<double>(p.n));
  for (std::size_t r = 0; r < p.n; ++r)
    for (std::size_t k = 0; k < p.d; ++k) columns[k][r] = p(keyed[r].second, k);
  return columns;
}

real pair_sum_1d(const std::vector<double>& x) {
  // The j-th smallest is the max of 2j + 1 ordered pairs (j before it, twice, and itself).
  real sum = 0.0L;
  for (std::size_t j = 0; j < x.size(); ++j) sum += static_cast<real>(2 * j + 1) * (1.0L - x[j]);
  return sum;
}

/// d = 2 by merge sort over y of the x-ordered points: when the left and right
/// halves are each sorted by y, one linear pass gives every right point its
/// count of left points below it and the sum of (1 − y) of those above.
/// Sequential memory access throughout (a Fenwick tree over 2^20 ranks spends
/// its time in cache misses).
class Merge2 {
 public:
  struct Item {
    double y, wx;  // y and 1 − x
  };
  Merge2(const std::vector<double>& x, const std::vector<double>& y) : items_(x.size()), scratch_(x.size()) {
    for (std::size_t i = 0; i < x.size(); ++i) items_[i] = {y[i], 1.0 - x[i]};
  }
  /// Σ_{i before j} (1 − x_j)(1 − max(y_i, y_j)) over the x order.
  real run() {
    solve(0, items_.size());
    return cross_;
  }

 private:
  void solve(std::size_t lo, std::size_t hi) {
    if (hi - lo < 2) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    solve(lo, mid);
    solve(mid, hi);
    real left_weight = 0.0L;
    for (std::size_t i = lo; i < mid; ++i) left_weight += 1.0L - items_[i].y;
    real below_weight = 0.0L, level = 0.0L;
    std::size_t i = lo;
    for (std::size_t j = mid; j < hi; ++j) {
      const double yj = items_[j].y;
      for (; i < mid && items_[i].y <= yj; ++i) below_weight += 1.0L - items_[i].y;
      const real below = static_cast<real>(i - lo);
      level += items_[j].wx * (below * (1.0L - yj) + (left_weight - below_weight));
    }
    cross_ += level;
    std::merge(items_.begin() + lo, items_.begin() + mid, items_.begin() + mid, items_.begin() + hi,
               scratch_.begin() + lo, [](const Item& a, const Item& b) { return a.y < b.y; });
    std::copy(scratch_.begin() + lo, scratch_.begin() + hi, items_.begin() + lo);
  }
  std::vector<Item> items_, scratch_;
  real cross_ = 0.0L;
};

real pair_sum_2d(const std::vector<double>& x, const std::vector<double>& y) {
  real diagonal = 0.0L;
  for (std::size_t j = 0; j < x.size(); ++j) diagonal += (1.0L - x[j]) * (1.0L - y[j]);
  return diagonal + 2.0L * Merge2(x, y).run();
}

/// d = 3: divide and conquer over the x order, positions [lo, hi). Each node
/// keeps its points merged by y (for the sweeps) and by z (for local z ranks,
/// so the Fenwick trees are the node's size and mostly stay in cache).
class Dominance3 {
 public:
  Dominance3(const std::vector<double>& y, const std::vector<double>& z)
      : y_(y),
        z_(z),
        by_y_(y.size()),
        by_z_(y.size()),
        scratch_(y.size()),
        local_rank_(y.size()),
        cross_(y.size(), 0.0L),
        count_(y.size()),
        weight_z_(y.size()),
        weight_y_(y.size()),
        weight_yz_(y.size()) {
    std::iota(by_y_.begin(), by_y_.end(), std::size_t{0});
    std::iota(by_z_.begin(), by_z_.end(), std::size_t{0});
  }
  /// cross[j] = Σ_{i before j in the x order} (1 − max(y_i, y_j))(1 − max(z_i, z_j)).
  std::vector<real> run() {
    solve(0, y_.size());
    return std::move(cross_);
  }

 private:
  void merge_by(std::vector<std::size_t>& order, const std::vector<double>& key, std::size_t lo, std::size_t mid,
                std::size_t hi) {
    std::merge(order.begin() + lo, order.begin() + mid, order.begin() + mid, order.begin() + hi, scratch_.begin() + lo,
               [&](std::size_t a, std::size_t b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
    std::copy(scratch_.begin() + lo, scratch_.begin() + hi, order.begin() + lo);
  }

  void solve(std::size_t lo, std::size_t hi) {
    if (hi - lo < 2) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    solve(lo, mid);
    solve(mid, hi);
    merge_by(by_y_, y_, lo, mid, hi);  // (y, position): at equal y, left points come first
    merge_by(by_z_, z_, lo, mid, hi);
    for (std::size_t t = lo; t < hi; ++t) local_rank_[by_z_[t]] = t - lo;
    real inserted = 0.0L;  // ascending y: left points with y_i ≤ y_j
    for (std::size_t t = lo; t < hi; ++t) {
      const std::size_t p = by_y_[t], r = local_rank_[p];
      const real wz = 1.0L - z_[p];
      if (p < mid) {
        count_.add(r, 1.0L, hi - lo);
        weight_z_.add(r, wz, hi - lo);
        inserted += wz;
      } else {
        const real below = count_.prefix(r);
        const real above = inserted - weight_z_.prefix(r);
        cross_[p] += (1.0L - y_[p]) * (below * wz + above);
      }
    }
    real inserted_yz = 0.0L;  // descending y: left points with y_i > y_j
    for (std::size_t t = hi; t-- > lo;) {
      const std::size_t p = by_y_[t], r = local_rank_[p];
      const real wy = 1.0L - y_[p], wz = 1.0L - z_[p];
      if (p < mid) {
        weight_y_.add(r, wy, hi - lo);
        weight_yz_.add(r, wy * wz, hi - lo);
        inserted_yz += wy * wz;
      } else {
        const real y_below = weight_y_.prefix(r);
        const real yz_above = inserted_yz - weight_yz_.prefix(r);
        cross_[p] += wz * y_below + yz_above;
      }
    }
    for (std::size_t t = lo; t < hi; ++t) {  // empty the trees' first hi − lo slots for the next node
      const std::size_t p = by_y_[t];
      if (p >= mid) continue;
      const std::size_t r = local_rank_[p];
      const real wy = 1.0L - y_[p], wz = 1.0L - z_[p];
      count_.add(r, -1.0L, hi - lo);
      weight_z_.add(r, -wz, hi - lo);
      weight_y_.add(r, -wy, hi - lo);
      weight_yz_.add(r, -wy * wz, hi - lo);
    }
  }

  const std::vector<double>& y_;
  const std::vector<double>& z_;
  std::vector<std::size_t> by_y_, by_z_, scratch_, local_rank_;
  std::vector<real> cross_;
  Fenwick count_, weight_z_, weight_y_, weight_yz_;
};

real pair_sum_3d(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z) {
  const std::vector<real> cross = Dominance3(y, z).run();
  real off_diagonal = 0.0L, diagonal = 0.0L;
  for (std::size_t j = 0; j < x.size(); ++j) {
    off_diagonal += (1.0L - x[j]) * cross[j];
    diagonal += (1.0L - x[j]) * (1.0L - y[j]) * (1.0L - z[j]);
  }
  return diagonal + 2.0L * off_diagonal;
}

}  // namespace

long double l2_star_pair_sum_fast(const PointView& points) {
  require(points.d >= 1 && points.d <= 3, "d", points.d,
          "the fast L2-star algorithm covers d <= 3; use pairwise (Warnock)");
  const auto columns = sorted_by_first(points);
  switch (points.d) {
    case 1:
      return pair_sum_1d(columns[0]);
    case 2:
      return pair_sum_2d(columns[0], columns[1]);
    default:
      return pair_sum_3d(columns[0], columns[1], columns[2]);
  }
}

}  // namespace stratum::analysis
