#include "stratum/randomizers/owen_base_b.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <map>
#include <numeric>
#include <vector>

namespace stratum {
namespace {

// 2 (bit flips), ≤ 12 (one-word Fisher–Yates), 13–24 (three words), > 24
// prime (affine ∘ cycle walk), > 24 composite (shift ∘ cycle walk).
const std::vector<std::uint32_t> kBases = {2, 3, 5, 13, 23, 25, 29, 8161, 65536};

double chi_squared_p(double statistic, double dof) {
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), statistic));
}
double sidak(double alpha, int m) { return 1 - std::pow(1 - alpha, 1.0 / m); }
double chi_squared(const std::vector<int>& counts, double expected) {
  double x = 0;
  for (int c : counts) x += (c - expected) * (c - expected) / expected;
  return x;
}

// Oracle: Σ_j π_{j, i mod b^j}(a_j) b^-(j+1) in long double, one node
// permutation image at a time.
long double oracle(const BaseBOwenScrambler& s, unsigned dim, std::uint64_t index) {
  const std::uint32_t b = s.base(dim);
  long double value = 0, scale = 1.0L / b;
  std::uint64_t rest = index, prefix = 0, power = 1;
  for (unsigned j = 0; j < digits_detail::digit_count(b); ++j) {
    const auto digit = static_cast<std::uint32_t>(rest % b);
    value += static_cast<long double>(s.permute_digit(dim, j, prefix, digit)) * scale;
    prefix += digit * power;  // digits past 2^64 are 0, so the wrap of power is harmless
    power *= b;
    rest /= b;
    scale /= b;
  }
  return value;
}

TEST(BaseBOwenScrambler, MatchesTheNodeOracleAtAnyIndex) {
  const BaseBOwenScrambler s(21, kBases);
  for (unsigned dim = 0; dim < kBases.size(); ++dim)
    for (std::uint64_t index : {0ull, 1ull, 2ull, 24ull, 25ull, 4096ull, 99999ull, (1ull << 32) - 1, 1ull << 32,
                                (1ull << 32) + 1, (1ull << 51) + 5, ~0ull}) {
      const long double expected = oracle(s, dim, index);
      EXPECT_LE(s.sample(index, dim), expected) << kBases[dim] << " " << index;
      EXPECT_GT(s.sample(index, dim), expected - 0x1.0p-53L - 0x1.0p-60L) << kBases[dim] << " " << index;
    }
}

TEST(BaseBOwenScrambler, NodePermutationsArePermutationsThatDependOnThePrefix) {
  const BaseBOwenScrambler s(5, kBases);
  for (unsigned dim = 0; dim < kBases.size(); ++dim) {
    const std::uint32_t b = kBases[dim];
    std::vector<std::uint32_t> identity(b);
    std::iota(identity.begin(), identity.end(), 0u);
    std::vector<std::vector<std::uint32_t>> seen;
    for (std::uint64_t prefix = 0; prefix < 4; ++prefix) {
      std::vector<std::uint32_t> images(b);
      for (std::uint32_t a = 0; a < b; ++a) images[a] = s.permute_digit(dim, 3, prefix, a);
      std::vector<std::uint32_t> sorted = images;
      std::sort(sorted.begin(), sorted.end());
      ASSERT_EQ(sorted, identity) << "base " << b << " prefix " << prefix;
      seen.push_back(images);
    }
    if (b > 2) {
      EXPECT_TRUE(seen[0] != seen[1] || seen[0] != seen[2] || seen[0] != seen[3]) << b;
    }
  }
}

// Indices that agree on their lowest v digits and differ at digit v agree on
// the first v output digits and differ at digit v (nets stay nets).
TEST(BaseBOwenScrambler, SharedPrefixesGiveSharedLeadingDigits) {
  const BaseBOwenScrambler s(9, {3, 29});
  for (unsigned dim = 0; dim < 2; ++dim) {
    const double b = dim == 0 ? 3 : 29;
    for (unsigned v = 0; v < 5; ++v)
      for (std::uint64_t i : {0ull, 1ull, 7ull, 100ull}) {
        const auto low = static_cast<std::uint64_t>(std::pow(b, v));
        const std::uint64_t a = i % low, c = a + low * (1 + i % 2);  // digit v: 0 versus 1 or 2
        const double x = s.sample(a, dim), y = s.sample(c, dim);
        const double scale_v = std::pow(b, v), scale_next = scale_v * b;
        EXPECT_EQ(std::floor(x * scale_v), std::floor(y * scale_v)) << dim << " " << a << " " << c;
        EXPECT_NE(std::floor(x * scale_next), std::floor(y * scale_next)) << dim << " " << a << " " << c;
      }
  }
}

