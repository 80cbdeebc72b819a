#include "stratum/patterns/multi_jittered.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "unbiased.hpp"

namespace stratum {
namespace {

std::vector<double> points_of(const MultiJittered& mj) {
  std::vector<double> out(2 * mj.count());
  std::vector<std::uint64_t> scratch(mj.scratch_size());
  mj.generate(out.data(), scratch.data());
  return out;
}

std::vector<double> points_of(const CorrelatedMultiJittered& cmj) {
  std::vector<double> out;
  for (std::uint64_t i = 0; i < cmj.count(); ++i) {
    out.push_back(cmj.sample(i, 0));
    out.push_back(cmj.sample(i, 1));
  }
  return out;
}

std::size_t bin(double v, std::uint64_t cells) {
  return static_cast<std::size_t>(std::floor(v * static_cast<double>(cells)));
}

// Latin in both coordinates (n intervals) and one point per columns × rows stratum.
void expect_multi_jittered(const std::vector<double>& x, std::uint64_t columns, std::uint64_t rows,
                           const std::string& what) {
  const std::uint64_t n = columns * rows;
  ASSERT_EQ(x.size(), 2 * n);
  std::vector<int> in_x(n, 0), in_y(n, 0), strata(n, 0);
  for (std::uint64_t i = 0; i < n; ++i) {
    ASSERT_GE(x[2 * i], 0.0);
    ASSERT_LT(x[2 * i], 1.0);
    ASSERT_GE(x[2 * i + 1], 0.0);
    ASSERT_LT(x[2 * i + 1], 1.0);
    ++in_x[bin(x[2 * i], n)];
    ++in_y[bin(x[2 * i + 1], n)];
    ++strata[bin(x[2 * i + 1], rows) * columns + bin(x[2 * i], columns)];
  }
  for (std::uint64_t k = 0; k < n; ++k) {
    ASSERT_EQ(in_x[k], 1) << what << ": x interval " << k;
    ASSERT_EQ(in_y[k], 1) << what << ": y interval " << k;
    ASSERT_EQ(strata[k], 1) << what << ": stratum " << k;
  }
}

TEST(MultiJittered, LatinAndStratifiedForManyShapes) {
  for (auto [m, k] : std::vector<std::pair<std::uint64_t, std::uint64_t>>{
           {1, 1}, {1, 7}, {4, 4}, {4, 8}, {8, 4}, {3, 5}, {16, 16}, {31, 33}})
    for (std::uint64_t seed : {0ull, 5ull})
      expect_multi_jittered(points_of(MultiJittered(m, k, seed)), m, k, std::to_string(m) + "x" + std::to_string(k));
}

// The construction as Chiu, Shirley and Wang describe it, written out from
// the generator's primitives (shuffles keyed by (seed, column) and (seed,
// row), jitter uniform01(hash64(seed, tag), index, dim)): the chained keys
// and the cells visitors that generate now goes through give these points.
TEST(MultiJittered, EqualsTheConstructionWrittenOut) {
  for (const auto& [m, k] : {std::pair{2ull, 2ull}, {3ull, 5ull}, {1ull, 7ull}, {6ull, 4ull}})
    for (const std::uint64_t seed : {0ull, 9ull, 0xfeedfacecafebeefull}) {
      const std::uint64_t n = m * k;
      std::vector<double> expected(2 * n);
      std::vector<std::uint64_t> perm(std::max(m, k));
      for (std::uint64_t i = 0; i < m; ++i) {
        random_permutation(perm.data(), k, hash64(seed, 0x4d4a58ULL, i));
        for (std::uint64_t j = 0; j < k; ++j)
          expected[2 * (j * m + i)] =
              cell_coordinate(i * k + perm[j], uniform01<double>(hash64(seed, 0x4d4a4a4954ULL), j * m + i, 0), n);
      }
      for (std::uint64_t j = 0; j < k; ++j) {
        random_permutation(perm.data(), m, hash64(seed, 0x4d4a59ULL, j));
        for (std::uint64_t i = 0; i < m; ++i)
          expected[2 * (j * m + i) + 1] =
              cell_coordinate(j * m + perm[i], uniform01<double>(hash64(seed, 0x4d4a4a4954ULL), j * m + i, 1), n);
      }
      EXPECT_EQ(points_of(MultiJittered(m, k, seed)), expected) << m << "x" << k << " seed " << seed;
    }
}

TEST(MultiJittered, ClosestToSquareFactorization) {
  EXPECT_EQ(MultiJittered::closest_to_square(64, 0).columns(), 8u);
  EXPECT_EQ(MultiJittered::closest_to_square(72, 0).columns(), 8u);
  EXPECT_EQ(MultiJittered::closest_to_square(72, 0).rows(), 9u);
  EXPECT_EQ(MultiJittered::closest_to_square(30, 0).columns(), 5u);
  EXPECT_EQ(MultiJittered::closest_to_square(13, 0).columns(), 1u);
  EXPECT_EQ(MultiJittered::closest_to_square(1, 0).rows(), 1u);
}

TEST(MultiJittered, ShufflesDependOnTheSeed) {
  const auto a = points_of(MultiJittered(4, 4, 1)), b = points_of(MultiJittered(4, 4, 2));
  EXPECT_NE(a, b);
  EXPECT_EQ(a, points_of(MultiJittered(4, 4, 1)));
  // The fine column of the point in stratum (0, 0) varies with the seed.
  std::set<std::size_t> fine;
  for (std::uint64_t seed = 0; seed < 40; ++seed) fine.insert(bin(points_of(MultiJittered(4, 4, seed))[0], 16));
  EXPECT_EQ(fine.size(), 4u);
}

// Kensler's permutation is a bijection of {0..l-1} for every l and pattern,
// including the patterns whose 32-bit sum i + p would wrap.
TEST(KenslerPermute, IsABijection) {
  for (std::uint32_t l : {1u, 2u, 3u, 5u, 16u, 17u, 100u, 1000u, 4097u})
    for (std::uint32_t p : {0u, 1u, 12345u, 0x9e3779b9u, 0xfffffffeu, 0xffffffffu}) {
      std::vector<bool> seen(l, false);
      for (std::uint32_t i = 0; i < l; ++i) {
        const std::uint32_t v = kensler_permute(i, l, p);
        ASSERT_LT(v, l);
        ASSERT_FALSE(seen[v]) << "l=" << l << " p=" << p;
        seen[v] = true;
      }
    }
}

// The prepared domain (walk mask and p mod l by a FastDivider) permutes as
// kensler_permute does, for every l kind: 1, powers of two, others, near 2^32.
TEST(KenslerPermute, PreparedDomainsPermuteAlike) {
  for (std::uint32_t l : {1u, 2u, 3u, 4u, 7u, 64u, 100u, 4097u, 65536u, 0x7fffffffu, 0xfffffffeu, 0xffffffffu}) {
    const KenslerDomain domain(l);
    EXPECT_EQ(domain.size(), l);
    for (std::uint32_t p : {0u, 1u, 12345u, 0x9e3779b9u, 0xfffffffeu, 0xffffffffu})
      for (std::uint64_t k = 0; k < 200; ++k) {
        const auto i = static_cast<std::uint32_t>(k < 100 ? k % l : hash64(l, p, k) % l);
        ASSERT_EQ(domain.permute(i, p), kensler_permute(i, l, p)) << "l=" << l << " p=" << p << " i=" << i;
      }
  }
}

// The memo's listings transcribed literally (float arithmetic, 32-bit sums):
// an oracle for the index-addressable double port.
std::uint32_t memo_permute(std::uint32_t i, std::uint32_t l, std::uint32_t p) {
  std::uint32_t w = l - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= p;
    i *= 0xe170893d;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3f;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1 | p >> 27;
    i *= 0x6935fa69;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3;
    i ^= (i & w) >> 2;
    i *= 0xc860a3df;
    i &= w;
    i ^= i >> 5;
  } while (i >= l);
  return (i + p) % l;
}
float memo_randfloat(std::uint32_t i, std::uint32_t p) {
  i ^= p;
  i ^= i >> 17;
  i ^= i >> 10;
  i *= 0xb36534e5;
  i ^= i >> 12;
  i ^= i >> 21;
  i *= 0x93fc4795;
  i ^= 0xdf6e307f;
  i ^= i >> 17;
  i *= 1 | p >> 18;
  return static_cast<float>(i) * (1.0f / 4294967808.0f);
}
std::pair<float, float> memo_cmj(int s, int N, int p, float a = 1.0f) {
  int m = static_cast<int>(std::sqrt(static_cast<float>(N) * a));
  int n = (N + m - 1) / m;
  const auto u = [](int v) { return static_cast<std::uint32_t>(v); };
  s = static_cast<int>(memo_permute(u(s), u(N), u(p) * 0x51633e2d));
  int sx = static_cast<int>(memo_permute(u(s % m), u(m), u(p) * 0x68bc21eb));
  int sy = static_cast<int>(memo_permute(u(s / m), u(n), u(p) * 0x02e5be93));
  float jx = memo_randfloat(u(s), u(p) * 0x967a889b);
  float jy = memo_randfloat(u(s), u(p) * 0x368cc8b7);
  return {(static_cast<float>(sx) + (static_cast<float>(sy) + jx) / static_cast<float>(n)) / static_cast<float>(m),
          (static_cast<float>(s) + jy) / static_cast<float>(N)};
}

TEST(CorrelatedMultiJittered, MatchesKenslersListing) {
  EXPECT_EQ(memo_permute(3, 7, 12345), kensler_permute(3, 7, 12345));
  for (std::uint64_t n : {1ull, 5ull, 16ull, 20ull, 100ull, 1000ull})
    for (std::uint64_t seed : {0ull, 1ull, 2ull, 3ull}) {
      const CorrelatedMultiJittered cmj(n, seed);
      for (std::uint64_t i = 0; i < n; ++i) {
        const auto [x, y] = memo_cmj(static_cast<int>(i), static_cast<int>(n), static_cast<int>(cmj.pattern()));
        ASSERT_NEAR(cmj.sample(i, 0), x, 2e-6) << "n=" << n << " i=" << i;
        ASSERT_NEAR(cmj.sample(i, 1), y, 2e-6) << "n=" << n << " i=" << i;
      }
    }
  // Aspect 2: m = floor(sqrt(2n)) columns.
  const CorrelatedMultiJittered wide(32, 9, 2.0);
  EXPECT_EQ(wide.columns(), 8u);
  EXPECT_EQ(wide.rows(), 4u);
  for (std::uint64_t i = 0; i < 32; ++i)
    ASSERT_NEAR(wide.sample(i, 0), memo_cmj(static_cast<int>(i), 32, static_cast<int>(wide.pattern()), 2.0f).first,
                2e-6);
}

TEST(CorrelatedMultiJittered, LatinAndStratifiedWhenComplete) {
  // squares, m(m+1), aspect 0.5 and 2
  for (auto [n, aspect] : std::vector<std::pair<std::uint64_t, double>>{
           {1, 1}, {16, 1}, {64, 1}, {1024, 1}, {20, 1}, {72, 1}, {32, 0.5}, {32, 2}, {4096, 1}})
    for (std::uint64_t seed : {0ull, 77ull}) {
      const CorrelatedMultiJittered cmj(n, seed, aspect);
      ASSERT_TRUE(cmj.complete()) << n;
      expect_multi_jittered(points_of(cmj), cmj.columns(), cmj.rows(), "cmj n=" + std::to_string(n));
    }
}

// For n < m·k the set stays Latin in y over n intervals and has at most one
// point per stratum and per 1/(m k) interval of x.
TEST(CorrelatedMultiJittered, IncompleteCountsKeepTheirGuarantees) {
  for (std::uint64_t n : {5ull, 7ull, 10ull, 50ull, 1000ull, 10001ull}) {
    const CorrelatedMultiJittered cmj(n, 4);
    ASSERT_FALSE(cmj.complete()) << n;
    const std::uint64_t mk = cmj.columns() * cmj.rows();
    const auto x = points_of(cmj);
    std::vector<int> in_y(n, 0), in_x(mk, 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      ++in_y[bin(x[2 * i + 1], n)];
      ++in_x[bin(x[2 * i], mk)];
    }
    for (int h : in_y) ASSERT_EQ(h, 1) << n;
    for (int h : in_x) ASSERT_LE(h, 1) << n;
  }
}

TEST(CorrelatedMultiJittered, RejectsBadArguments) {
  EXPECT_THROW(CorrelatedMultiJittered(0, 0), invalid_argument);
  EXPECT_THROW(CorrelatedMultiJittered(1ull << 32, 0), invalid_argument);
  EXPECT_THROW(CorrelatedMultiJittered(16, 0, 0.0), invalid_argument);
  EXPECT_THROW(CorrelatedMultiJittered(16, 0, std::nan("")), invalid_argument);
  EXPECT_THROW(MultiJittered(0, 3, 0), invalid_argument);
}

// Multi-jittered and CMJ estimates are unbiased over 400 seeds; family level
// 0.001 over 3 tests (Šidák).
TEST(MultiJittered, UnbiasedOverSeeds) {
  const double alpha = testing::sidak(0.001, 3);
  const double truth = testing::test_integral(2);
  testing::expect_unbiased(
      "multi-jittered 3x5",
      testing::estimates_over_seeds(400, 2, [](std::uint64_t s) { return points_of(MultiJittered(3, 5, s)); }), truth,
      alpha);
  testing::expect_unbiased(
      "cmj 16",
      testing::estimates_over_seeds(400, 2, [](std::uint64_t s) { return points_of(CorrelatedMultiJittered(16, s)); }),
      truth, alpha);
  testing::expect_unbiased(
      "cmj 10",
      testing::estimates_over_seeds(400, 2, [](std::uint64_t s) { return points_of(CorrelatedMultiJittered(10, s)); }),
      truth, alpha);
}

}  // namespace
}  // namespace stratum
