#pragma once
/// Extensible rank-1 lattice sequences x_i = frac(φ_2(i) · g) for an integer
/// generating vector g (Hickernell, Hong, L'Ecuyer, Lemieux 2000,
/// "Extensible lattice sequences for quasi-Monte Carlo quadrature"): the
/// van der Corput radical inverse φ_2 of the index times g, modulo 1. The
/// first 2^m points are exactly the rank-1 lattice {frac(k g / 2^m) :
/// k < 2^m} (φ_2 maps 0 … 2^m − 1 onto the multiples of 2^-m), so one
/// sequence holds a lattice rule for every n = 2^m, each extending the
/// previous; the next 2^m points are that lattice shifted by φ_2(2^m)·g.
///
/// Arithmetic. φ_2(i) = reverse(i) / 2^64 exactly, so the coordinate is
/// (reverse(i) · g_j mod 2^64) / 2^64: one 64-bit multiplication that wraps
/// exactly, for every 64-bit index (the double keeps its 53 leading bits).
///
/// The default g is the first 32 components of the embedded lattice
/// "lattice-32001-1024-1048576.3600" of Cools, Kuo, Nuyens 2006
/// ("Constructing embedded lattice rules for multivariate integration",
/// SIAM J. Sci. Comput. 28(6)), published on F. Y. Kuo's lattice page:
/// constructed component by component for the weighted Korobov space with
/// order-2 weights, good for every n = 2^m from 2^10 to 2^20 (the sequence
/// is defined beyond, with no such guarantee). Its entries are odd, so every
/// coordinate of a 2^m prefix is a permutation of {k / 2^m} (Latin).
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "stratum/util/bits.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

class LatticeSequence {
 public:
  static constexpr unsigned max_dimensions = 4096;
  /// Components of the default generating vector (Cools, Kuo, Nuyens 2006).
  static constexpr std::array<std::uint64_t, 32> default_generator = {
      1,      182667, 469891, 498753, 110745, 446247, 250185, 118627, 245333, 283199, 408519,
      391023, 246327, 126539, 399185, 461527, 300343, 69681,  516695, 436179, 106383, 238523,
      413283, 70841,  47719,  300129, 113029, 123925, 410745, 211325, 17489,  511893};

  /// The default generating vector's first d components (d ≤ 32).
  explicit LatticeSequence(unsigned dimensions) {
    require(dimensions >= 1 && dimensions <= default_generator.size(), "d", dimensions,
            "the default generating vector has 32 components; give a generator for more dimensions");
    generator_.assign(default_generator.begin(), default_generator.begin() + dimensions);
  }

  /// A user's generating vector: one positive integer per dimension.
  explicit LatticeSequence(std::span<const std::uint64_t> generator) {
    require(!generator.empty() && generator.size() <= max_dimensions, "generator", generator.size(),
            "needs 1 to " + std::to_string(max_dimensions) + " entries, one per dimension");
    for (std::size_t j = 0; j < generator.size(); ++j)
      if (generator[j] == 0)  // message built only on failure
        throw invalid_argument("generator", "entry " + std::to_string(j) + " = 0", "entries must be positive integers");
    generator_.assign(generator.begin(), generator.end());
  }

  unsigned dimensions() const noexcept { return static_cast<unsigned>(generator_.size()); }
  std::uint64_t generator(unsigned dim) const noexcept { return generator_[dim]; }

  /// frac(φ_2(index) · g_dim) as a 64-bit binary fraction, exactly.
  constexpr std::uint64_t fraction(std::uint64_t index, unsigned dim) const noexcept {
    return reverse_bits64(index) * generator_[dim];
  }

  /// The coordinate's 53 (or 24) leading bits, always < 1.
  template <class Real = double>
  constexpr Real sample(std::uint64_t index, unsigned dim) const noexcept {
    return coordinate<Real>(index, generator_[dim]);
  }
  /// sample's coordinate for a generator entry g alone (the pixel sampler's pairs keep two entries, not the vector).
  template <class Real = double>
  STRATUM_HOST_DEVICE static constexpr Real coordinate(std::uint64_t index, std::uint64_t g) noexcept {
    return to_unit<Real>(static_cast<double>((reverse_bits64(index) * g) >> 11) * 0x1.0p-53);
  }

 private:
  std::vector<std::uint64_t> generator_;
};

}  // namespace stratum
