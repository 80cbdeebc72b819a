#include "stratum/sequences/sobol.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <boost/random/detail/sobol_table.hpp>
#include <boost/random/sobol.hpp>
#include <cstring>
#include <initializer_list>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "stratum/randomizers/base2.hpp"
#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/registry.hpp"
#include "stratum/sequences/radical_inverse.hpp"

namespace stratum {
namespace {

constexpr std::uint64_t two32 = std::uint64_t{1} << 32;
using u64s = std::initializer_list<std::uint64_t>;

// C · digits by brute force: one column per set bit, the Gray code written out.
std::uint64_t brute_force_bits(const Sobol& sobol, std::uint64_t index, unsigned dim, bool gray = true) {
  const std::uint64_t digits = gray ? (index ^ (index / 2)) : index;
  std::uint64_t x = 0;
  for (unsigned c = 0; c < 64; ++c)
    if ((digits >> c) & 1) x ^= sobol.direction(dim, c);
  return x;
}

TEST(Sobol, EqualsBoostRandomSobolBitForBit) {
  // Boost's engine skips the origin: its k-th vector is our point k + 1.
  // Boost's sobol is a 64-bit engine, so all 64 bits are compared (the
  // brief asks for the top 32; the low 32 agree as well).
  const unsigned d = 64;
  const Sobol sobol(d);
  boost::random::sobol engine(d);
  for (unsigned j = 0; j < d; ++j) ASSERT_EQ(sobol.bits(0, j), 0u);
  for (std::uint64_t i = 1; i <= 4096; ++i)
    for (unsigned j = 0; j < d; ++j) ASSERT_EQ(sobol.bits(i, j), engine()) << "point " << i << " dim " << j;
}

// Boost.Random ships the first 3667 Joe-Kuo dimensions: the check on the
// 21201-dimension table generated from scipy's copy.
constexpr unsigned boost_dimensions = boost::random::detail::qrng_tables::sobol::max_dimension;

TEST(Sobol, TableEqualsBoostsJoeKuoTableWhereItHasOne) {
  using boost_table = boost::random::detail::qrng_tables::sobol;
  ASSERT_EQ(boost_dimensions, 3667u);
  EXPECT_EQ(sobol_joe_kuo::directions(0).degree, 0u);
  for (unsigned dim = 1; dim < boost_dimensions; ++dim) {
    const auto table = sobol_joe_kuo::directions(dim);
    ASSERT_EQ(table.polynomial, boost_table::polynomial(dim - 1)) << dim;
    ASSERT_EQ(table.degree, unsigned(std::bit_width(table.polynomial)) - 1) << dim;
    for (unsigned k = 0; k < boost_table::max_degree; ++k)
      ASSERT_EQ(k < table.degree ? table.m[k] : 0u, boost_table::minit(dim - 1, k)) << dim << " " << k;
  }
}

TEST(Sobol, TableRecordsAreJoeKuoShaped) {
  // Every dimension: a polynomial of the stated degree with a_0 = 1, degrees
  // ascending, m_k odd and below 2^k; the last dimension's values as in
  // new-joe-kuo-6.21201 (dimension 21201 there: s = 18, a = 115799).
  unsigned previous = 0;
  for (unsigned dim = 1; dim < Sobol::max_dimensions; ++dim) {
    const auto table = sobol_joe_kuo::directions(dim);
    ASSERT_EQ(unsigned(std::bit_width(table.polynomial)) - 1, table.degree) << dim;
    ASSERT_EQ(table.polynomial & 1u, 1u) << dim;
    ASSERT_GE(table.degree, previous) << dim;
    previous = table.degree;
    for (unsigned k = 1; k <= table.degree; ++k) {
      ASSERT_EQ(table.m[k - 1] % 2, 1u) << dim << " " << k;
      ASSERT_LT(table.m[k - 1], 1u << k) << dim << " " << k;
    }
  }
  const auto last = sobol_joe_kuo::directions(21200);
  EXPECT_EQ(last.degree, 18u);
  EXPECT_EQ(last.polynomial, 524263u);  // 2^18 + 2 * 115799 + 1
  const std::uint32_t m[18] = {1,   1,    7,    11,   15,   7,     37,    239,    337,
                               245, 1557, 3681, 7357, 9639, 27367, 26869, 114603, 86317};
  for (unsigned k = 0; k < 18; ++k) EXPECT_EQ(last.m[k], m[k]) << k;
}

TEST(Sobol, EqualsBoostInAllOfBoostsDimensions) {
  const Sobol sobol(boost_dimensions);
  boost::random::sobol engine(boost_dimensions);
  for (std::uint64_t i = 1; i <= 16; ++i)
    for (unsigned j = 0; j < boost_dimensions; ++j) ASSERT_EQ(sobol.bits(i, j), engine()) << i << " " << j;
}

TEST(Sobol, RejectsDimensionsOutsideTheTable) {
  EXPECT_EQ(Sobol::max_dimensions, 21201u);
  EXPECT_THROW(Sobol(0), invalid_argument);
  try {
    Sobol sobol(21202);
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "d");
    EXPECT_NE(std::string(e.what()).find("21202"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("1 to 21201"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("Joe-Kuo"), std::string::npos);
  }
}

// Dimension 0 is van der Corput; the first points of dimension 1 are the
// textbook ones (Joe-Kuo dimension 2: 1/2, 3/4, 1/4, 5/8 in natural order).
TEST(Sobol, ReferenceValues) {
  const Sobol gray(2), natural(2, Sobol::Order::natural);
  for (std::uint64_t i = 0; i < 1000; ++i) {
    ASSERT_EQ(natural.sample(i, 0), radical_inverse(2, i));
    ASSERT_EQ(gray.sample(i, 0), radical_inverse(2, Sobol::gray_code(i)));
  }
  const double first[] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (std::uint64_t i = 0; i < 8; ++i) EXPECT_EQ(natural.sample(i, 1), first[i]) << i;
  EXPECT_EQ(gray.sample(2, 1), 0.25);  // gray(2) = 3: 1/2 xor 3/4
  EXPECT_EQ(gray.sample(3, 1), 0.75);  // gray(3) = 2
}

// Past 2^32 the index does not wrap: point 2^32 + i differs from point i,
// equals the brute-force GF(2) product and Boost's engine seeded there.
TEST(Sobol, IndicesPastTwoToThe32DoNotWrap) {
  const unsigned d = 8;
  const Sobol sobol(d);
  boost::random::sobol engine(d);
  for (std::uint64_t i : u64s{0, 1, 2, 3, 1000, 123456}) {
    const std::uint64_t index = two32 + i;
    engine.seed(index - 1);
    for (unsigned j = 0; j < d; ++j) {
      const std::uint64_t far = sobol.bits(index, j);
      EXPECT_NE(far, sobol.bits(i, j)) << i << " " << j;
      EXPECT_EQ(far, brute_force_bits(sobol, index, j));
      EXPECT_EQ(far, engine());
      const double x = sobol.sample(index, j);
      EXPECT_NE(x, sobol.sample(i, j)) << "differs in the top 53 bits, not just below";
      EXPECT_GE(x, 0.0);
      EXPECT_LT(x, 1.0);
    }
  }
  // The largest index: every column is used, output still in [0, 1).
  const std::uint64_t last = ~std::uint64_t{0};
  for (unsigned j = 0; j < d; ++j) {
    EXPECT_EQ(sobol.bits(last, j), brute_force_bits(sobol, last, j));
    EXPECT_LT(sobol.sample(last, j), 1.0);
    EXPECT_LT(sobol.sample<float>(last, j), 1.0f);
  }
}

TEST(Sobol, DoubleAndFloatAreTheTopBits) {
  const Sobol sobol(4);
  for (std::uint64_t i : u64s{1, 77, two32 + 5, ~0ull}) {
    const std::uint64_t w = sobol.bits(i, 3);
    EXPECT_EQ(sobol.sample(i, 3), static_cast<double>(w >> 11) * 0x1p-53);
    EXPECT_EQ(sobol.sample<float>(i, 3), static_cast<float>(w >> 40) * 0x1p-24f);
  }
}

TEST(Sobol, ReversedBitsAndStepsAgree) {
  for (auto order : {Sobol::Order::gray, Sobol::Order::natural}) {
    const Sobol sobol(16, order);
    for (unsigned j = 0; j < 16; ++j) {
      std::uint64_t x = sobol.bits(0, j);
      for (std::uint64_t i = 1; i < 3000; ++i) {
        x ^= sobol.step(i, j);
        ASSERT_EQ(x, sobol.bits(i, j));
        ASSERT_EQ(sobol.reversed_bits(i, j), reverse_bits64(x));
        ASSERT_EQ(x, brute_force_bits(sobol, i, j, order == Sobol::Order::gray));
      }
    }
  }
}

// Gray block [m 2^k, (m+1) 2^k) holds the points of natural block gray(m);
// in particular every power-of-two prefix is the same set in both orders.
TEST(Sobol, GrayBlocksAreNaturalBlocksOfTheGrayCode) {
  const Sobol gray(5), natural(5, Sobol::Order::natural);
  for (std::uint64_t block : u64s{0, 1, 3, 6, (two32 >> 6) + 1}) {
    for (unsigned j = 0; j < 5; ++j) {
      std::vector<std::uint64_t> a, b;
      for (std::uint64_t i = 0; i < 64; ++i) {
        a.push_back(gray.bits(block * 64 + i, j));
        b.push_back(natural.bits(Sobol::gray_code(block) * 64 + i, j));
      }
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      EXPECT_EQ(a, b) << "block " << block << " dim " << j;
    }
  }
}

// Replaying (index, dim) pairs in any order gives the same bits, with and
// without randomizers (no hidden state).
TEST(Sobol, DeterministicUnderReplayInAnyOrder) {
  const Sobol sobol(32);
  const HashOwenScrambler owen(11);
  std::vector<std::pair<std::uint64_t, unsigned>> calls;
  for (std::uint64_t i = 0; i < 200; ++i)
    for (unsigned j = 0; j < 32; ++j) calls.emplace_back(i * 7919 + (i % 3) * two32, j);
  std::vector<std::uint64_t> first;
  std::vector<double> scrambled;
  for (auto [i, j] : calls) {
    first.push_back(sobol.bits(i, j));
    scrambled.push_back(sobol.sample(i, j, owen));
  }
  std::vector<std::size_t> order(calls.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(5));
  const Sobol again(32);
  for (std::size_t k : order) {
    ASSERT_EQ(again.bits(calls[k].first, calls[k].second), first[k]);
    ASSERT_EQ(again.sample(calls[k].first, calls[k].second, HashOwenScrambler(11)), scrambled[k]);
  }
}

// The generic sample(index, dim, r) equals the randomizer applied to bits().
TEST(Sobol, SampleWithRandomizerAppliesItToTheBits) {
  const Sobol sobol(6);
  const HashOwenScrambler hash(3);
  const OwenScrambler owen(3);
  const DigitalShift shift(3);
  const LinearMatrixScramble lms(3);
  for (std::uint64_t i : u64s{0, 9, 4097, two32 + 9}) {
    for (unsigned j = 0; j < 6; ++j) {
      const std::uint64_t w = sobol.bits(i, j);
      EXPECT_EQ(sobol.sample(i, j, hash), bits_to_double(hash(w, j)));
      EXPECT_EQ(sobol.sample(i, j, hash.dimension(j)), bits_to_double(hash(w, j)));
      EXPECT_EQ(sobol.sample<float>(i, j, hash), bits_to_float(hash(w, j)));
      EXPECT_EQ(sobol.sample(i, j, owen), bits_to_double(owen(w, j)));
      EXPECT_EQ(sobol.sample(i, j, shift), bits_to_double(w ^ shift.shift(j)));
      EXPECT_EQ(sobol.sample(i, j, lms.dimension(j)), bits_to_double(lms(w, j)));
      EXPECT_EQ(sobol.sample(i, j, NoRandomizer{}), sobol.sample(i, j));
    }
  }
}

// --- elementary intervals ------------------------------------------------

// Counts of the first n points in the 2^a × 2^b boxes of dims (x, y).
std::vector<int> box_counts(const std::vector<std::uint64_t>& xs, const std::vector<std::uint64_t>& ys, std::size_t n,
                            unsigned a, unsigned b) {
  std::vector<int> counts(std::size_t{1} << (a + b), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t bx = a == 0 ? 0 : xs[i] >> (64 - a);
    const std::uint64_t by = b == 0 ? 0 : ys[i] >> (64 - b);
    ++counts[(by << a) | bx];
  }
  return counts;
}

template <class Randomizer>
std::vector<std::uint64_t> words(const Sobol& sobol, unsigned dim, std::size_t n, const Randomizer& r) {
  std::vector<std::uint64_t> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = r(sobol.bits(i, dim), dim);
  return out;
}

// At N = 2^k (k = 2..12) dims (0, 1) are a (0,k,2)-net: one point in every
// 2^-i × 2^-(k-i) box, unscrambled and after every digital randomizer. Other
// pairs are (t,k,2)-nets with t > 0; a digital scramble maps each dyadic
// interval onto one of the same length, so the multiset of box counts is
// exactly that of the unscrambled points.
TEST(Sobol, ElementaryIntervalsUnderEveryDigitalRandomizer) {
  const Sobol sobol(64);
  const std::size_t n_max = 4096;
  const std::pair<unsigned, unsigned> pairs[] = {{0, 1}, {2, 3}, {5, 17}, {31, 63}};
  for (auto [dx, dy] : pairs) {
    const auto plain_x = words(sobol, dx, n_max, NoRandomizer{});
    const auto plain_y = words(sobol, dy, n_max, NoRandomizer{});
    auto check = [&](const std::string& name, const auto& r) {
      const auto xs = words(sobol, dx, n_max, r);
      const auto ys = words(sobol, dy, n_max, r);
      for (unsigned k = 2; k <= 12; ++k)
        for (unsigned i = 0; i <= k; ++i) {
          auto got = box_counts(xs, ys, std::size_t{1} << k, i, k - i);
          if (dx == 0 && dy == 1) {
            for (int c : got) ASSERT_EQ(c, 1) << name << " k=" << k << " i=" << i;
          } else {
            auto want = box_counts(plain_x, plain_y, std::size_t{1} << k, i, k - i);
            std::sort(got.begin(), got.end());
            std::sort(want.begin(), want.end());
            ASSERT_EQ(got, want) << name << " dims " << dx << "," << dy << " k=" << k << " i=" << i;
          }
        }
    };
    check("none", NoRandomizer{});
    for (std::uint64_t seed : {1ull, 99ull}) {
      check("owen", OwenScrambler(seed));
      check("owen-hash", HashOwenScrambler(seed));
      check("xor", DigitalShift(seed));
      check("lms", LinearMatrixScramble(seed));
    }
  }
}

// A (0,2)-sequence: every aligned block [m 2^k, (m+1) 2^k) of dims (0, 1),
// not just the prefixes, is a (0,k,2)-net, also past 2^32 and in natural order.
TEST(Sobol, EveryAlignedBlockOfTheFirstTwoDimensionsIsAZeroTwoNet) {
  for (auto order : {Sobol::Order::gray, Sobol::Order::natural}) {
    const Sobol sobol(2, order);
    for (unsigned k = 1; k <= 10; ++k) {
      const std::size_t n = std::size_t{1} << k;
      for (std::uint64_t m : u64s{1, 5, (two32 >> k) + 3}) {
        std::vector<std::uint64_t> xs(n), ys(n);
        for (std::size_t i = 0; i < n; ++i) {
          xs[i] = sobol.bits(m * n + i, 0);
          ys[i] = sobol.bits(m * n + i, 1);
        }
        for (unsigned i = 0; i <= k; ++i)
          for (int c : box_counts(xs, ys, n, i, k - i)) ASSERT_EQ(c, 1) << "k " << k << " block " << m;
      }
    }
  }
}

// Cranley-Patterson rotation does not keep elementary intervals but keeps
// the 1D stratification: at N = 2^k each coordinate has one point in every
// interval [m/N, (m+1)/N).
TEST(Sobol, CranleyPattersonKeepsOneDimensionalStratification) {
  const Sobol sobol(8);
  for (std::uint64_t seed : {3ull, 4ull})
    for (unsigned k = 1; k <= 12; ++k) {
      const std::size_t n = std::size_t{1} << k;
      const CranleyPattersonRotation rotation(seed);
      for (unsigned j = 0; j < 8; ++j) {
        std::vector<int> hits(n, 0);
        for (std::size_t i = 0; i < n; ++i) ++hits[static_cast<std::size_t>(rotation(sobol.sample(i, j), j) * n)];
        for (int h : hits) ASSERT_EQ(h, 1) << "seed " << seed << " k " << k << " dim " << j;
      }
    }
}

// --- registry ------------------------------------------------------------

PointSet registry_points(const std::string& name, std::uint64_t n, unsigned d, const std::string& randomize,
                         std::uint64_t seed, std::uint64_t start = 0, unsigned threads = 1,
                         const std::string& order = "gray") {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  request.start = start;
  request.randomize = randomize;
  request.threads = threads;
  request.params["order"] = order;
  return generate_points(name, request);
}

// The bulk Gray-code walk equals random access bit for bit, for every
// randomizer, both orders, a start past 2^32, chunks split over threads,
// and the walk's layouts for few (d < 8), many and very many (d > 1024)
// dimensions.
TEST(SobolRegistry, BulkEqualsRandomAccess) {
  const std::uint64_t seed = 42;
  for (auto [d, n] : {std::pair<unsigned, std::uint64_t>{5, 9000}, {11, 9000}, {1100, 40}}) {
    for (const char* order : {"gray", "natural"}) {
      const Sobol sobol(d, std::string(order) == "gray" ? Sobol::Order::gray : Sobol::Order::natural);
      for (std::uint64_t start : u64s{0, 5, two32 - 3000}) {
        auto compare = [&](const std::string& name, auto sample) {
          const PointSet points = registry_points("sobol", n, d, name, seed, start, 2, order);
          for (std::uint64_t i = 0; i < n; ++i)
            for (unsigned j = 0; j < d; ++j)
              ASSERT_EQ(points(i, j), sample(start + i, j)) << name << " " << order << " start " << start << " i " << i;
        };
        compare("none", [&](std::uint64_t i, unsigned j) { return sobol.sample(i, j); });
        compare("owen-hash", [&](std::uint64_t i, unsigned j) { return sobol.sample(i, j, HashOwenScrambler(seed)); });
        compare("xor", [&](std::uint64_t i, unsigned j) { return sobol.sample(i, j, DigitalShift(seed)); });
        compare("lms", [&](std::uint64_t i, unsigned j) { return sobol.sample(i, j, LinearMatrixScramble(seed)); });
        compare("cp",
                [&](std::uint64_t i, unsigned j) { return CranleyPattersonRotation(seed)(sobol.sample(i, j), j); });
        if (start == 5 && d == 5)  // exact Owen costs 64 hashes per coordinate: one case is enough
          compare("owen", [&](std::uint64_t i, unsigned j) { return sobol.sample(i, j, OwenScrambler(seed)); });
      }
    }
  }
}

// The bulk generator cuts rows into aligned blocks of 2^k rows (k depends on
// d) and groups of rows whose words are whole vectors (lcm(d, 8), doubled up
// to 64 words, for d <= 256; d words above). Dimensions on either side of
// each switch, starts that are not aligned (or past 2^40), and counts that
// end inside a block and a group, split over two threads.
TEST(SobolRegistry, BulkEqualsRandomAccessForEveryBlockLayout) {
  const std::uint64_t seed = 17;
  const HashOwenScrambler owen(seed);
  const DigitalShift shift(seed);
  for (unsigned d : {1u, 2u, 3u, 4u, 6u, 8u, 9u, 16u, 17u, 63u, 256u, 257u, 300u}) {
    const std::uint64_t n = std::max<std::uint64_t>(37, 24000 / d + 37);
    for (const char* order : {"gray", "natural"}) {
      const Sobol sobol(d, std::string(order) == "gray" ? Sobol::Order::gray : Sobol::Order::natural);
      for (std::uint64_t start : u64s{0, 7, (std::uint64_t{1} << 40) + 4093}) {
        const PointSet hashed = registry_points("sobol", n, d, "owen-hash", seed, start, 2, order);
        const PointSet shifted = registry_points("sobol", n, d, "xor", seed, start, 2, order);
        for (std::uint64_t i = 0; i < n; ++i)
          for (unsigned j = 0; j < d; ++j) {
            ASSERT_EQ(hashed(i, j), sobol.sample(start + i, j, owen))
                << "d " << d << " " << order << " start " << start << " i " << i << " j " << j;
            ASSERT_EQ(shifted(i, j), sobol.sample(start + i, j, shift))
                << "d " << d << " start " << start << " i " << i;
          }
      }
    }
  }
}

// FNV-1a over the bits of the doubles, row by row.
std::uint64_t digest(const PointSet& points) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < points.n; ++i)
    for (std::size_t j = 0; j < points.d; ++j) {
      std::uint64_t bits;
      const double x = points(i, j);
      std::memcpy(&bits, &x, sizeof bits);
      h = (h ^ bits) * 0x100000001b3ULL;
    }
  return h;
}

// Bulk output pinned bit for bit: digests computed with random access
// (Sobol::sample with each randomizer) by the implementation before the
// block-based bulk generator, for n = 5000 (300 for exact Owen), d = 7,
// start = 1000003, seed = 31, on one and two threads.
TEST(SobolRegistry, BulkOutputIsPinned) {
  struct Pin {
    const char* order;
    const char* randomize;
    std::uint64_t digest;
  };
  const Pin pins[] = {
      {"gray", "none", 0xfecd43438dcf0f85ull},    {"gray", "owen-hash", 0xc916d42d31417e5aull},
      {"gray", "xor", 0xf6faa991535196feull},     {"gray", "lms", 0xa5f55a514451ab5full},
      {"gray", "cp", 0xcf7e8d5598904035ull},      {"gray", "owen", 0x4b63b670836ecc10ull},
      {"natural", "none", 0xf969eb418dcf0f85ull}, {"natural", "owen-hash", 0x814b9ff0724a86faull},
      {"natural", "xor", 0x634d2a2fabdc5964ull},  {"natural", "lms", 0xd648e5e4d24e2134ull},
      {"natural", "cp", 0x3095546369d86e95ull},   {"natural", "owen", 0xa2e47770a73e1604ull},
  };
  for (const Pin& pin : pins)
    for (unsigned threads : {1u, 2u}) {
      const std::uint64_t n = std::string(pin.randomize) == "owen" ? 300 : 5000;
      EXPECT_EQ(digest(registry_points("sobol", n, 7, pin.randomize, 31, 1000003, threads, pin.order)), pin.digest)
          << pin.order << " " << pin.randomize << " threads " << threads;
    }
}

TEST(SobolRegistry, DefaultIsOwenHashAndZeroTwoIsTheFirstTwoDimensions) {
  SamplerRequest request;
  request.n = 300;
  request.d = 2;
  request.seed = 8;
  const PointSet by_default = generate_points("sobol", request);
  const PointSet zero_two = generate_points("zero-two", request);
  const Sobol sobol(2);
  for (std::uint64_t i = 0; i < 300; ++i)
    for (unsigned j = 0; j < 2; ++j) {
      EXPECT_EQ(by_default(i, j), sobol.sample(i, j, HashOwenScrambler(8)));
      EXPECT_EQ(zero_two(i, j), by_default(i, j));
    }
  request.d = 3;
  EXPECT_THROW(generate_points("zero-two", request), invalid_argument);
  request.d = 2;
  // The base-2 family's randomizers, as Sobol' (cp too: the same rotated points).
  request.randomize = "cp";
  const PointSet rotated = generate_points("zero-two", request), sobol_rotated = generate_points("sobol", request);
  for (std::uint64_t i = 0; i < 300; ++i)
    for (unsigned j = 0; j < 2; ++j) EXPECT_EQ(rotated(i, j), sobol_rotated(i, j));
  request.randomize = "permute";  // a base-b randomizer
  EXPECT_THROW(generate_points("zero-two", request), invalid_argument);
}

// bits=b keeps b digits of every coordinate after the randomizer: exactly
// floor(x 2^b) / 2^b of the full points, for each randomizer and layout
// (the linear ones through masked columns, the others at the finish).
TEST(SobolRegistry, BitsKeepsTheFirstDigits) {
  for (unsigned d : {3u, 8u, 300u})
    for (const char* randomize : {"none", "xor", "lms", "owen-hash", "owen", "cp"})
      for (unsigned bits : {1u, 7u, 30u, 52u, 53u, 60u}) {
        SamplerRequest request;
        request.n = 700;
        request.d = d;
        request.seed = 9;
        request.start = 3;
        request.randomize = randomize;
        const PointSet full = generate_points("sobol", request);
        request.params["bits"] = std::to_string(bits);
        const PointSet kept = generate_points("sobol", request);
        const double scale = std::ldexp(1.0, int(bits));
        for (std::uint64_t i = 0; i < *request.n; ++i)
          for (unsigned j = 0; j < d; ++j)
            ASSERT_EQ(kept(i, j), std::floor(full(i, j) * scale) / scale)
                << randomize << " d " << d << " bits " << bits << " i " << i << " j " << j;
      }
  for (const char* bad : {"0", "65", "-1", "x"}) {
    SamplerRequest request;
    request.n = 4;
    request.d = 2;
    request.randomize = "none";
    request.params["bits"] = bad;
    try {
      generate_points("sobol", request);
      FAIL() << bad;
    } catch (const invalid_argument& e) {
      EXPECT_EQ(e.argument(), "bits") << bad;
    }
  }
}

TEST(SobolRegistry, RejectsBadOrderAndTooManyDimensions) {
  EXPECT_THROW(registry_points("sobol", 4, 2, "none", 0, 0, 1, "reversed"), invalid_argument);
  try {
    registry_points("sobol", 4, 21202, "none", 0);
    FAIL() << "no exception";
  } catch (const invalid_argument& e) {
    EXPECT_EQ(e.argument(), "d");
    EXPECT_NE(std::string(e.what()).find("21202"), std::string::npos);
  }
}

}  // namespace
}  // namespace stratum
