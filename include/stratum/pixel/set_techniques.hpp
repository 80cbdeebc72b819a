#pragma once
/// The 2D set techniques of the pixel sampler (pixel/pixel_sampler.hpp): how
/// point `index` of the set of a 64-bit seed is computed from a small key of
/// the seed, with no table per seed. Each is the construction of the
/// registry's sampler of the same name, its first two coordinates (tested
/// point for point against the registry, tests/pixel/set_techniques_test.cpp).
///
/// A technique offers (all but `takes` host-and-device):
///  - `progressive`: its sets are prefixes of one randomized sequence, so a
///    set's points are indexed from 0 up without bound and a pixel's arrays
///    and frames continue its sequence;
///  - `takes(n)` (host): whether it makes a set of n points;
///  - `Shape shape(n)`: what its sets of n points share (a grid's side);
///  - `Key key(shape, seed)`: what a set's points need of its seed;
///  - `point<coordinates>(key, shape, index)`: the point (coordinate 1 is
///    left 0 when coordinates is 1, and not computed).
#include <array>
#include <cstdint>

#include "stratum/patterns/jittered.hpp"
#include "stratum/patterns/multi_jittered.hpp"
#include "stratum/patterns/strata.hpp"
#include "stratum/randomizers/base2.hpp"
#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/sequences/halton.hpp"
#include "stratum/sequences/kronecker.hpp"
#include "stratum/sequences/lattice_sequence.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/host_device.hpp"