// Node permutations over 12000 prefixes (position 9) as a sample of nodes:
// base 5 uniform on all 120 permutations; base 13 (three-word Fisher–Yates)
// and base 29 (affine ∘ cycle walk) uniform on pairs (π(0), π(1)); base 25
// (composite: shift ∘ cycle walk) uniform images π(3). χ² tests at
// family-wise α = 1e-3 (4 tests, Šidák).
TEST(BaseBOwenScrambler, NodePermutationsAreUniform) {
  const BaseBOwenScrambler s(13, {5, 13, 29, 25});
  const double level = sidak(1e-3, 4);
  const int nodes = 12000;
  std::map<std::vector<std::uint32_t>, int> perms5;
  std::vector<int> pairs13(13 * 13, 0), pairs29(29 * 29, 0), images25(25, 0);
  for (std::uint64_t prefix = 0; prefix < nodes; ++prefix) {
    std::vector<std::uint32_t> p(5);
    for (std::uint32_t a = 0; a < 5; ++a) p[a] = s.permute_digit(0, 9, prefix, a);
    ++perms5[p];
    ++pairs13[s.permute_digit(1, 9, prefix, 0) * 13 + s.permute_digit(1, 9, prefix, 1)];
    ++pairs29[s.permute_digit(2, 9, prefix, 0) * 29 + s.permute_digit(2, 9, prefix, 1)];
    ++images25[s.permute_digit(3, 9, prefix, 3)];
  }
  std::vector<int> counts5;
  for (const auto& [perm, count] : perms5) counts5.push_back(count);
  counts5.resize(120, 0);
  EXPECT_GT(chi_squared_p(chi_squared(counts5, nodes / 120.0), 119), level);
  auto off_diagonal = [](const std::vector<int>& pairs, int b) {
    std::vector<int> cells;
    for (int u = 0; u < b; ++u)
      for (int v = 0; v < b; ++v) {
        if (u == v) EXPECT_EQ(pairs[static_cast<std::size_t>(u * b + v)], 0);
        else cells.push_back(pairs[static_cast<std::size_t>(u * b + v)]);
      }
    return cells;
  };
  EXPECT_GT(chi_squared_p(chi_squared(off_diagonal(pairs13, 13), nodes / 156.0), 155), level);
  EXPECT_GT(chi_squared_p(chi_squared(off_diagonal(pairs29, 29), nodes / 812.0), 811), level);
  EXPECT_GT(chi_squared_p(chi_squared(images25, nodes / 25.0), 24), level);
}

// The nodes that share a prefix draw their shifts π(0) from that prefix's
// words: the shifts of two positions must still be independent, whether
// they come from one word, from the two sides of a word boundary (D(3) = 18,
// D(13) = 8, D(29) = 6) or from words apart. 20000 prefixes, the pair
// (π_{j1,p}(0), π_{j2,p}(0)) against uniform on b² cells; 9 χ² tests at
// family-wise α = 1e-3 (Šidák).
TEST(BaseBOwenScrambler, ShiftsSharingAPrefixAreIndependent) {
  struct Pair {
    unsigned dim, j1, j2;
  };
  const std::vector<std::uint32_t> bases = {2, 3, 13, 29};
  const std::vector<Pair> pairs = {{0, 20, 21}, {0, 20, 63}, {1, 10, 11}, {1, 17, 18}, {1, 10, 40},
                                   {2, 6, 7},   {2, 7, 8},   {3, 5, 6},   {3, 3, 13}};
  const BaseBOwenScrambler s(17, bases);
  const double level = sidak(1e-3, static_cast<int>(pairs.size()));
  const int prefixes = 20000;  // every prefix p < b^j1: a node at both positions
  for (const Pair& pair : pairs) {
    const std::uint32_t b = bases[pair.dim];
    ASSERT_GE(std::pow(double(b), pair.j1), double(prefixes));
    std::vector<int> counts(std::size_t{b} * b, 0);
    for (std::uint64_t p = 0; p < prefixes; ++p)
      ++counts[s.permute_digit(pair.dim, pair.j1, p, 0) * b + s.permute_digit(pair.dim, pair.j2, p, 0)];
    EXPECT_GT(chi_squared_p(chi_squared(counts, prefixes / double(b * b)), double(b * b - 1)), level)
        << "base " << b << " positions " << pair.j1 << ", " << pair.j2;
  }
}

