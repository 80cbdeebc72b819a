#pragma once
/// Building blocks shared by the stratified patterns (grid, jittered,
/// N-rooks, multi-jittered, N-queens, Latin squares): a point placed inside
/// a given cell of an equal subdivision of [0, 1), a mixed-radix shape of
/// strata n_0 × … × n_{d-1}, and a counter-based Fisher–Yates shuffle.
///
/// Stratified sampling (lecture §4) only pays off if every point really lies
/// in its stratum. (cell + u) / count rounds, and for u close to 1 it can
/// round onto the next cell's boundary (1 + (1 - 2^-53) rounds to 2), so
/// `cell_coordinate` corrects the rounded value until it lies in the cell in
/// exact arithmetic *and* floor(x · count), as a caller would compute it,
/// gives the cell back.
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

namespace strata_detail {
/// x·n < c in exact arithmetic, for a double c. Rounding is monotone and c is
/// a double, so fl(x·n) < c and fl(x·n) > c already decide it (and
/// fl(x·n) < c also whenever x·n < c, which is why cell_coordinate's upper
/// test needs no more than fl(x·n) ≥ hi); only a tie needs fma(x, n, −c),
/// x·n − c rounded once, whose sign is exact (a software call without
/// hardware FMA, hence kept off the common path).
inline bool below_exactly(double x, double n, double c) noexcept {
  const double product = x * n;
  return product < c || (product == c && std::fma(x, n, -c) < 0);
}
}  // namespace strata_detail

/// (cell + offset) / count for offset in [0, 1), in the caller's precision,
/// guaranteed to satisfy cell ≤ x · count < cell + 1 exactly and
/// floor(fl(x · count)) = cell. Requires cell < count ≤ 2^53.
template <class Real = double>
[[gnu::always_inline]] inline Real cell_coordinate(std::uint64_t cell, double offset, std::uint64_t count) noexcept {
  const double n = static_cast<double>(count);
  const double lo = static_cast<double>(cell);
  const double hi = static_cast<double>(cell + 1);
  if constexpr (sizeof(Real) == sizeof(float)) {
    float x = to_unit_float((lo + offset) / n);
    const float nf = static_cast<float>(count);
    const float hif = static_cast<float>(cell + 1);
    while (static_cast<double>(x) * n >= hi || x * nf >= hif) x = std::nextafter(x, 0.0f);
    while (strata_detail::below_exactly(static_cast<double>(x), n, lo)) x = std::nextafter(x, 1.0f);
    return x;
  } else {
    double x = (lo + offset) / n;
    while (x * n >= hi) x = std::nextafter(x, 0.0);  // also ends x·n ≥ hi in exact arithmetic
    while (strata_detail::below_exactly(x, n, lo)) x = std::nextafter(x, 1.0);
    return x;
  }
}

/// A set's jitter offsets uniform01(hash64(seed, tag), index, dim) as a
/// chain: hash64 extends link by link (hash64_extend), so the set computes
/// jitter_chain(seed, tag) once and each coordinate two links (jittered_cell).
inline std::uint64_t jitter_chain(std::uint64_t seed, std::uint64_t tag) noexcept { return hash64(hash64(seed, tag)); }
/// cell_coordinate of `cell` jittered by uniform01(hash64(seed, tag), index, dim), from jitter_chain(seed, tag).
template <class Real = double>
inline Real jittered_cell(std::uint64_t cell, std::uint64_t chain, std::uint64_t index, unsigned dim,
                          std::uint64_t count) noexcept {
  return cell_coordinate<Real>(cell, bits_to_double(hash64_extend(hash64_extend(chain, index), dim)), count);
}

/// a^b, or nullopt when it exceeds 2^64 - 1.
constexpr std::optional<std::uint64_t> checked_power(std::uint64_t base, unsigned exponent) noexcept {
  std::uint64_t result = 1;
  for (unsigned k = 0; k < exponent; ++k) {
    if (base != 0 && result > ~std::uint64_t{0} / base) return std::nullopt;
    result *= base;
  }
  return result;
}

