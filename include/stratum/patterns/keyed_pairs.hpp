#pragma once
/// 2D sets whose points follow from a small key of the set's seed: the
/// first two coordinates of a sampler's set, point by point, after one
/// hash of the seed and with no table per seed. A renderer draws a new set
/// per pixel and dimension (pbrt-v4's samplers likewise reseed per pixel
/// sample), so a set's setup, not its points, would dominate; each type
/// here is its sampler's construction written keyed, bit for bit (tested
/// against the registry's sets, tests/patterns/keyed_pairs_test.cpp):
/// - RandomPairs: RandomPattern(seed);
/// - JitteredPairs: Jittered over a k × k grid (n = k²);
/// - SobolOwenHashPairs: Sobol' dimensions 0 and 1 under HashOwenScrambler(seed);
/// - Pmj02Pairs: Pmj02(·, seed)'s first pair.
/// The registry says which sampler and randomizer has which
/// (SamplerInfo::keyed_pairs). takes(n, root) says whether a set of n points
/// exists, and point(key, root, index) gives point `index` of the set of seed
/// s from key = key(s); root = ⌊√n⌋ (the jittered grid's side), computed once
/// per count rather than per point.
#include <array>
#include <cstdint>
#include <variant>

#include "stratum/patterns/jittered.hpp"
#include "stratum/patterns/strata.hpp"
#include "stratum/randomizers/base2.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

/// What a keyed set's points depend on besides their index.
struct PairKey {
  std::uint64_t a = 0, b = 0;
};

struct RandomPairs {
  static PairKey key(std::uint64_t seed) noexcept { return {hash64(seed)}; }
  static bool takes(std::uint64_t, std::uint64_t) noexcept { return true; }
  template <int coordinates>
  static std::array<double, 2> point(PairKey key, std::uint64_t, std::uint64_t index) noexcept {
    std::array<double, 2> p{0.0, 0.0};
    uniform01_pair<coordinates>(key.a, index, p.data());
    return p;
  }
};

struct JitteredPairs {
  static PairKey key(std::uint64_t seed) noexcept { return {hash64(Jittered::key_of(seed))}; }
  /// n = k² points, one in each cell of the k × k grid (root = ⌊√n⌋).
  static bool takes(std::uint64_t n, std::uint64_t root) noexcept { return root * root == n; }
  /// Point `index` lies in cell (index mod k, ⌊index / k⌋ mod k), k = root.
  template <int coordinates>
  static std::array<double, 2> point(PairKey key, std::uint64_t root, std::uint64_t index) noexcept {
    const std::array<double, 2> u = RandomPairs::point<coordinates>(key, root, index);
    std::array<double, 2> p{cell_coordinate<double>(index % root, u[0], root), 0.0};
    if constexpr (coordinates == 2) p[1] = cell_coordinate<double>((index / root) % root, u[1], root);
    return p;
  }
};

struct SobolOwenHashPairs {
  static PairKey key(std::uint64_t seed) noexcept {
    return {HashOwenScrambler::dimension_key(seed, 0), HashOwenScrambler::dimension_key(seed, 1)};
  }
  static bool takes(std::uint64_t, std::uint64_t) noexcept { return true; }
  template <int coordinates>
  std::array<double, 2> point(PairKey key, std::uint64_t, std::uint64_t index) const noexcept {
    std::array<double, 2> p{sobol->sample(index, 0, HashOwenScrambler::Dimension(key.a)), 0.0};
    if constexpr (coordinates == 2) p[1] = sobol->sample(index, 1, HashOwenScrambler::Dimension(key.b));
    return p;
  }
  const Sobol* sobol = &Sobol::first_two();
};

struct Pmj02Pairs {
  static PairKey key(std::uint64_t seed) noexcept { return {Pmj02::digit_key(seed, 0), Pmj02::digit_key(seed, 1)}; }
  static bool takes(std::uint64_t, std::uint64_t) noexcept { return true; }
  template <int coordinates>
  static std::array<double, 2> point(PairKey key, std::uint64_t, std::uint64_t index) noexcept {
    std::array<double, 2> p{bits_to_double(Pmj02::keyed_bits(index, 0, key.a)), 0.0};
    if constexpr (coordinates == 2) p[1] = bits_to_double(Pmj02::keyed_bits(index, 1, key.b));
    return p;
  }
};

/// One of the above (a class, not an alias, so that the registry's header
/// can name it without including the sequences' tables).
struct KeyedPairs {
  std::variant<RandomPairs, JitteredPairs, SobolOwenHashPairs, Pmj02Pairs> pairs;
};

}  // namespace stratum
