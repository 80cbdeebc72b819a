// Exact star discrepancy for any d ≥ 2 by enumerating the critical boxes:
// a sweep over the last coordinate's critical values c (the points' values,
// and 1) keeps the points below c — strictly for the open term
// V − A([0,y))/N, inclusively for the closed term A([0,y])/N − V — and
// recurses on the remaining coordinates with the volume factor c; at two
// coordinates the 2D scan (star_discrepancy_2d.cpp) finishes. O(N^d) time.
// Branches that cannot beat the best value so far are skipped: the open term
// of a branch is at most its volume factor, its closed term at most its count/N.
#include <algorithm>
#include <numeric>
#include <vector>

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "star_discrepancy_sweep.hpp"
#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::analysis {
namespace {

using star_detail::kNoValue;

enum class Term { open, closed };

struct Nested {
  const PointView& points;
  double inv_n;

  /// Best value of `term` over the boxes whose coordinates above `dim` are
  /// fixed (volume factor `weight`), on the points `subset` that satisfy them.
  double best(std::vector<std::uint32_t> subset, std::size_t dim, double weight, Term term, double floor) const {
    if (dim == 1) {
      std::vector<std::pair<double, double>> plane;
      plane.reserve(subset.size());
      for (auto i : subset) plane.emplace_back(points(i, 0), points(i, 1));
      std::sort(plane.begin(), plane.end());
      const auto terms = star_detail::sweep_2d(plane, weight, inv_n, 1);
      return term == Term::open ? terms.open : terms.closed;
    }
    std::sort(subset.begin(), subset.end(),
              [&](std::uint32_t a, std::uint32_t b) { return points(a, dim) < points(b, dim); });
    double result = kNoValue;
    std::size_t i = 0;
    while (i <= subset.size()) {
      // c: the next distinct value in this coordinate, or 1 after the last.
      const double c = i < subset.size() ? points(subset[i], dim) : 1.0;
      std::size_t j = i;
      while (j < subset.size() && points(subset[j], dim) == c) ++j;
      const std::size_t kept = term == Term::open ? i : j;
      const double ceiling = term == Term::open ? weight * c : static_cast<double>(kept) * inv_n;
      if (ceiling > std::max(result, floor)) {
        std::vector<std::uint32_t> below(subset.begin(), subset.begin() + static_cast<std::ptrdiff_t>(kept));
        result = std::max(result, best(std::move(below), dim - 1, weight * c, term, std::max(result, floor)));
      }
      if (i == subset.size()) break;
      i = j;
    }
    return result;
  }
};

}  // namespace

double star_discrepancy_grid(const PointView& points, unsigned threads) {
  require(points.d >= 2, "d", points.d, "the critical-box enumeration needs d >= 2");
  require(points.n >= 1, "n", points.n, "needs at least 1 point");
  const std::size_t d = points.d, top = d - 1;
  std::vector<std::uint32_t> counted;
  for (std::size_t i = 0; i < points.n; ++i) {
    bool inside = true;
    for (std::size_t j = 0; j < d; ++j) inside = inside && points(i, j) < 1.0;
    if (inside) counted.push_back(static_cast<std::uint32_t>(i));
  }
  if (d == 2) return star_discrepancy_2d(points, threads);
  std::sort(counted.begin(), counted.end(),
            [&](std::uint32_t a, std::uint32_t b) { return points(a, top) < points(b, top); });

  // The top coordinate's critical values, each an independent task for both terms.
  std::vector<std::size_t> group_starts;
  for (std::size_t i = 0; i < counted.size(); ++i)
    if (i == 0 || points(counted[i], top) != points(counted[i - 1], top)) group_starts.push_back(i);
  group_starts.push_back(counted.size());  // the corner c = 1
  const Nested nested{points, 1.0 / static_cast<double>(points.n)};
  const std::size_t tasks = group_starts.size();
  std::vector<double> open(tasks, kNoValue), closed(tasks, kNoValue);
  auto run = [&](std::size_t t) {
    check_interrupt();
    const std::size_t i = group_starts[t];
    const bool last = t + 1 == tasks;
    const double c = last ? 1.0 : points(counted[i], top);
    const std::size_t j = last ? counted.size() : group_starts[t + 1];
    open[t] = nested.best({counted.begin(), counted.begin() + static_cast<std::ptrdiff_t>(i)}, top - 1, c, Term::open,
                          kNoValue);
    if (!last)
      closed[t] = nested.best({counted.begin(), counted.begin() + static_cast<std::ptrdiff_t>(j)}, top - 1, c,
                              Term::closed, kNoValue);
  };
  oneapi::tbb::task_arena arena(static_cast<int>(std::max(1u, threads)));
  arena.execute([&] { oneapi::tbb::parallel_for(std::size_t{0}, tasks, run); });
  double result = 0;
  for (std::size_t t = 0; t < tasks; ++t) result = std::max({result, open[t], closed[t]});
  return result;
}

}  // namespace stratum::analysis
