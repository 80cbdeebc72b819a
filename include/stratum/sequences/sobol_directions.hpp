#pragma once
/// The Joe–Kuo direction numbers of all 21201 dimensions (Joe, Kuo 2008,
/// "Constructing Sobol sequences with better two-dimensional projections",
/// new-joe-kuo-6.21201), decoded from the bit-packed table that
/// scripts/generate_sobol_table.py writes from scipy's copy. The first 3667
/// dimensions are those of Boost.Random's table (tests/sequences/sobol_test.cpp).
/// Host code: the kernels read Sobol's own tables (docs/gpu.md).
#include <cstddef>
#include <cstdint>

#include "stratum/sequences/sobol_joe_kuo_table.hpp"

namespace stratum::sobol_joe_kuo {

/// Primitive polynomial and initial direction numbers of one dimension.
struct Directions {
  unsigned degree = 0;               ///< s; 0 for dimension 0 (van der Corput)
  std::uint32_t polynomial = 0;      ///< bits a_s..a_0 (a_s = a_0 = 1), as Boost and scipy store it
  std::uint32_t m[max_degree] = {};  ///< m_1..m_s: odd, m_k < 2^k
};

/// Bits of one record of degree s: a_1..a_{s−1}, then m_k in k − 1 bits, k = 2..s.
constexpr unsigned record_bits(unsigned s) noexcept { return (s - 1) + s * (s - 1) / 2; }

/// `width` (1..63) bits of the packed stream from bit `position` on.
constexpr std::uint64_t read_bits(std::uint64_t position, unsigned width) noexcept {
  const std::size_t word = static_cast<std::size_t>(position / 64);
  const unsigned shift = static_cast<unsigned>(position % 64);
  std::uint64_t value = packed[word] >> shift;
  if (shift + width > 64) value |= packed[word + 1] << (64 - shift);
  return value & ((std::uint64_t{1} << width) - 1);
}

/// Dimension dim < dimensions. The records are sorted by degree and all
/// records of a degree have the same length, so the counts locate them.
constexpr Directions directions(unsigned dim) noexcept {
  Directions out;
  if (dim == 0) return out;
  unsigned first = 1, s = 1;
  std::uint64_t position = 0;
  while (dim >= first + degree_counts[s]) {
    first += degree_counts[s];
    position += std::uint64_t{degree_counts[s]} * record_bits(s);
    ++s;
  }
  position += std::uint64_t{dim - first} * record_bits(s);
  out.degree = s;
  out.polynomial = (std::uint32_t{1} << s) | 1u;
  for (unsigned i = 1; i < s; ++i) out.polynomial |= static_cast<std::uint32_t>(read_bits(position++, 1)) << (s - i);
  out.m[0] = 1;
  for (unsigned k = 2; k <= s; ++k) {
    out.m[k - 1] = 2 * static_cast<std::uint32_t>(read_bits(position, k - 1)) + 1;
    position += k - 1;
  }
  return out;
}

}  // namespace stratum::sobol_joe_kuo
