// Lower and upper bounds for the star discrepancy from a δ-partition
// (Thiémard 2001, "An algorithm to compute bounds for the star discrepancy",
// J. Complexity 17, 850–880).
//
// The recursion works on boxes [α,β] whose first k coordinates span
// [α_j,β_j] and whose others span [0,β_j] (k = 0 for the unit cube). A box with
// V(β) ≤ δ is finished; otherwise γ keeps α_j on the first k coordinates and
// scales the others to t·β_j with V(γ) = V(β) − δ, [γ,β] is finished, and the
// rest is the union of the boxes, for j = k … d−1,
//   B_j = [α,β] restricted to x_i ≥ γ_i (k ≤ i < j), x_j ≤ γ_j,
// each of the same form with k = j, each split the same way. For x in a
// finished box [α,β] the anchored boxes are nested, [0,α) ⊆ [0,x) ⊆ [0,β), so
//   A([0,x))/N − V(x) ≤ A([0,β))/N − V(α)   and   V(x) − A([0,x))/N ≤ V(β) − A([0,α))/N,
// which bounds D* above, while the corners themselves are values of the local
// discrepancy, which bound it below; the two differ by at most δ.
//
// Each box carries the points in [0,β), so a sub-box only tests those
// (Thiémard counts with a range tree instead; this list is simpler and
// O(points in the box) per box).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "stratum/analysis/star_discrepancy.hpp"
#include "stratum/distributed.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::analysis {
namespace {

[[noreturn]] void too_many_boxes(double delta, std::uint64_t max_boxes);

struct Bounds {
  double lower = 0;
  double upper = 0;
  std::uint64_t boxes = 0;
  void merge(const Bounds& other) {
    lower = std::max(lower, other.lower);
    upper = std::max(upper, other.upper);
    boxes += other.boxes;
  }
};

std::string short_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void too_many_boxes(double delta, std::uint64_t max_boxes) {
  throw invalid_argument("delta", short_text(delta),
                         "the delta-partition needs more than max_boxes = " + std::to_string(max_boxes) +
                             " boxes for these points; give a larger delta or a larger max_boxes");
}

double volume(const std::vector<double>& corner) {
  double v = 1;
  for (double c : corner) v *= c;
  return v;
}

/// A box [alpha, beta] of the recursion: coordinates below `fixed` span
/// [alpha_j, beta_j] with alpha_j > 0, the others [0, beta_j]; `inside` holds
/// the points in [0, beta) (A([0, alpha)) is 0 while a coordinate of alpha is 0).
struct Box {
  std::vector<double> alpha, beta;
  std::size_t fixed = 0;
  std::vector<std::uint32_t> inside;
};

struct Partition {
  const PointView& points;
  double delta;
  double inv_n;
  std::uint64_t max_boxes;
  std::atomic<std::uint64_t>& boxes_so_far;
  std::vector<std::vector<double>> sorted_axes;  ///< every coordinate value, per axis, sorted

  bool below(std::uint32_t i, const std::vector<double>& corner) const {
    for (std::size_t j = 0; j < points.d; ++j)
      if (!(points(i, j) < corner[j])) return false;
    return true;
  }

  /// The corner values of a finished box, and the two bounds. The lower
  /// bound is sharpened as in Thiémard's program: a corner whose box holds
  /// too many points is shrunk to the closed box [0, m] around them (m_j: the
  /// largest coordinate among them; same points, less volume), one with too
  /// few is grown to the next point coordinate in every axis (same points,
  /// more volume). Both are values of the local discrepancy.
  Bounds finish(const std::vector<double>& alpha, const std::vector<double>& beta,
                const std::vector<std::uint32_t>& inside) const {
    if (boxes_so_far.fetch_add(1, std::memory_order_relaxed) + 1 > max_boxes) too_many_boxes(delta, max_boxes);
    const std::size_t d = points.d;
    std::vector<double> alpha_max(d, 0.0), beta_max(d, 0.0);
    std::size_t count_alpha = 0;
    for (auto i : inside) {
      const bool in_alpha = below(i, alpha);
      count_alpha += in_alpha;
      for (std::size_t j = 0; j < d; ++j) {
        beta_max[j] = std::max(beta_max[j], points(i, j));
        if (in_alpha) alpha_max[j] = std::max(alpha_max[j], points(i, j));
      }
    }
    const double va = volume(alpha), vb = volume(beta);
    const double fa = static_cast<double>(count_alpha) * inv_n;
    const double fb = static_cast<double>(inside.size()) * inv_n;
    Bounds b;
    b.upper = std::max(vb - fa, fb - va);
    auto sharpened = [&](const std::vector<double>& corner, double fraction, double v,
                         const std::vector<double>& largest) {
      if (fraction > v) return fraction - (fraction > 0 ? volume(largest) : 0.0);
      return next_coordinate_volume(corner) - fraction;
    };
    b.lower = std::max(
        {std::abs(fa - va), std::abs(fb - vb), sharpened(alpha, fa, va, alpha_max), sharpened(beta, fb, vb, beta_max)});
    b.boxes = 1;
    return b;
  }

  /// V of the corner whose coordinate j is the smallest point coordinate ≥ corner_j (or 1).
  double next_coordinate_volume(const std::vector<double>& corner) const {
    double v = 1;
    for (std::size_t j = 0; j < points.d; ++j) {
      const auto& axis = sorted_axes[j];
      const auto it = std::lower_bound(axis.begin(), axis.end(), corner[j]);
      v *= it == axis.end() ? 1.0 : *it;
    }
    return v;
  }