/// The largest r with r^d ≤ n (d ≥ 1), exactly.
inline std::uint64_t integer_root(std::uint64_t n, unsigned d) noexcept {
  if (d == 1 || n <= 1) return n;
  // A first guess (the loops below make it exact): a square root in hardware where d = 2, not a pow call.
  const double guess = d == 2 ? std::sqrt(static_cast<double>(n)) : std::pow(static_cast<double>(n), 1.0 / d);
  auto r = static_cast<std::uint64_t>(guess);
  while (r > 0) {
    const auto p = checked_power(r, d);
    if (p && *p <= n) break;
    --r;
  }
  for (;;) {
    const auto p = checked_power(r + 1, d);
    if (!p || *p > n) return r;
    ++r;
  }
}

/// A grid of strata n_0 × … × n_{d-1}: point (cell) index i has digit
/// (i / (n_0 ⋯ n_{j-1})) mod n_j in dimension j, dimension 0 varying fastest.
class StrataShape {
 public:
  /// Equal strata in every dimension: n must be a perfect d-th power.
  static StrataShape equal(std::uint64_t n, unsigned d) {
    require(d >= 1, "d", d, "needs at least one dimension");
    const std::uint64_t root = integer_root(n, d);
    if (checked_power(root, d) != n) {
      const std::uint64_t below = *checked_power(root, d);
      const auto above = checked_power(root + 1, d);
      throw invalid_argument(
          "n", to_message_string(n),
          "equal strata in d = " + std::to_string(d) + " need n = k^d (nearest: " + std::to_string(below) + " = " +
              std::to_string(root) + "^" + std::to_string(d) +
              (above ? ", " + std::to_string(*above) + " = " + std::to_string(root + 1) + "^" + std::to_string(d)
                     : std::string()) +
              "); or give strata=n1x...xnd with product n");
    }
    return StrataShape(std::vector<std::uint64_t>(d, root));
  }

  /// Strata per dimension, each ≥ 1; their product must fit in 64 bits.
  explicit StrataShape(std::vector<std::uint64_t> strata) : strata_(std::move(strata)) {
    require(!strata_.empty(), "strata", "(empty)", "needs one count per dimension");
    strides_.resize(strata_.size());
    std::uint64_t product = 1;
    for (std::size_t j = 0; j < strata_.size(); ++j) {
      require(strata_[j] >= 1, "strata", strata_[j], "every stratum count must be at least 1");
      require(product <= ~std::uint64_t{0} / strata_[j], "strata", "product", "the number of strata exceeds 2^64 - 1");
      strides_[j] = product;
      product *= strata_[j];
    }
    count_ = product;
  }

  unsigned dimensions() const noexcept { return static_cast<unsigned>(strata_.size()); }
  /// Total number of strata (cells).
  std::uint64_t count() const noexcept { return count_; }
  /// Strata along dimension dim.
  std::uint64_t strata(unsigned dim) const noexcept { return strata_[dim]; }
  /// The cell of stratum `index` along dimension dim.
  std::uint64_t cell(std::uint64_t index, unsigned dim) const noexcept {
    return (index / strides_[dim]) % strata_[dim];
  }

 private:
  std::vector<std::uint64_t> strata_;
  std::vector<std::uint64_t> strides_;
  std::uint64_t count_ = 1;
};

/// A uniformly random permutation of {0, …, n-1} (Fisher–Yates, Durstenfeld
/// 1964), its swaps drawn by uniform_below from (key, step), so it depends
/// only on the key: never on threads or call order.
template <class Index>
inline void random_permutation(Index* values, std::uint64_t n, std::uint64_t key) noexcept {
  for (std::uint64_t i = 0; i < n; ++i) values[i] = static_cast<Index>(i);
  for (std::uint64_t i = n; i > 1; --i) {
    const std::uint64_t j = uniform_below(i, key, i);
    const Index t = values[i - 1];
    values[i - 1] = values[j];
    values[j] = t;
  }
}

}  // namespace stratum