namespace stratum::pixel {

using Point2 = std::array<double, 2>;

/// A shape that sets do not need (any n, nothing shared).
struct NoShape {};

/// Independent uniform points: the registry's `random`.
struct RandomTechnique {
  static constexpr bool progressive = true;
  using Shape = NoShape;
  struct Key {
    std::uint64_t mixed;  ///< hash64(seed): point i coordinate j is uniform01(seed, i, j)
  };
  bool takes(std::uint64_t) const noexcept { return true; }
  STRATUM_HOST_DEVICE Shape shape(std::uint64_t) const noexcept { return {}; }
  STRATUM_HOST_DEVICE Key key(Shape, std::uint64_t seed) const noexcept { return {hash64(seed)}; }
  template <int coordinates>
  STRATUM_HOST_DEVICE Point2 point(Key key, Shape, std::uint64_t index) const noexcept {
    Point2 p{0.0, 0.0};
    uniform01_pair<coordinates>(key.mixed, index, p.data());
    return p;
  }
};

/// Jittered sampling on a k × k grid (n = k²): the registry's `jittered`.
/// Point i lies in cell (i mod k, ⌊i / k⌋).
struct JitteredTechnique {
  static constexpr bool progressive = false;
  struct Shape {
    std::uint64_t side = 1;
  };
  using Key = RandomTechnique::Key;
  bool takes(std::uint64_t n) const noexcept {
    const std::uint64_t k = integer_root(n, 2);
    return n >= 1 && k * k == n;
  }
  Shape shape(std::uint64_t n) const noexcept { return {integer_root(n, 2)}; }
  STRATUM_HOST_DEVICE Key key(Shape, std::uint64_t seed) const noexcept { return {hash64(Jittered::key_of(seed))}; }
  template <int coordinates>
  Point2 point(Key key, Shape shape, std::uint64_t index) const noexcept {
    const Point2 u = RandomTechnique{}.point<coordinates>(key, {}, index);
    const std::uint64_t k = shape.side;
    Point2 p{cell_coordinate<double>(index % k, u[0], k), 0.0};
    if constexpr (coordinates == 2) p[1] = cell_coordinate<double>((index / k) % k, u[1], k);
    return p;
  }
};

/// How a base-2 randomizer of the registry scrambles one Sobol' dimension
/// of a seed's set: a bound per-dimension scrambler and its application.
namespace base2_scrambles {
struct None {
  struct Dimension {};
  STRATUM_HOST_DEVICE static Dimension dimension(std::uint64_t, unsigned) noexcept { return {}; }
  STRATUM_HOST_DEVICE static double apply(Dimension, const Sobol::View& sobol, std::uint64_t index,
                                          unsigned dim) noexcept {
    return bits_to_double(sobol.bits(index, dim));
  }
};
struct OwenHash {
  using Dimension = HashOwenScrambler::Dimension;
  STRATUM_HOST_DEVICE static Dimension dimension(std::uint64_t seed, unsigned dim) noexcept {
    return Dimension(HashOwenScrambler::dimension_key(seed, dim));
  }
  STRATUM_HOST_DEVICE static double apply(Dimension d, const Sobol::View& sobol, std::uint64_t index,
                                          unsigned dim) noexcept {
    return bits_to_double(reverse_bits64(d.scramble_reversed(sobol.reversed_bits(index, dim))));
  }
};
/// A randomizer whose seeded form binds a dimension (OwenScrambler, LinearMatrixScramble).
template <class Randomizer>
struct Bound {
  using Dimension = decltype(Randomizer(0).dimension(0));
  STRATUM_HOST_DEVICE static Dimension dimension(std::uint64_t seed, unsigned dim) noexcept {
    return Randomizer(seed).dimension(dim);
  }
  STRATUM_HOST_DEVICE static double apply(const Dimension& d, const Sobol::View& sobol, std::uint64_t index,
                                          unsigned dim) noexcept {
    return bits_to_double(d(sobol.bits(index, dim)));
  }
};
using Owen = Bound<OwenScrambler>;
using Lms = Bound<LinearMatrixScramble>;
struct Xor {
  using Dimension = std::uint64_t;
  STRATUM_HOST_DEVICE static Dimension dimension(std::uint64_t seed, unsigned dim) noexcept {
    return DigitalShift(seed).shift(dim);
  }
  STRATUM_HOST_DEVICE static double apply(Dimension shift, const Sobol::View& sobol, std::uint64_t index,
                                          unsigned dim) noexcept {
    return bits_to_double(sobol.bits(index, dim) ^ shift);
  }
};
struct Rotation {
  using Dimension = double;
  STRATUM_HOST_DEVICE static Dimension dimension(std::uint64_t seed, unsigned dim) noexcept {
    return CranleyPattersonRotation(seed).shift(dim);
  }
  STRATUM_HOST_DEVICE static double apply(Dimension shift, const Sobol::View& sobol, std::uint64_t index,
                                          unsigned dim) noexcept {
    return CranleyPattersonRotation::rotate(bits_to_double(sobol.bits(index, dim)), shift);
  }
};
}  // namespace base2_scrambles

/// Sobol' dimensions 0 and 1 (the (0,2)-sequence, Gray-code order) under a
/// base-2 randomizer: the registry's `sobol` and `zero-two` with randomizer
/// none, owen-hash (their default), owen, xor, lms or cp. The tables are the
/// shared, read-only Sobol::first_two() (on a device: a View over a copy).
template <class Scramble>
struct SobolTechnique {
  static constexpr bool progressive = true;
  using Shape = NoShape;
  struct Key {
    typename Scramble::Dimension x, y;
  };
  Sobol::View sobol = Sobol::first_two().view();
  bool takes(std::uint64_t) const noexcept { return true; }
  STRATUM_HOST_DEVICE Shape shape(std::uint64_t) const noexcept { return {}; }
  STRATUM_HOST_DEVICE Key key(Shape, std::uint64_t seed) const noexcept {
    return {Scramble::dimension(seed, 0), Scramble::dimension(seed, 1)};
  }
  template <int coordinates>
  STRATUM_HOST_DEVICE Point2 point(const Key& key, Shape, std::uint64_t index) const noexcept {
    Point2 p{Scramble::apply(key.x, sobol, index, 0), 0.0};
    if constexpr (coordinates == 2) p[1] = Scramble::apply(key.y, sobol, index, 1);
    return p;
  }
};
using SobolOwenHash = SobolTechnique<base2_scrambles::OwenHash>;

/// Progressive multi-jittered (0,2) points (Christensen, Kensler, Kilpatrick
/// 2018; sequences/pmj.hpp): the registry's `pmj02`, its first pair.
struct Pmj02Technique {
  static constexpr bool progressive = true;
  using Shape = NoShape;
  struct Key {
    std::uint64_t x, y;
  };
  bool takes(std::uint64_t) const noexcept { return true; }
  STRATUM_HOST_DEVICE Shape shape(std::uint64_t) const noexcept { return {}; }
  STRATUM_HOST_DEVICE Key key(Shape, std::uint64_t seed) const noexcept {
    return {Pmj02::digit_key(seed, 0), Pmj02::digit_key(seed, 1)};
  }
  template <int coordinates>
  STRATUM_HOST_DEVICE Point2 point(Key key, Shape, std::uint64_t index) const noexcept {
    Point2 p{bits_to_double(Pmj02::keyed_bits(index, 0, key.x)), 0.0};
    if constexpr (coordinates == 2) p[1] = bits_to_double(Pmj02::keyed_bits(index, 1, key.y));
    return p;
  }
};

/// A sequence's coordinates (0, 1), unrandomized or under a Cranley–Patterson
/// rotation of the seed (the registry's none and cp of its rotation family):
/// Sequence2D offers `value(index, dim)`.
template <class Sequence2D>
struct RotatedTechnique {
  static constexpr bool progressive = true;
  using Shape = NoShape;
  struct Key {
    double x = 0, y = 0;  ///< the shifts (0 unrotated)
  };
  Sequence2D sequence{};
  bool rotate = false;  ///< cp: rotated by the seed's shifts
  bool takes(std::uint64_t) const noexcept { return true; }
  STRATUM_HOST_DEVICE Shape shape(std::uint64_t) const noexcept { return {}; }
  STRATUM_HOST_DEVICE Key key(Shape, std::uint64_t seed) const noexcept {
    if (!rotate) return {};
    const CranleyPattersonRotation rotation(seed);
    return {rotation.shift(0), rotation.shift(1)};
  }
  template <int coordinates>
  STRATUM_HOST_DEVICE Point2 point(Key key, Shape, std::uint64_t index) const noexcept {
    Point2 p{coordinate(index, 0, key.x), 0.0};
    if constexpr (coordinates == 2) p[1] = coordinate(index, 1, key.y);
    return p;
  }

