/// The O(d N²) L2 discrepancies (Warnock 1972 for L2-star; Hickernell 1998
/// for CD and WD; Zhou, Fang, Ning 2013 for MD) and scipy's O(N d) update of
/// the centered discrepancy. Formulas in l2_discrepancy.hpp.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

#include "stratum/analysis/l2_discrepancy.hpp"
#include "stratum/distributed.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"
#include "stratum/memory.hpp"

namespace stratum::analysis {

namespace {

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define STRATUM_L2_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define STRATUM_L2_CLONES
#endif

/// The coordinates column by column (x[k * n + i]) and, for CD and MD, the
/// distances to the centre c[k * n + i] = |x_ik − ½|: the inner loop over j
/// then reads contiguous memory and vectorizes.
struct Columns {
  std::size_t n = 0, d = 0;
  std::vector<double> x, c;
};

Columns to_columns(const PointView& p) {
  Columns cols{p.n, p.d, std::vector<double>(p.n * p.d), std::vector<double>(p.n * p.d)};
  for (std::size_t i = 0; i < p.n; ++i)
    for (std::size_t k = 0; k < p.d; ++k) {
      cols.x[k * p.n + i] = p(i, k);
      cols.c[k * p.n + i] = std::abs(p(i, k) - 0.5);
    }
  return cols;
}

// The pair kernels g(a, b) of l2_discrepancy.hpp, with ca = |a − ½|, cb = |b − ½|.
struct StarPair {
  static double g(double a, double, double b, double) { return 1.0 - std::max(a, b); }
};
struct CenteredPair {
  static double g(double a, double ca, double b, double cb) {
    return 1.0 + 0.5 * ca + 0.5 * cb - 0.5 * std::abs(a - b);
  }
};
struct WrapPair {
  static double g(double a, double, double b, double) {
    const double t = std::abs(a - b);
    return 1.5 - t + t * t;
  }
};
struct MixturePair {
  static double g(double a, double ca, double b, double cb) {
    const double t = a - b;
    return 1.875 - 0.25 * ca - 0.25 * cb - 0.75 * std::abs(t) + 0.5 * t * t;
  }
};

constexpr std::size_t kRowBlock = 32;     // rows per task (fixed: the reduction order never depends on threads)
constexpr std::size_t kColumnTile = 256;  // partners kept in L1 while the block's rows pass over them

/// The row blocks in the order their sums are kept: 0, B−1, 1, B−2, … A
/// contiguous run of this order pairs long blocks (few rows above them)
/// with short ones, so equal shares of it are nearly equal work.
std::vector<std::size_t> deal_blocks(std::size_t blocks) {
  std::vector<std::size_t> order;
  order.reserve(blocks);
  for (std::size_t low = 0, high = blocks; low < high;) {
    order.push_back(low++);
    if (low < high) order.push_back(--high);
  }
  return order;
}

/// Σ_{i in [row_begin, row_end)} Σ_{j > i} Π_k g(x_ik, x_jk), tiled over j.
template <class Pair>
[[gnu::always_inline]] inline double upper_pairs(const Columns& cols, std::size_t row_begin, std::size_t row_end) {
  const std::size_t n = cols.n, d = cols.d;
  alignas(64) double product[kColumnTile];
  double block_sum = 0.0;
  for (std::size_t tile = row_begin + 1; tile < n; tile += kColumnTile) {
    const std::size_t tile_end = std::min(n, tile + kColumnTile);
    for (std::size_t i = row_begin; i < row_end && i + 1 < tile_end; ++i) {
      const std::size_t begin = std::max(tile, i + 1), count = tile_end - begin;
      for (std::size_t t = 0; t < count; ++t) product[t] = 1.0;
      for (std::size_t k = 0; k < d; ++k) {
        const double a = cols.x[k * n + i], ca = cols.c[k * n + i];
        const double* xb = cols.x.data() + k * n + begin;
        const double* cb = cols.c.data() + k * n + begin;
        for (std::size_t t = 0; t < count; ++t) product[t] *= Pair::g(a, ca, xb[t], cb[t]);
      }
      std::array<double, 8> lanes{};  // independent partial sums: vectorizable without reassociation
      std::size_t t = 0;
      for (; t + 8 <= count; t += 8)
        for (std::size_t l = 0; l < 8; ++l) lanes[l] += product[t + l];
      for (; t < count; ++t) lanes[0] += product[t];
      block_sum += ((lanes[0] + lanes[4]) + (lanes[1] + lanes[5])) + ((lanes[2] + lanes[6]) + (lanes[3] + lanes[7]));
    }
  }
  return block_sum;
}

// One compiled (and cloned for AVX2 / AVX-512) copy per kernel.
STRATUM_L2_CLONES double upper_pairs_star(const Columns& c, std::size_t b, std::size_t e) {
  return upper_pairs<StarPair>(c, b, e);
}
STRATUM_L2_CLONES double upper_pairs_centered(const Columns& c, std::size_t b, std::size_t e) {
  return upper_pairs<CenteredPair>(c, b, e);
}
STRATUM_L2_CLONES double upper_pairs_wrap(const Columns& c, std::size_t b, std::size_t e) {
  return upper_pairs<WrapPair>(c, b, e);
}
STRATUM_L2_CLONES double upper_pairs_mixture(const Columns& c, std::size_t b, std::size_t e) {
  return upper_pairs<MixturePair>(c, b, e);
}
template <class Pair>
double upper_pairs_dispatch(const Columns& c, std::size_t b, std::size_t e) {
  if constexpr (std::is_same_v<Pair, StarPair>) return upper_pairs_star(c, b, e);
  if constexpr (std::is_same_v<Pair, CenteredPair>) return upper_pairs_centered(c, b, e);
  if constexpr (std::is_same_v<Pair, WrapPair>) return upper_pairs_wrap(c, b, e);
  if constexpr (std::is_same_v<Pair, MixturePair>) return upper_pairs_mixture(c, b, e);
}

/// Σ_{i,j} Π_k g(x_ik, x_jk) = Σ_i g(x_i, x_i) + 2 Σ_{i<j}, with the row blocks'
/// sums added in block order. The blocks are a job's items: each process of
/// a distributed job computes its share (stratum/distributed.hpp), so the
/// sum is the same, bit for bit, on any number of processes.
template <class Pair>
long double pair_sum(const Columns& cols, unsigned threads) {
  const std::size_t n = cols.n, blocks = (n + kRowBlock - 1) / kRowBlock;
  std::vector<double> partial(blocks, 0.0);
  // Block b costs ∝ n − 32b, so the shares are cut from the dealt order
  // (equal work per process); the sum below still runs in block order.
  const std::vector<std::size_t> order = deal_blocks(blocks);
  const distributed::Share mine = distributed::share(blocks);
  auto block = [&](std::size_t slot) {
    check_interrupt();
    const std::size_t b = order[slot];
    partial[slot] = upper_pairs_dispatch<Pair>(cols, b * kRowBlock, std::min(n, (b + 1) * kRowBlock));
  };
  if (threads <= 1) {
    for (std::size_t slot = mine.begin; slot < mine.end; ++slot) block(slot);
  } else {
    tbb::task_arena arena(static_cast<int>(threads));
    arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(mine.begin, mine.end, 1),
          [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t slot = r.begin(); slot < r.end(); ++slot) block(slot);
          },
          tbb::simple_partitioner());
    });
  }
  distributed::gather_shares(partial, blocks);
  std::vector<std::size_t> slot_of(blocks);
  for (std::size_t slot = 0; slot < blocks; ++slot) slot_of[order[slot]] = slot;
  long double upper = 0.0L;
  for (std::size_t b = 0; b < blocks; ++b) upper += partial[slot_of[b]];
  long double diagonal = 0.0L;
  for (std::size_t i = 0; i < n; ++i) {
    double product = 1.0;
    for (std::size_t k = 0; k < cols.d; ++k) {
      const double a = cols.x[k * n + i], ca = cols.c[k * n + i];
      product *= Pair::g(a, ca, a, ca);
    }
    diagonal += product;
  }
  return diagonal + 2.0L * upper;
}

