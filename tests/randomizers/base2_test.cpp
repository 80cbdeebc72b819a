#include "stratum/randomizers/base2.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/bits.hpp"

namespace stratum {
namespace {

// The four digital randomizers as (name, word map for dim) closures.
using WordMap = std::function<std::uint64_t(std::uint64_t, unsigned)>;
std::vector<std::pair<std::string, WordMap>> digital_randomizers(std::uint64_t seed) {
  return {
      {"owen", [r = OwenScrambler(seed)](std::uint64_t w, unsigned dim) { return r(w, dim); }},
      {"owen-hash", [r = HashOwenScrambler(seed)](std::uint64_t w, unsigned dim) { return r(w, dim); }},
      {"xor", [r = DigitalShift(seed)](std::uint64_t w, unsigned dim) { return r(w, dim); }},
      {"lms", [r = LinearMatrixScramble(seed)](std::uint64_t w, unsigned dim) { return r(w, dim); }},
  };
}

TEST(Base2, DigitalShiftIsAnXorDecorrelatedAcrossDimensionsAndSeeds) {
  const DigitalShift a(1), b(1), c(2);
  EXPECT_EQ(a.shift(3), b.shift(3));
  EXPECT_NE(a.shift(3), c.shift(3));
  EXPECT_NE(a.shift(3), a.shift(4));
  EXPECT_EQ(a(0x1234, 3), 0x1234 ^ a.shift(3));
  EXPECT_EQ(a(a(0x1234, 3), 3), 0x1234u);
  // Different randomizers with the same seed do not share their words.
  EXPECT_NE(a.shift(0), LinearMatrixScramble(1).dimension(0).shift());
}

// The defining property of every digital (nested) scramble in base 2:
// output digit b is input digit b XOR a function of the higher digits. So
// flipping input bit b flips output bit b and leaves every higher bit.
TEST(Base2, EachDigitIsFlippedByAFunctionOfHigherDigitsOnly) {
  std::mt19937_64 words(17);
  for (std::uint64_t seed : std::initializer_list<std::uint64_t>{0, 5}) {
    for (const auto& [name, r] : digital_randomizers(seed)) {
      for (int trial = 0; trial < 40; ++trial) {
        const std::uint64_t w = words();
        const unsigned dim = static_cast<unsigned>(trial % 7);
        const std::uint64_t y = r(w, dim);
        for (unsigned b = 0; b < 64; ++b) {
          const std::uint64_t change = r(w ^ (std::uint64_t{1} << b), dim) ^ y;
          ASSERT_EQ(change >> b, 1u) << name << " bit " << b;  // bit b flips, nothing above it
        }
      }
    }
  }
}

// Hence each randomizer permutes the 2^m dyadic intervals of every level m.
TEST(Base2, PermutesTheDyadicIntervalsOfEachLevel) {
  for (const auto& [name, r] : digital_randomizers(3))
    for (unsigned m : {1u, 4u, 10u}) {
      std::vector<int> seen(std::size_t{1} << m, 0);
      for (std::uint64_t p = 0; p < (std::uint64_t{1} << m); ++p) ++seen[r(p << (64 - m) | 0x5a5a, 2) >> (64 - m)];
      for (int s : seen) ASSERT_EQ(s, 1) << name << " level " << m;
    }
}

// The top 32 digits of the 64-bit hash-based scramble are the published
// 32-bit one (Burley 2020 with Vegdahl's constants, as in pbrt-v4's
// FastOwenScrambler and Cycles) with seed = low half of the dimension key.
std::uint32_t published_owen32(std::uint32_t v, std::uint32_t seed) {
  v = reverse_bits32(v);
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return reverse_bits32(v);
}

TEST(Base2, HashOwenTopHalfIsThePublished32BitScramble) {
  std::mt19937_64 words(23);
  const HashOwenScrambler owen(77);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::uint64_t w = words();
    const unsigned dim = static_cast<unsigned>(trial % 50);
    const auto per_dim = owen.dimension(dim);
    ASSERT_EQ(owen(w, dim) >> 32, published_owen32(static_cast<std::uint32_t>(w >> 32), per_dim.seed32()));
    ASSERT_EQ(per_dim(w), owen(w, dim));
    ASSERT_EQ(reverse_bits64(per_dim.scramble_reversed(reverse_bits64(w))), owen(w, dim));
  }
}

// Values of the 64-bit hash-based scramble pinned from the implementation
// before the per-dimension cache existed: dimensions below, at and above
// HashOwenScrambler::cached_dimensions (16), indices past 2^32.
TEST(Base2, HashOwenPinnedValuesAcrossTheDimensionCache) {
  struct Pin {
    std::uint64_t index;
    unsigned dim;
    std::uint64_t scrambled;
  };
  const Pin pins[] = {
      {0ull, 0, 0x4540d111d02f1bdbull},      {1ull, 3, 0xf4e6f43397b86175ull},
      {77ull, 15, 0x5d92f86095475a77ull},    {77ull, 16, 0x76362a4cfeeaf808ull},
      {12345ull, 39, 0x6dfd89e21295cf43ull}, {4294967305ull, 17, 0x80dbb8fe36cdf800ull},
      {~0ull, 1, 0x2acd1ea57b016134ull},
  };
  const HashOwenScrambler owen(2024);
  const Sobol sobol(40);
  for (const Pin& pin : pins) {
    const std::uint64_t w = sobol.bits(pin.index, pin.dim);
    EXPECT_EQ(owen(w, pin.dim), pin.scrambled) << pin.index << " " << pin.dim;
    EXPECT_EQ(owen.dimension(pin.dim)(w), pin.scrambled);
    const HashOwenScrambler copy = owen;  // the cache is part of the value
    EXPECT_EQ(copy(w, pin.dim), pin.scrambled);
  }
  static_assert(HashOwenScrambler::cached_dimensions == 16);
  static_assert(sizeof(HashOwenScrambler) <= 8 + 16 * 16, "cheap to copy: 264 bytes");
  // Usable in constant expressions (the cache is built by a constexpr constructor).
  static_assert(HashOwenScrambler(2024).dimension(3).scramble_reversed(1) ==
                HashOwenScrambler::scramble_reversed(1, HashOwenScrambler(2024).dimension(3).addend(),
                                                     HashOwenScrambler(2024).dimension(3).multiplier()));
}

// The static form with explicit constants (what vectorized bulk code runs)
// is the bound scramble, for cached and derived dimensions; the multiplier is odd.
TEST(Base2, HashOwenStepsWithExplicitConstantsAreTheBoundScramble) {
  std::mt19937_64 words(41);
  const HashOwenScrambler owen(6);
  for (unsigned dim = 0; dim < 40; ++dim) {
    const auto bound = owen.dimension(dim);
    EXPECT_EQ(bound.multiplier() & 1, 1u);
    EXPECT_EQ(static_cast<std::uint32_t>(bound.addend()), bound.seed32());
    for (int trial = 0; trial < 20; ++trial) {
      const std::uint64_t r = words();
      ASSERT_EQ(HashOwenScrambler::scramble_reversed(r, bound.addend(), bound.multiplier()),
                bound.scramble_reversed(r));
    }
  }
}

// Exact Owen scrambling applies one flip per tree node: node (depth, higher digits).
TEST(Base2, OwenFlipsEachDigitByItsNode) {
  std::mt19937_64 words(29);
  const OwenScrambler owen(8);
  for (int trial = 0; trial < 50; ++trial) {
    const std::uint64_t w = words();
    const auto per_dim = owen.dimension(4);
    std::uint64_t want = w;
    for (unsigned depth = 0; depth < 64; ++depth) {
      const std::uint64_t prefix = depth == 0 ? 0 : w >> (64 - depth);
      if (per_dim.flip(depth, prefix)) want ^= std::uint64_t{1} << (63 - depth);
    }
    ASSERT_EQ(owen(w, 4), want);
  }
  // Two words sharing their first 20 digits share the first 20 flips.
  const std::uint64_t a = 0xabcde00000000000ULL, b = 0xabcde12345678901ULL;
  EXPECT_EQ((owen(a, 1) ^ a) >> 44, (owen(b, 1) ^ b) >> 44);
}

TEST(Base2, LinearMatrixScrambleIsLowerTriangularAndLinear) {
  std::mt19937_64 words(31);
  const LinearMatrixScramble lms(12);
  const auto dim = lms.dimension(6);
  int below = 0;
  for (unsigned p = 0; p < 64; ++p) {
    const std::uint64_t column = dim.column(p);
    ASSERT_EQ(column >> p, 1u) << "unit diagonal, nothing above: column " << p;
    below += std::popcount(column) - 1;
  }
  // Random entries below the diagonal: 2016 of them, about half set.
  EXPECT_NEAR(below, 1008, 150);
  for (int trial = 0; trial < 100; ++trial) {
    const std::uint64_t a = words(), b = words();
    ASSERT_EQ(dim.linear(a ^ b), dim.linear(a) ^ dim.linear(b));
    ASSERT_EQ(dim(a), dim.linear(a) ^ dim.shift());
    ASSERT_EQ(lms(a, 6), dim(a));
  }
}

// --- statistics ----------------------------------------------------------

// Unbiasedness of every randomizer on Sobol' points: the mean over 200 seeds
// of the N = 64 estimate matches the exact integral. Student t with 199
// degrees of freedom; 5 randomizers × 2 integrands = 10 tests at a family
// level of 1e-3, so each is two-sided at 1 - (1 - 1e-3)^(1/10) (Šidák).
TEST(Base2, EveryRandomizerGivesUnbiasedEstimates) {
  const int seeds = 200, n = 64;
  const double alpha = 1 - std::pow(1 - 1e-3, 1.0 / 10);
  const double bound = boost::math::quantile(boost::math::students_t(seeds - 1), 1 - alpha / 2);
  const Sobol sobol(3);
  struct Integrand {
    std::string name;
    double exact;
    std::function<double(const double*)> f;
  };
  const std::vector<Integrand> integrands = {
      {"prod(x_j + 0.5), d = 3", 1.0, [](const double* x) { return (x[0] + 0.5) * (x[1] + 0.5) * (x[2] + 0.5); }},
      {"x0 * x1", 0.25, [](const double* x) { return x[0] * x[1]; }},
  };
  using PointMap = std::function<double(std::uint64_t seed, std::uint64_t index, unsigned dim)>;
  const std::vector<std::pair<std::string, PointMap>> randomizers = {
      {"owen", [&](auto s, auto i, unsigned j) { return sobol.sample(i, j, OwenScrambler(s)); }},
      {"owen-hash", [&](auto s, auto i, unsigned j) { return sobol.sample(i, j, HashOwenScrambler(s)); }},
      {"xor", [&](auto s, auto i, unsigned j) { return sobol.sample(i, j, DigitalShift(s)); }},
      {"lms", [&](auto s, auto i, unsigned j) { return sobol.sample(i, j, LinearMatrixScramble(s)); }},
      {"cp", [&](auto s, auto i, unsigned j) { return CranleyPattersonRotation(s)(sobol.sample(i, j), j); }},
  };
  for (const auto& [name, point] : randomizers)
    for (const auto& integrand : integrands) {
      double sum = 0, sum2 = 0;
      for (int s = 0; s < seeds; ++s) {
        double estimate = 0;
        for (int i = 0; i < n; ++i) {
          const double x[3] = {point(s, i, 0), point(s, i, 1), point(s, i, 2)};
          estimate += integrand.f(x);
        }
        estimate /= n;
        sum += estimate;
        sum2 += estimate * estimate;
      }
      const double mean = sum / seeds;
      const double variance = (sum2 - seeds * mean * mean) / (seeds - 1);
      ASSERT_GT(variance, 0) << name << ": the estimates must actually vary";
      const double t = (mean - integrand.exact) / std::sqrt(variance / seeds);
      EXPECT_LT(std::abs(t), bound) << name << " on " << integrand.name << ": mean " << mean;
    }
}

// Owen (exact) and hash-based Owen make a fixed point uniform over seeds,
// in its leading digits and in digits 48-53 (the low end of a double, which
// the unscrambled point at index < 2^32 has all zero). χ² on 64 bins, 63
// degrees of freedom. Also the joint distribution of two dimensions (8 × 8
// bins): the per-dimension keys are decorrelated. 2 scramblers × (2 points ×
// 2 digit windows + 1 joint) = 10 tests at a family level of 1e-3 (Šidák).
TEST(Base2, OwenScramblersMakeAFixedPointUniform) {
  const int seeds = 6400, bins = 64;
  const double alpha = 1 - std::pow(1 - 1e-3, 1.0 / 10);
  const double bound = boost::math::quantile(boost::math::chi_squared(bins - 1), 1 - alpha);
  const Sobol sobol(4);
  auto chi2 = [&](const std::vector<int>& counts) {
    const double expected = static_cast<double>(seeds) / bins;
    double sum = 0;
    for (int c : counts) sum += (c - expected) * (c - expected) / expected;
    return sum;
  };
  using Scramble = std::function<std::uint64_t(std::uint64_t seed, std::uint64_t word, unsigned dim)>;
  const std::vector<std::pair<std::string, Scramble>> scramblers = {
      {"owen", [](auto s, auto w, unsigned j) { return OwenScrambler(s)(w, j); }},
      {"owen-hash", [](auto s, auto w, unsigned j) { return HashOwenScrambler(s)(w, j); }},
  };
  for (const auto& [name, scramble] : scramblers) {
    for (std::uint64_t index : std::initializer_list<std::uint64_t>{5, (std::uint64_t{1} << 32) + 3}) {
      std::vector<int> top(bins, 0), low(bins, 0), joint(bins, 0);
      const std::uint64_t w3 = sobol.bits(index, 3), w2 = sobol.bits(index, 2);
      for (int s = 0; s < seeds; ++s) {
        const std::uint64_t y = scramble(static_cast<std::uint64_t>(s), w3, 3);
        ++top[y >> 58];
        ++low[(y >> 11) & 63];
        if (index == 5) {
          ++joint[((y >> 61) << 3) | (scramble(static_cast<std::uint64_t>(s), w2, 2) >> 61)];
        }
      }
      EXPECT_LT(chi2(top), bound) << name << " index " << index << " leading digits";
      EXPECT_LT(chi2(low), bound) << name << " index " << index << " digits 48-53";
      if (index == 5) {
        EXPECT_LT(chi2(joint), bound) << name << " joint of dimensions 2 and 3";
      }
    }
  }
}

}  // namespace
}  // namespace stratum