 private:
  STRATUM_HOST_DEVICE double coordinate(std::uint64_t index, unsigned dim, double shift) const noexcept {
    const double value = sequence.value(index, dim);
    return rotate ? CranleyPattersonRotation::rotate(value, shift) : value;
  }
};

/// Halton's first two coordinates (bases 2 and 3).
struct Halton2D {
  STRATUM_HOST_DEVICE double value(std::uint64_t index, unsigned dim) const noexcept {
    return to_unit<double>(radical_inverse(Halton::base(dim), index, detail::prime_reciprocal(dim)));
  }
};
/// frac(s + i·α) with the registry's default α (R_2, Roberts 2018) or given α, exactly in 128 bits.
struct Kronecker2D {
  Kronecker::u128 offset = 0;
  std::array<Kronecker::u128, 2> alpha{};
  static Kronecker2D of(const Kronecker& kronecker) {
    return {Kronecker::to_fraction(kronecker.offset()), {kronecker.alpha_fraction(0), kronecker.alpha_fraction(1)}};
  }
  STRATUM_HOST_DEVICE double value(std::uint64_t index, unsigned dim) const noexcept {
    return Kronecker::coordinate(index, offset, alpha[dim]);
  }
};
/// The extensible rank-1 lattice frac(φ₂(i)·g) (Hickernell et al. 2000), its generating vector's first two entries.
struct LatticeSequence2D {
  std::array<std::uint64_t, 2> generator{LatticeSequence::default_generator[0], LatticeSequence::default_generator[1]};
  STRATUM_HOST_DEVICE double value(std::uint64_t index, unsigned dim) const noexcept {
    return LatticeSequence::coordinate(index, generator[dim]);
  }
};
using HaltonTechnique = RotatedTechnique<Halton2D>;
using KroneckerTechnique = RotatedTechnique<Kronecker2D>;
using LatticeSequenceTechnique = RotatedTechnique<LatticeSequence2D>;

/// Kensler's correlated multi-jittered sampling (2013, "Correlated
/// Multi-Jittered Sampling"; patterns/multi_jittered.hpp): the registry's
/// `cmj`, index-addressable through its hashed permutations. A set of n
/// points shares its grid and permutation domains (Shape); a seed is
/// Kensler's pattern number, from which a point derives its keys.
struct CmjTechnique {
  static constexpr bool progressive = false;
  using Shape = CorrelatedMultiJittered;
  using Key = CorrelatedMultiJittered::Keys;
  double aspect = 1.0;  ///< columns / rows
  bool takes(std::uint64_t n) const noexcept { return n >= 1 && n <= 0xffffffffULL; }
  Shape shape(std::uint64_t n) const { return CorrelatedMultiJittered(n, 0, aspect); }
  Key key(const Shape& shape, std::uint64_t seed) const noexcept {
    return shape.keys(CorrelatedMultiJittered::pattern_of(seed));
  }
  template <int coordinates>
  Point2 point(const Key& key, const Shape& shape, std::uint64_t index) const noexcept {
    Point2 p{0.0, 0.0};
    shape.sample_for(key, index, coordinates, p.data());
    return p;
  }
};

}  // namespace stratum::pixel
