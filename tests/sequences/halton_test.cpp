#include "stratum/sequences/halton.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/randomizers/digital_shift_base_b.hpp"
#include "stratum/randomizers/owen_base_b.hpp"
#include "stratum/registry.hpp"
#include "../registry/registry_points.hpp"

namespace stratum {
namespace {

TEST(Halton, UsesTheFirstPrimesAsBases) {
  EXPECT_EQ(Halton::base(0), 2u);
  EXPECT_EQ(Halton::base(1), 3u);
  EXPECT_EQ(Halton::base(2), 5u);
  EXPECT_EQ(Halton::base(999), 7919u);  // the 1000th prime
  const Halton halton(3);
  EXPECT_DOUBLE_EQ(halton.sample(5, 0), 0.625);
  EXPECT_DOUBLE_EQ(halton.sample(5, 1), 2.0 / 3 + 1.0 / 9);
  EXPECT_DOUBLE_EQ(halton.sample(5, 2), 1.0 / 25);
}

TEST(Halton, RejectsBadDimensions) {
  EXPECT_THROW(Halton(0), invalid_argument);
  EXPECT_THROW(Halton(Halton::max_dimensions + 1), invalid_argument);
  EXPECT_NO_THROW(Halton(1000));
}

// Halton in bases (2, 3): the first 2^i 3^j points have one point in every
// box of size 2^-i × 3^-j (mixed-base elementary intervals).
TEST(Halton, MixedBaseElementaryIntervals) {
  const Halton halton(2);
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 4; ++j) {
      const int nx = 1 << i, ny = static_cast<int>(std::pow(3, j));
      std::vector<int> hits(static_cast<std::size_t>(nx * ny), 0);
      for (int k = 0; k < nx * ny; ++k) {
        // Points lie on the grid corners exactly; nudge by 1e-9 so a value
        // rounded just below a boundary k / 3^j is counted in its own box.
        const int bx = static_cast<int>(halton.sample(k, 0) * nx + 1e-9);
        const int by = static_cast<int>(halton.sample(k, 1) * ny + 1e-9);
        ++hits[static_cast<std::size_t>(by * nx + bx)];
      }
      for (int h : hits) ASSERT_EQ(h, 1) << "2^" << i << " x 3^" << j;
    }
}

TEST(Hammersley, FirstDimensionIsIOverN) {
  const Hammersley hammersley(16, 3);
  EXPECT_EQ(hammersley.sample(4, 0), 0.25);
  EXPECT_EQ(hammersley.sample(4, 1), 0.125);
  EXPECT_DOUBLE_EQ(hammersley.sample(4, 2), 1.0 / 3 + 1.0 / 9);
  EXPECT_THROW(Hammersley(0, 2), invalid_argument);
}

// Hammersley with N = 2^i 3^j in dimensions (0, 2): every 2^-a × 3^-b box
// with 2^a 3^b = N... dimension 0 is i/N, so any box of N equal columns and
// one row holds one point; with dimension 1 (base 2) at N = 2^k it is a (0,k,2)-net.
TEST(Hammersley, BaseTwoNetAtPowersOfTwo) {
  for (int k = 1; k <= 10; ++k) {
    const std::uint64_t n = 1ull << k;
    const Hammersley hammersley(n, 2);
    for (int i = 0; i <= k; ++i) {
      const std::uint64_t nx = 1ull << i, ny = 1ull << (k - i);
      std::vector<int> hits(n, 0);
      for (std::uint64_t p = 0; p < n; ++p)
        ++hits[static_cast<std::size_t>(hammersley.sample(p, 1) * ny) * nx +
               static_cast<std::size_t>(hammersley.sample(p, 0) * nx)];
      for (int h : hits) ASSERT_EQ(h, 1);
    }
  }
}

// ---- The registry's randomized Halton and Hammersley points ----

PointSet registry_points(const std::string& name, std::uint64_t n, unsigned d, const std::string& randomize,
                         std::uint64_t seed, std::uint64_t start = 0) {
  return testing::sampler_points(name, n, d, randomize, seed, start);
}

const std::vector<std::string> kDigitRandomizers = {"none", "permute", "owen", "xor"};

TEST(HaltonRegistry, OffersTheBaseBRandomizersWithPermuteFirst) {
  const std::vector<std::string> expected = {"permute", "none", "owen", "xor", "cp"};
  EXPECT_EQ(find_sampler("halton").randomizers, expected);
  EXPECT_EQ(find_sampler("hammersley").randomizers, expected);
  const PointSet by_default = registry_points("halton", 100, 3, "", 5);
  const PointSet permuted = registry_points("halton", 100, 3, "permute", 5);
  for (std::size_t k = 0; k < 300; ++k) ASSERT_EQ(by_default.data[k], permuted.data[k]);
}

// The first 2^i 3^j points put one point in every 2^-i × 3^-j box of
// dimensions (0, 1), and the first 2^i 5^j one in every 2^-i × 5^-j box of
// dimensions (0, 2), for the unscrambled points and every digit randomizer.
TEST(HaltonRegistry, MixedBaseElementaryIntervalsSurviveDigitRandomizers) {
  for (const std::string& randomize : kDigitRandomizers)
    for (std::uint64_t seed : {1ull, 2ull}) {
      const PointSet p = registry_points("halton", 1000, 3, randomize, seed);
      // Unscrambled points sit on box corners: nudge them inside (see above).
      const double nudge = randomize == "none" ? 1e-9 : 0.0;
      for (unsigned dim : {1u, 2u}) {
        const int base = dim == 1 ? 3 : 5;
        for (int i = 0; i <= 5; ++i)
          for (int j = 0; j <= (dim == 1 ? 3 : 2); ++j) {
            const int nx = 1 << i, ny = static_cast<int>(std::pow(base, j)), count = nx * ny;
            std::vector<int> hits(static_cast<std::size_t>(count), 0);
            for (int k = 0; k < count; ++k) {
              const int bx = static_cast<int>(p(static_cast<std::size_t>(k), 0) * nx + nudge);
              const int by = static_cast<int>(p(static_cast<std::size_t>(k), dim) * ny + nudge);
              ++hits[static_cast<std::size_t>(by * nx + bx)];
            }
            for (int h : hits)
              ASSERT_EQ(h, 1) << randomize << " seed " << seed << ": 2^" << i << " x " << base << "^" << j;
          }
      }
    }
}

// Cranley–Patterson rotation moves the points off the digit grid but keeps
// every coordinate's 1D stratification: the first b^k points, one per
// interval [t/b^k, (t+1)/b^k).
TEST(HaltonRegistry, CranleyPattersonKeepsOneDimensionalStratification) {
  const PointSet p = registry_points("halton", 3125, 3, "cp", 17);
  const PointSet plain = registry_points("halton", 3125, 3, "none", 17);
  for (unsigned dim = 0; dim < 3; ++dim) {
    const std::uint64_t base = prime(dim);
    const CranleyPattersonRotation rotation(17);
    EXPECT_EQ(p(7, dim), rotation(plain(7, dim), dim));
    for (std::uint64_t count = base; count <= 3125; count *= base) {
      std::vector<int> hits(count, 0);
      for (std::uint64_t k = 0; k < count; ++k) ++hits[static_cast<std::size_t>(p(k, dim) * count)];
      for (int h : hits) ASSERT_EQ(h, 1) << "base " << base << " count " << count;
    }
  }
}

// request.start offsets the index, also past 2^32, for every randomizer: the
// registry's points are the core randomizers' samples at start + k.
TEST(HaltonRegistry, StartOffsetsTheIndexForEveryRandomizer) {
  const std::uint64_t start = (1ull << 32) + 5, seed = 3;
  const std::vector<std::uint32_t> bases = {2, 3, 5};
  const RandomDigitPermutations permute(seed, bases);
  const BaseBDigitalShift shift(seed, bases);
  const BaseBOwenScrambler owen(seed, bases);
  const CranleyPattersonRotation rotation(seed);
  const Halton halton(3);
  for (const std::string randomize : {"permute", "none", "owen", "xor", "cp"}) {
    const PointSet p = registry_points("halton", 40, 3, randomize, seed, start);
    for (std::uint64_t k = 0; k < 40; ++k)
      for (unsigned dim = 0; dim < 3; ++dim) {
        const std::uint64_t i = start + k;
        const double expected = randomize == "permute" ? permute.sample(i, dim)
                                : randomize == "xor"   ? shift.sample(i, dim)
                                : randomize == "owen"  ? owen.sample(i, dim)
                                : randomize == "cp"    ? rotation(halton.sample(i, dim), dim)
                                                       : halton.sample(i, dim);
        ASSERT_EQ(p(k, dim), expected) << randomize << " " << k << " " << dim;
      }
    const PointSet later = registry_points("halton", 10, 3, randomize, seed, start + 30);
    for (std::size_t k = 0; k < 30; ++k) ASSERT_EQ(later.data[k], p.data[90 + k]) << randomize;
  }
}

// Unbiasedness: over seeds, the mean of Q = (1/50) Σ f(x_k) with
// f = x0 · x1² · exp(x2), ∫f = (e − 1)/6, matches the integral. 300 seeds, a
// two-sided t-test on the seeds' sample variance for 5 cases (4 Halton
// randomizers and Hammersley cp) at family-wise α = 1e-3 (Šidák).
TEST(HaltonRegistry, EstimatesAreUnbiasedOverSeeds) {
  const int seeds = 300;
  const double exact = (std::exp(1.0) - 1) / 6;
  const double level = 1 - std::pow(1 - 1e-3, 1.0 / 5);
  const double t_crit = boost::math::quantile(boost::math::students_t(seeds - 1), 1 - level / 2);
  for (const auto& [name, randomize] : std::vector<std::pair<std::string, std::string>>{
           {"halton", "permute"}, {"halton", "owen"}, {"halton", "xor"}, {"halton", "cp"}, {"hammersley", "cp"}}) {
    double sum = 0, sum2 = 0;
    for (int seed = 0; seed < seeds; ++seed) {
      const PointSet p = registry_points(name, 50, 3, randomize, static_cast<std::uint64_t>(seed) + 1000);
      double q = 0;
      for (std::size_t k = 0; k < 50; ++k) q += p(k, 0) * p(k, 1) * p(k, 1) * std::exp(p(k, 2));
      q /= 50;
      sum += q;
      sum2 += q * q;
    }
    const double mean = sum / seeds, variance = (sum2 - seeds * mean * mean) / (seeds - 1);
    EXPECT_GT(variance, 0) << name << " " << randomize;
    EXPECT_LT(std::fabs(mean - exact), t_crit * std::sqrt(variance / seeds)) << name << " " << randomize;
  }
}

// Hammersley's dimension 0, i/N, is kept only by none: the digit randomizers
// scramble its binary digits (Latin at N = 2^k), cp rotates it (Latin at any
// N); its other dimensions are Halton's dimensions 0..d−2 with the same seed
// and randomizer.
TEST(HammersleyRegistry, DimensionZeroIsRandomizedAndTheRestIsHalton) {
  for (const std::string& randomize : kDigitRandomizers) {
    const PointSet h = registry_points("hammersley", 256, 4, randomize, 8);
    const PointSet halton = registry_points("halton", 256, 3, randomize, 8);
    std::vector<int> hits(256, 0);
    bool moved = false;
    for (std::size_t k = 0; k < 256; ++k) {
      moved = moved || h(k, 0) != static_cast<double>(k) / 256;
      ++hits[static_cast<std::size_t>(h(k, 0) * 256)];
      for (unsigned dim = 1; dim < 4; ++dim) ASSERT_EQ(h(k, dim), halton(k, dim - 1)) << randomize;
    }
    EXPECT_EQ(moved, randomize != "none") << randomize;
    for (int c : hits) ASSERT_EQ(c, 1) << randomize;
  }
  EXPECT_EQ(registry_points("hammersley", 10, 1, "none", 8)(3, 0), 0.3);
  EXPECT_NE(registry_points("hammersley", 10, 1, "permute", 8)(3, 0), 0.3);
  const PointSet rotated = registry_points("hammersley", 300, 2, "cp", 8);
  std::vector<int> hits(300, 0);
  for (std::size_t k = 0; k < 300; ++k) ++hits[static_cast<std::size_t>(rotated(k, 0) * 300)];
  for (int h : hits) ASSERT_EQ(h, 1);
  EXPECT_NE(rotated(0, 0), 0.0);
}

// Hammersley at N = 3^5 with dimensions (0, 2) (base 3): every box
// 3^-a × 3^-(5−a) holds one point unrandomized. (The digit randomizers scramble
// i/N in base 2, so they keep the boxes of dimensions (0, 1) at N = 2^k, see
// tests/registry/samplers_sequences_test.cpp, not these.)
TEST(HammersleyRegistry, ElementaryIntervalsAtPowersOfTheBase) {
  for (const std::string randomize : {"none"}) {
    const PointSet p = registry_points("hammersley", 243, 3, randomize, 4);
    // i/N and unscrambled radical inverses sit on box corners: nudge inside.
    const double nudge = randomize == "none" ? 1e-9 : 0.0;
    for (int a = 0; a <= 5; ++a) {
      const int nx = static_cast<int>(std::pow(3, a)), ny = 243 / nx;
      std::vector<int> hits(243, 0);
      for (std::size_t k = 0; k < 243; ++k)
        ++hits[static_cast<std::size_t>(static_cast<int>(p(k, 2) * ny + nudge) * nx +
                                        static_cast<int>(p(k, 0) * nx + 1e-9))];
      for (int h : hits) ASSERT_EQ(h, 1) << randomize << " a = " << a;
    }
  }
}

}  // namespace
}  // namespace stratum