// A point's digits past its last nonzero one are summed a word at a time:
// the value must equal the node-by-node sum for indices whose digit count
// ends anywhere in a word (base 3: D = 18, K = 41; base 5: D = 12, K = 28).
TEST(BaseBOwenScrambler, TailSumsEqualTheNodesAtEveryDigitCount) {
  const BaseBOwenScrambler s(33, {3, 5, 65536});
  for (unsigned dim = 0; dim < 3; ++dim) {
    const std::uint32_t b = s.base(dim);
    std::uint64_t top = 1;  // b^k: the first index with k + 1 digits
    for (unsigned k = 0; k < digits_detail::digit_count(b); ++k) {
      // b^k, b^k + 1 and the last index with k + 1 digits (b^(k+1) − 1, or 2^64 − 1)
      const std::uint64_t last = top > ~std::uint64_t{0} / b ? ~std::uint64_t{0} : top * b - 1;
      for (std::uint64_t index : {top, top + 1, last}) {
        const long double expected = oracle(s, dim, index);
        EXPECT_LE(s.sample(index, dim), expected) << b << " " << index;
        EXPECT_GT(s.sample(index, dim), expected - 0x1.0p-53L - 0x1.0p-60L) << b << " " << index;
      }
      if (top > ~std::uint64_t{0} / b) break;
      top *= b;
    }
  }
}

TEST(BaseBOwenScrambler, FirstBToTheKPointsStratifyTheUnitInterval) {
  const BaseBOwenScrambler s(2, {2, 3, 5, 29});
  for (unsigned dim = 0; dim < 4; ++dim) {
    const std::uint32_t b = s.base(dim);
    for (std::uint64_t count = b; count <= 2500; count *= b) {
      std::vector<int> hits(count, 0);
      for (std::uint64_t i = 0; i < count; ++i) ++hits[static_cast<std::size_t>(s.sample(i, dim) * count)];
      for (int h : hits) ASSERT_EQ(h, 1) << "base " << b << " count " << count;
    }
  }
}

// For a fixed index the scrambled coordinate is uniform over seeds: 2000
// seeds, 20 bins, χ² with 19 dof; 4 indices × 5 bases = 20 tests at
// family-wise α = 1e-3 (Šidák).
TEST(BaseBOwenScrambler, EachCoordinateIsUniformOverSeeds) {
  const std::vector<std::uint32_t> bases = {2, 3, 13, 29, 8161};
  const std::vector<std::uint64_t> indices = {0, 1, 1000, (1ull << 35) + 3};
  const double level = sidak(1e-3, static_cast<int>(bases.size() * indices.size()));
  const int seeds = 2000, bins = 20;
  std::vector<std::vector<int>> counts(bases.size() * indices.size(), std::vector<int>(bins, 0));
  for (int seed = 0; seed < seeds; ++seed) {
    const BaseBOwenScrambler s(static_cast<std::uint64_t>(seed), bases);
    for (std::size_t k = 0; k < indices.size(); ++k)
      for (unsigned dim = 0; dim < bases.size(); ++dim)
        ++counts[k * bases.size() + dim][static_cast<std::size_t>(s.sample(indices[k], dim) * bins)];
  }
  for (std::size_t t = 0; t < counts.size(); ++t)
    EXPECT_GT(chi_squared_p(chi_squared(counts[t], seeds / double(bins)), bins - 1), level)
        << "index " << indices[t / bases.size()] << " base " << bases[t % bases.size()];
}

TEST(BaseBOwenScrambler, DeterministicAndFloatIsTheRoundedDouble) {
  const BaseBOwenScrambler a(4, kBases), b(4, kBases);
  for (unsigned dim = 0; dim < kBases.size(); ++dim)
    for (std::uint64_t i = 600; i-- > 0;) {
      const double x = a.sample(i, dim);
      ASSERT_EQ(x, b.sample(i, dim));
      ASSERT_EQ(a.sample<float>(i, dim), to_unit_float(x));
      ASSERT_LT(x, 1.0);
    }
  EXPECT_NE(BaseBOwenScrambler(5, kBases).sample(3, 1), a.sample(3, 1));
}

TEST(BaseBOwenScrambler, RejectsBadBases) {
  EXPECT_THROW(BaseBOwenScrambler(1, {}), invalid_argument);
  EXPECT_THROW(BaseBOwenScrambler(1, {1}), invalid_argument);
  EXPECT_THROW(BaseBOwenScrambler(1, {70000}), invalid_argument);
}

}  // namespace
}  // namespace stratum
