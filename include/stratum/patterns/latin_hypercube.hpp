#pragma once
/// N-rooks / Latin hypercube sampling: n points in [0, 1)^d with exactly one
/// point in each of the n equal intervals of every coordinate, built from one
/// independent random permutation per dimension (McKay, Beckman, Conover
/// 1979, "A comparison of three methods for selecting values of input
/// variables in the analysis of output from a computer code"; Shirley 1991,
/// "Discrepancy as a quality measure for sample distributions", which calls
/// the 2D case N-rooks: n samples instead of the n² of a full grid, lecture
/// §7). Point i lies in interval π_j(i) of dimension j; `centered` puts it at
/// the interval's centre (scipy's LatinHypercube(scramble=False)), otherwise
/// at a uniform offset, so every point is uniform on [0, 1)^d and estimates
/// are unbiased with variance never above (n/(n-1)) × that of independent
/// points (Owen 1997, "Monte Carlo variance of scrambled net quadrature").
///
/// The permutations are exact Fisher–Yates shuffles whose swaps come from
/// (seed, dim, step) through the counter-based generator, so the set depends
/// only on (n, d, seed, centered). A shuffle is inherently sequential: the
/// caller supplies n integers of scratch per dimension (no allocation here).
#include <cstdint>

#include "stratum/patterns/strata.hpp"

namespace stratum {

class LatinHypercube {
 public:
  LatinHypercube(std::uint64_t count, unsigned dimensions, std::uint64_t seed, bool centered = false)
      : count_(count), dimensions_(dimensions), seed_(seed), centered_(centered) {
    require(count >= 1 && count <= (std::uint64_t{1} << 53), "n", count, "N-rooks needs 1 <= n <= 2^53");
    require(dimensions >= 1, "d", dimensions, "N-rooks needs at least one dimension");
  }

  std::uint64_t count() const noexcept { return count_; }
  unsigned dimensions() const noexcept { return dimensions_; }
  bool centered() const noexcept { return centered_; }

  /// cells[i] = π_dim(i), the interval of point i in dimension dim; cells
  /// holds count() entries.
  template <class Index>
  void permutation(unsigned dim, Index* cells) const noexcept {
    random_permutation(cells, count_, permutation_key(dim));
  }
  /// The key of dimension dim's permutation (random_permutation's `key`).
  std::uint64_t permutation_key(unsigned dim) const noexcept { return hash64(seed_, 0x4e524f4f4b53ULL, dim); }

  /// Coordinate dim of point `index`, given its interval cell = π_dim(index).
  template <class Real = double>
  Real coordinate(std::uint64_t cell, std::uint64_t index, unsigned dim) const noexcept {
    const double offset = centered_ ? 0.5 : uniform01<double>(hash64(seed_, 0x4a4954544552ULL), index, dim);
    return cell_coordinate<Real>(cell, offset, count_);
  }

  /// The jitter hashes as a chain: offset(index, dim) = hash64(key, index,
  /// dim) = hash64_extend(hash64_extend(hash64(key), index), dim), so a row
  /// shares its first link (row_key(index)) over its coordinates, and every
  /// row the link before it, jitter_key() = hash64(key).
  std::uint64_t jitter_key() const noexcept { return jitter_chain(seed_, 0x4a4954544552ULL); }
  std::uint64_t row_key(std::uint64_t index) const noexcept { return row_key_of(jitter_key(), index); }
  static std::uint64_t row_key_of(std::uint64_t jitter_key, std::uint64_t index) noexcept {
    return hash64_extend(jitter_key, index);
  }
  /// coordinate(cell, index, dim) from row_key(index).
  template <class Real = double>
  Real coordinate_in_row(std::uint64_t cell, std::uint64_t row_key, unsigned dim) const noexcept {
    const double offset = centered_ ? 0.5 : bits_to_double(hash64_extend(row_key, dim));
    return cell_coordinate<Real>(cell, offset, count_);
  }

  /// All points, row-major (count() × dimensions() values), using `scratch`
  /// of count() integers.
  template <class Real = double, class Index>
  void generate(Real* out, Index* scratch) const noexcept {
    for (unsigned j = 0; j < dimensions_; ++j) {
      permutation(j, scratch);
      for (std::uint64_t i = 0; i < count_; ++i) out[i * dimensions_ + j] = coordinate<Real>(scratch[i], i, j);
    }
  }

 private:
  std::uint64_t count_;
  unsigned dimensions_;
  std::uint64_t seed_;
  bool centered_;
};

}  // namespace stratum
