#pragma once
/// N-queens sampling: n points in [0, 1)², one in each row and each column
/// of an n × n grid of cells (N-rooks) and, in addition, no two cells on a
/// common diagonal or anti-diagonal (the n-queens condition), so the points
/// avoid the diagonal clumps an N-rooks set can have (lecture §7; Shirley
/// 1991, "Discrepancy as a quality measure for sample distributions").
/// Solutions exist for n = 1 and every n ≥ 4.
///
/// Construction, all index-addressable (cell of queen i from i alone):
/// - when gcd(n, 6) = 1, the modular solutions column = (a·row + b) mod n with
///   gcd(a(a-1)(a+1), n) = 1 (Pólya 1918): they are even solutions on the
///   torus; a and b are drawn from the seed, and because b is uniform every
///   cell holds a queen with probability exactly 1/n, so estimates are
///   unbiased;
/// - otherwise the explicit solutions of Hoffman, Loessi, Moore 1969
///   ("Constructions for the solution of the m queens problem"): for even n
///   with n mod 6 ≠ 2 the queens of rows 1…n/2 stand in columns 2, 4, …, n
///   and those of rows n/2+1…n in columns 1, 3, …, n-1; for even n with
///   n mod 6 ≠ 0, row i (≤ n/2) holds column 1 + (2(i-1) + n/2 - 1) mod n and
///   row n+1-i the mirror column; odd n adds (n, n) to the solution for n-1.
///   Only the 8 symmetries of the square randomize these, so the cell
///   occupancy is not uniform: use the "cp" randomizer for unbiased estimates.
/// Then one of the 8 symmetries of the square (chosen by the seed) is applied
/// and every point is jittered uniformly inside its cell.
#include <cstdint>
#include <numeric>
#include <utility>

#include "stratum/patterns/strata.hpp"

namespace stratum {

class NQueens {
 public:
  /// Whether an n-queens solution exists.
  static constexpr bool solvable(std::uint64_t n) noexcept { return n == 1 || n >= 4; }

  NQueens(std::uint64_t count, std::uint64_t seed) : count_(count), seed_(seed) {
    require(solvable(count) && count <= (std::uint64_t{1} << 32), "n", count,
            "n-queens solutions exist only for n = 1 or n >= 4 (n <= 2^32 here)");
    symmetry_ = static_cast<unsigned>(uniform_below(8, seed, 0x53594dULL));
    if (count > 1 && std::gcd(count, std::uint64_t{6}) == 1) {
      modular_ = true;
      const std::uint64_t key = hash64(seed, 0x4d4f44ULL);
      for (std::uint64_t attempt = 0;; ++attempt) {
        // a ∈ [2, n-2]; for n ≥ 5 coprime to 6, a = 2 already works when 3 ∤ n.
        const std::uint64_t a = 2 + uniform_below(count - 3, key, attempt);
        if (std::gcd(a, count) == 1 && std::gcd(a - 1, count) == 1 && std::gcd(a + 1, count) == 1) {
          multiplier_ = a;
          break;
        }
      }
      offset_ = uniform_below(count, key, ~std::uint64_t{0});
    }
  }

  std::uint64_t count() const noexcept { return count_; }
  /// Whether the seed chose among the modular (toroidal) solutions.
  bool modular() const noexcept { return modular_; }
  /// Index of the symmetry of the square applied (bit 0: transpose, bit 1:
  /// mirror x, bit 2: mirror y).
  unsigned symmetry() const noexcept { return symmetry_; }

  /// Column of the queen in row `row` of the solution before the symmetry.
  std::uint64_t base_column(std::uint64_t row) const noexcept {
    if (modular_)
      return static_cast<std::uint64_t>((static_cast<unsigned __int128>(multiplier_) * row + offset_) % count_);
    return explicit_column(row, count_);
  }

  /// The cell (column in dim 0, row in dim 1) of queen `index`.
  std::uint64_t cell(std::uint64_t index, unsigned dim) const noexcept {
    std::uint64_t x = index, y = base_column(index);
    if (symmetry_ & 1u) std::swap(x, y);
    if (symmetry_ & 2u) x = count_ - 1 - x;
    if (symmetry_ & 4u) y = count_ - 1 - y;
    return dim == 0 ? x : y;
  }

  template <class Real = double>
  Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return cell_coordinate<Real>(cell(index, dim), uniform01<double>(hash64(seed_, 0x514a4954ULL), index, dim),
                                 count_);
  }

  /// Hoffman–Loessi–Moore column of row r (0-based) for n ≥ 4 (or n = 1).
  static constexpr std::uint64_t explicit_column(std::uint64_t r, std::uint64_t n) noexcept {
    if (n == 1) return 0;
    if (n % 2 == 1) return r == n - 1 ? n - 1 : explicit_column(r, n - 1);
    const std::uint64_t half = n / 2;
    if (n % 6 != 2) return r < half ? 2 * r + 1 : 2 * (r - half);
    if (r < half) return (2 * r + half - 1) % n;
    return n - 1 - (2 * (n - 1 - r) + half - 1) % n;
  }

 private:
  std::uint64_t count_;
  std::uint64_t seed_;
  unsigned symmetry_ = 0;
  bool modular_ = false;
  std::uint64_t multiplier_ = 1;
  std::uint64_t offset_ = 0;
};

}  // namespace stratum