/// Σ_i Π_k h(x_ik) for the single sums of L2-star, CD and MD, in long double
/// throughout: O(N d) work, and it keeps rounding that is biased on
/// structured (e.g. dyadic) sets out of a result that is a small difference.
template <class Single>
long double single_sum(const PointView& p, Single h) {
  long double sum = 0.0L, compensation = 0.0L;  // Neumaier's compensated sum
  for (std::size_t i = 0; i < p.n; ++i) {
    long double product = 1.0L;
    for (std::size_t k = 0; k < p.d; ++k) product *= h(static_cast<long double>(p(i, k)));
    const long double t = sum + product;
    compensation += std::abs(sum) >= std::abs(product) ? (sum - t) + product : (product - t) + sum;
    sum = t;
  }
  return sum + compensation;
}

}  // namespace

double l2_working_bytes(L2Kind kind, std::size_t n, std::size_t d, const L2Options& options) {
  const double points = double(n), coordinates = double(n) * double(d);
  const bool fast = kind == L2Kind::star && d <= 3 && options.algorithm != L2Algorithm::pairwise;
  if (!fast) return 2 * sizeof(double) * coordinates;  // to_columns: x and its complement, column-major
  // sorted_by_first: (key, index) pairs while the sorted columns are filled;
  // then d = 2: two merge buffers of (y, 1 − x); d = 3: four index arrays,
  // the cross sums and four Fenwick trees of long doubles.
  const double sorting = 16 * points + sizeof(double) * coordinates;
  const double merging = sizeof(double) * coordinates + (d == 2 ? 32 * points : d == 3 ? 112 * points : 0);
  return std::max(sorting, merging);
}