  /// Finishes `box` if V(β) ≤ δ (then V(β) − V(α) ≤ δ, as V(α) = 0);
  /// otherwise finishes [γ, β] and appends the boxes B_j to `out`.
  Bounds split(const Box& box, std::vector<Box>& out) const {
    const std::size_t d = points.d;
    const double vb = volume(box.beta);
    if (vb <= delta) return finish(box.alpha, box.beta, box.inside);
    // γ_j = α_j on the fixed coordinates and t·β_j on the others, with t
    // chosen so that V(γ) = V(β) − δ (t ≤ 1: Thiémard 2001, §3).
    double fixed_alpha = 1, free_beta = 1;
    for (std::size_t j = 0; j < box.fixed; ++j) fixed_alpha *= box.alpha[j];
    for (std::size_t j = box.fixed; j < d; ++j) free_beta *= box.beta[j];
    const double t =
        std::min(1.0, std::pow((vb - delta) / (fixed_alpha * free_beta), 1.0 / static_cast<double>(d - box.fixed)));
    std::vector<double> gamma = box.alpha;
    for (std::size_t j = box.fixed; j < d; ++j) gamma[j] = t * box.beta[j];
    const Bounds result = finish(gamma, box.beta, box.inside);
    // B_j for j ≥ fixed: x_i ∈ [γ_i, β_i] for fixed ≤ i < j, x_j ∈ [0, γ_j],
    // x_i ∈ [0, β_i] above j. Every x ∈ [α,β] outside [γ,β] lies in the B_j of
    // its first coordinate j with x_j < γ_j.
    for (std::size_t j = box.fixed; j < d; ++j) {
      Box child{box.alpha, box.beta, j, {}};
      for (std::size_t i = box.fixed; i < j; ++i) child.alpha[i] = gamma[i];
      child.beta[j] = gamma[j];
      for (auto i : box.inside)
        if (points(i, j) < gamma[j]) child.inside.push_back(i);
      out.push_back(std::move(child));
    }
    return result;
  }

  /// Splits `box` and all its descendants depth-first with an explicit stack.
  Bounds run(Box box) const {
    Bounds total;
    std::vector<Box> stack;
    stack.push_back(std::move(box));
    while (!stack.empty()) {
      Box next = std::move(stack.back());
      stack.pop_back();
      total.merge(split(next, stack));
    }
    return total;
  }
};

}  // namespace

StarDiscrepancyBounds star_discrepancy_bounds(const PointView& points, double delta, std::uint64_t max_boxes,
                                              unsigned threads) {
  require(points.d >= 1, "d", points.d, "must be at least 1");
  require(points.n >= 1, "n", points.n, "needs at least 1 point");
  require(std::isfinite(delta) && delta > 0 && delta < 1, "delta", delta, "must be in (0, 1)");
  require(max_boxes >= 1, "max_boxes", max_boxes, "must be at least 1");
  std::atomic<std::uint64_t> boxes_so_far{0};
  std::vector<std::vector<double>> axes(points.d);
  for (std::size_t j = 0; j < points.d; ++j) {
    for (std::size_t i = 0; i < points.n; ++i) axes[j].push_back(points(i, j));
    std::sort(axes[j].begin(), axes[j].end());
  }
  const Partition partition{points,    delta,        1.0 / static_cast<double>(points.n),
                            max_boxes, boxes_so_far, std::move(axes)};
  std::vector<std::uint32_t> all;
  const std::vector<double> zero(points.d, 0.0), one(points.d, 1.0);
  for (std::size_t i = 0; i < points.n; ++i)
    if (partition.below(static_cast<std::uint32_t>(i), one)) all.push_back(static_cast<std::uint32_t>(i));
  // Split breadth-first until there are enough boxes to share out, then
  // finish each subtree on its own; the merge is a max and a sum, so the
  // result does not depend on the schedule.
  Bounds result;
  std::vector<Box> frontier;
  frontier.push_back(Box{zero, one, 0, std::move(all)});
  constexpr std::size_t kTasks = 64;
  while (!frontier.empty() && frontier.size() < kTasks) {
    std::vector<Box> next;
    for (const auto& box : frontier) result.merge(partition.split(box, next));
    frontier = std::move(next);
  }
  // The subtrees are a job's items: a distributed job's processes each
  // finish their share; (lower, upper, boxes) per subtree are gathered.
  std::vector<Bounds> parts(frontier.size());
  const distributed::Dealt mine =
      distributed::dealt(frontier.size());  // round-robin: neighbouring subtrees differ most
  oneapi::tbb::task_arena arena(static_cast<int>(std::max(1u, threads)));
  arena.execute([&] {
    oneapi::tbb::parallel_for(std::size_t{0}, mine.size(), [&](std::size_t j) {
      check_interrupt();
      parts[mine[j]] = partition.run(std::move(frontier[mine[j]]));
    });
  });
  if (distributed::size() > 1) {
    std::vector<double> packed(3 * parts.size());
    for (std::size_t j = 0; j < mine.size(); ++j) {
      const std::size_t i = mine[j];
      packed[3 * i] = parts[i].lower, packed[3 * i + 1] = parts[i].upper, packed[3 * i + 2] = double(parts[i].boxes);
    }
    distributed::gather_dealt(packed, parts.size());
    for (std::size_t i = 0; i < parts.size(); ++i)
      parts[i] = {packed[3 * i], packed[3 * i + 1], static_cast<std::uint64_t>(packed[3 * i + 2])};
  }
  for (const auto& part : parts) result.merge(part);
  // Each process counted only its own boxes: the budget holds for the job.
  if (result.boxes > max_boxes) too_many_boxes(delta, max_boxes);
  return {result.lower, result.upper, result.boxes};
}

}  // namespace stratum::analysis
