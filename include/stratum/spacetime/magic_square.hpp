#pragma once
/// Pan-diagonal (diabolic) magic squares as time-slot tables (LECTURE.md §8):
/// entries 0 .. m²−1 such that every row, every column and every broken
/// diagonal in both directions sums to m(m²−1)/2. Assigned to the strata of
/// an m×m grid, every row, column and diagonal of strata then has the same
/// mean time, including across pixel borders, since the square tiles.
///
/// They exist for m = 1 and every m ≥ 4 with m ≢ 2 (mod 4); for m = 2, 3 and
/// m ≡ 2 (mod 4) none exists (a classical parity argument; see Rosser,
/// Walker 1939, "The algebraic theory of diabolic magic squares", Duke
/// Math. J. 5).
///
/// Construction: de la Hire's method of two auxiliary squares (de la Hire
/// 1705), M = m·A + B, where (A, B) takes every pair of values in 0 .. m−1
/// once, and A and B each have every row, column and broken diagonal sum
/// m(m−1)/2. We use A = σ((r + 2c) mod m) and B = σ((e r + f c) mod m) with a
/// bijection σ of 0 .. m−1. Along a line of slope (dr, dc) the argument
/// steps by s (s = 2, 1, 3, −1 for rows, columns, diagonals, antidiagonals of
/// A), so the line visits each element of a coset of gZ_m, g = gcd(s, m),
/// g times; the line sum is right when σ maps every such coset to values of
/// mean (m−1)/2.
///  - m odd, 3 ∤ m: (e, f) = (2, 1), σ = identity. Every step (1, 2, 3, −1)
///    is a unit, each line is a permutation: the classical cyclic
///    ("knight's move") square (see Kraitchik 1942, "Mathematical
///    recreations"). (A, B) is a bijection since det = 1·1 − 2·2 = −3
///    is a unit.
///  - m odd, 3 | m (m ≥ 9): (e, f) = (1, −2). The steps are units except 3
///    (diagonals of A, antidiagonals of B), with g = 3, so σ must balance
///    the residues mod 3: σ(3q + ρ) = 3q + π_q(ρ) with permutations π_q of
///    {0, 1, 2} whose column sums Σ_q π_q(ρ) are all equal (three cyclic
///    shifts, then pairs of a permutation and its reverse, m/3 being odd).
///    det = −2 − 2 = −4 is a unit (m odd).
///  - m ≡ 0 (mod 4): (e, f) = (2, 3); every step (1, 2, 3, −1; 2, 3, 5, −1)
///    has g with m/g even, so each coset is closed under v → v + m/2, and
///    σ(v) = v for v < m/2, σ(v) = 3m/2 − 1 − v otherwise, satisfies
///    σ(v) + σ(v + m/2) = m − 1: every coset has mean (m−1)/2. det = 3 − 4
///    = −1 is a unit.
/// m = 4 returns the lecture slide's square instead (also pan-diagonal).
/// The tests check every m in 4 .. 64 by brute force.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "stratum/spacetime/time_assignment.hpp"
#include "stratum/util/error.hpp"

namespace stratum {

/// Does a pan-diagonal magic square of order m exist?
constexpr bool pandiagonal_magic_exists(std::uint64_t m) noexcept { return m == 1 || (m >= 4 && m % 4 != 2); }

/// The lecture's 4×4 pan-diagonal magic square (rows top to bottom).
inline constexpr std::array<std::uint32_t, 16> slide_magic_square = {15, 8,  5, 2, 4, 3, 14, 9,
                                                                     10, 13, 0, 7, 1, 6, 11, 12};

/// The magic sum of order m: m(m²−1)/2.
constexpr std::uint64_t magic_sum(std::uint64_t m) noexcept { return m * (m * m - 1) / 2; }

/// A pan-diagonal magic square of order m (entries 0 .. m²−1), built as
/// described above; throws invalid_argument naming m when none exists.
inline SlotTable pandiagonal_magic_square(std::uint32_t m) {
  require_slot_order(m);
  require(pandiagonal_magic_exists(m), "m", m,
          "pan-diagonal magic squares exist only for m = 1 and m >= 4 with m mod 4 != 2 (none for m = 2, 3, 6, 10, "
          "14, ...)");
  SlotTable table{m, std::vector<std::uint32_t>(static_cast<std::size_t>(m) * m)};
  if (m == 4) {
    for (std::size_t k = 0; k < 16; ++k) table.slots[k] = slide_magic_square[k];
    return table;
  }
  if (m == 1) {
    table.slots[0] = 0;
    return table;
  }
  std::vector<std::uint32_t> sigma(m);
  std::int64_t e = 2, f = 1;
  for (std::uint32_t v = 0; v < m; ++v) sigma[v] = v;
  if (m % 4 == 0) {
    e = 2, f = 3;
    for (std::uint32_t v = m / 2; v < m; ++v) sigma[v] = 3 * m / 2 - 1 - v;
  } else if (m % 3 == 0) {
    e = 1, f = -2;
    constexpr std::uint32_t cycles[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
    for (std::uint32_t q = 0; q < m / 3; ++q)
      for (std::uint32_t rho = 0; rho < 3; ++rho) {
        // q < 3: cyclic shifts (column sums 3 each); then pairs of the
        // identity and its reverse (column sums 2 each).
        const std::uint32_t image = q < 3 ? cycles[q][rho] : (q % 2 == 1 ? rho : 2 - rho);
        sigma[3 * q + rho] = 3 * q + image;
      }
  }
  const auto mod = [m](std::int64_t value) {
    const std::int64_t mm = m;
    return static_cast<std::uint32_t>(((value % mm) + mm) % mm);
  };
  for (std::uint32_t r = 0; r < m; ++r)
    for (std::uint32_t c = 0; c < m; ++c)
      table(r, c) = m * sigma[mod(std::int64_t{r} + 2 * std::int64_t{c})] + sigma[mod(e * r + f * c)];
  return table;
}

}  // namespace stratum