double l2_discrepancy_squared(L2Kind kind, const PointView& points, const L2Options& options) {
  require(points.n >= 1, "n", points.n, "an L2 discrepancy needs at least 1 point");
  require(points.d >= 1, "d", points.d, "must be at least 1");
  require_memory(l2_working_bytes(kind, points.n, points.d, options),
                 "the L2 discrepancy of " + std::to_string(points.n) + " x " + std::to_string(points.d) +
                     " points (its copies of the points and buffers)");
  const bool fast_possible = kind == L2Kind::star && points.d <= 3;
  if (options.algorithm == L2Algorithm::fast && !fast_possible)
    throw invalid_argument("algorithm", "fast",
                           kind == L2Kind::star ? "the fast L2-star algorithm covers d <= 3; use pairwise (Warnock)"
                                                : "only L2-star has a fast algorithm; use pairwise");
  const long double n = static_cast<long double>(points.n) + (options.iterative ? 1 : 0);
  const long double d = static_cast<long double>(points.d);
  const bool fast = fast_possible && options.algorithm != L2Algorithm::pairwise;
  long double pairs = 0.0L, single = 0.0L, constant = 0.0L, single_weight = 0.0L;
  switch (kind) {
    case L2Kind::star:
      pairs = fast ? l2_star_pair_sum_fast(points) : pair_sum<StarPair>(to_columns(points), options.threads);
      single = single_sum(points, [](long double x) { return 1.0L - x * x; });
      constant = std::pow(3.0L, -d);
      single_weight = std::pow(2.0L, 1.0L - d);
      break;
    case L2Kind::centered:
      pairs = pair_sum<CenteredPair>(to_columns(points), options.threads);
      single = single_sum(points, [](long double x) {
        const long double c = std::abs(x - 0.5L);
        return 1.0L + 0.5L * c - 0.5L * c * c;
      });
      constant = std::pow(13.0L / 12.0L, d);
      single_weight = 2.0L;
      break;
    case L2Kind::wrap_around:
      pairs = pair_sum<WrapPair>(to_columns(points), options.threads);
      constant = -std::pow(4.0L / 3.0L, d);
      break;
    case L2Kind::mixture:
      pairs = pair_sum<MixturePair>(to_columns(points), options.threads);
      single = single_sum(points, [](long double x) {
        const long double c = std::abs(x - 0.5L);
        return 5.0L / 3.0L - 0.25L * c - 0.25L * c * c;
      });
      constant = std::pow(19.0L / 12.0L, d);
      single_weight = 2.0L;
      break;
  }
  return static_cast<double>(constant - single_weight / n * single + pairs / (n * n));
}

double l2_centered_update(const double* x_new, const PointView& sample, double initial) {
  // Appending x to n − 1 points normalized by n (iterative = true) adds its
  // single term, its n − 1 cross terms (twice) and its diagonal term.
  const double n = static_cast<double>(sample.n) + 1.0;
  double single = 1.0, diagonal = 1.0;
  for (std::size_t k = 0; k < sample.d; ++k) {
    const double c = std::abs(x_new[k] - 0.5);
    single *= 1.0 + 0.5 * c - 0.5 * c * c;
    diagonal *= 1.0 + c;
  }
  double cross = 0.0;
  for (std::size_t i = 0; i < sample.n; ++i) {
    double product = 1.0;
    for (std::size_t k = 0; k < sample.d; ++k)
      product *= CenteredPair::g(x_new[k], std::abs(x_new[k] - 0.5), sample(i, k), std::abs(sample(i, k) - 0.5));
    cross += product;
  }
  return initial - 2.0 / n * single + 2.0 / (n * n) * cross + diagonal / (n * n);
}

}  // namespace stratum::analysis
