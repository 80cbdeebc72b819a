#include "stratum/sequences/lattice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

Rank1Lattice make(std::uint64_t n, std::vector<std::uint64_t> z) { return Rank1Lattice(n, z); }

// (a b) mod n by binary doubling: an oracle independent of __int128.
std::uint64_t mulmod_by_doubling(std::uint64_t a, std::uint64_t b, std::uint64_t n) {
  std::uint64_t result = 0;
  a %= n;
  for (; b != 0; b >>= 1) {
    if (b & 1u) result = result >= n - a ? result - (n - a) : result + a;
    a = a >= n - a ? a - (n - a) : a + a;
  }
  return result;
}

TEST(Rank1Lattice, MatchesFracOfIZOverNInLongDouble) {
  const auto lattice = make(1021, {1, 306, 542, 1020});
  for (std::uint64_t i = 0; i < 1021; ++i)
    for (unsigned j = 0; j < 4; ++j) {
      const long double x = static_cast<long double>(i) * lattice.generator(j) / 1021.0L;
      const long double expected = x - std::floor(x);
      ASSERT_NEAR(lattice.sample(i, j), static_cast<double>(expected), 0x1.0p-52) << i << " " << j;
      ASSERT_NEAR(lattice.sample<float>(i, j), static_cast<double>(expected), 0x1.0p-24) << i << " " << j;
    }
  // n a power of two: every value is exact.
  const auto dyadic = make(8, {1, 3});
  EXPECT_EQ(dyadic.sample(5, 0), 0.625);
  EXPECT_EQ(dyadic.sample(5, 1), 0.875);   // 15 / 8 mod 1
  EXPECT_EQ(dyadic.sample(13, 1), 0.875);  // indices wrap modulo n
}

// Products i z beyond 2^64 are reduced exactly (n near 2^40, i z ~ 2^80).
TEST(Rank1Lattice, LargeProductsAreExact) {
  const std::uint64_t n = (std::uint64_t{1} << 40) + 15;
  const auto lattice = make(n, {1, n - 2, 0x9e3779b97fULL % n});
  for (std::uint64_t i : {n - 1, n / 3, std::uint64_t{123456789012}})
    for (unsigned j = 0; j < 3; ++j) EXPECT_EQ(lattice.numerator(i, j), mulmod_by_doubling(i, lattice.generator(j), n));
  EXPECT_LT(lattice.sample(n - 1, 1), 1.0);
}

TEST(Rank1Lattice, RejectsBadGenerators) {
  const std::vector<std::vector<std::uint64_t>> bad = {{1, 0}, {1, 8}, {}, std::vector<std::uint64_t>(257, 1)};
  for (const auto& z : bad) {
    try {
      make(8, z);
      FAIL() << "no exception for size " << z.size();
    } catch (const invalid_argument& e) {
      EXPECT_EQ(e.argument(), "generator");
    }
  }
  try {
    make(8, {1, 9});
    FAIL();
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("entry 1 = 9"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[1, 8)"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(make(1, {1, 1}));  // the single point 0
  EXPECT_EQ(make(1, {1, 1}).sample(0, 1), 0.0);
}

TEST(Fibonacci, NumbersAndIndices) {
  EXPECT_EQ(fibonacci_number(0), 0u);
  EXPECT_EQ(fibonacci_number(10), 55u);
  EXPECT_EQ(fibonacci_number(20), 6765u);
  EXPECT_EQ(fibonacci_number(93), 12200160415121876738ull);
  EXPECT_EQ(fibonacci_index(1), 2u);
  EXPECT_EQ(fibonacci_index(89), 11u);
  EXPECT_EQ(fibonacci_index(90), 0u);
  EXPECT_EQ(fibonacci_index(12200160415121876738ull), 93u);
}

// For n = F_k the golden rule gives F_{k−1}; checked against the nearest
// integer to n/φ computed independently (φ from sqrt in long double).
TEST(Fibonacci, GoldenGeneratorIsTheClassicOneForFibonacciN) {
  const long double phi = (1.0L + std::sqrt(5.0L)) / 2.0L;
  for (unsigned k = 3; k <= 60; ++k) {
    const std::uint64_t n = fibonacci_number(k);
    EXPECT_EQ(golden_generator(n), fibonacci_number(k - 1)) << k;
    EXPECT_EQ(static_cast<std::uint64_t>(std::llround(static_cast<long double>(n) / phi)), fibonacci_number(k - 1))
        << k;
  }
  // Other n: nearest to n/φ among values coprime to n.
  EXPECT_EQ(golden_generator(100), 61u);    // 61.80 -> 62 shares 2 with 100; 61 is prime
  EXPECT_EQ(golden_generator(256), 159u);   // 158.2 -> 158 even; 159 odd
  EXPECT_EQ(golden_generator(1000), 619u);  // 618.03 -> 618 even; 619 is 0.97 away, 617 is 1.03
  for (std::uint64_t n = 2; n < 3000; ++n) ASSERT_EQ(std::gcd(golden_generator(n), n), 1u) << n;
}

// One point in every row and every column of the n × n grid, with and
// without a Cranley–Patterson rotation.
void expect_latin(const Rank1Lattice& lattice, const CranleyPattersonRotation* rotation) {
  const std::uint64_t n = lattice.count();
  std::vector<int> rows(n, 0), cols(n, 0);
  for (std::uint64_t i = 0; i < n; ++i) {
    double x = lattice.sample(i, 0), y = lattice.sample(i, 1);
    std::uint64_t cx = 0, cy = 0;
    if (rotation) {
      x = (*rotation)(x, 0), y = (*rotation)(y, 1);
      cx = static_cast<std::uint64_t>(x * static_cast<double>(n));
      cy = static_cast<std::uint64_t>(y * static_cast<double>(n));
    } else {
      // Points are the grid corners r/n: recover r.
      cx = static_cast<std::uint64_t>(std::llround(x * static_cast<double>(n)));
      cy = static_cast<std::uint64_t>(std::llround(y * static_cast<double>(n)));
    }
    ++cols[cx];
    ++rows[cy];
  }
  for (std::uint64_t c = 0; c < n; ++c) ASSERT_TRUE(rows[c] == 1 && cols[c] == 1) << "n=" << n << " cell " << c;
}

TEST(Fibonacci, OnePointPerRowAndColumnAlsoAfterRotation) {
  for (std::uint64_t n : {2ull, 3ull, 89ull, 144ull, 233ull, 610ull, 987ull, 1597ull, 100ull, 256ull, 1000ull}) {
    const Rank1Lattice lattice = fibonacci_lattice(n);
    EXPECT_EQ(lattice.generator(0), 1u);
    expect_latin(lattice, nullptr);
    for (std::uint64_t seed : {1ull, 2ull, 3ull}) {
      const CranleyPattersonRotation rotation(seed);
      expect_latin(lattice, &rotation);
    }
  }
  EXPECT_EQ(fibonacci_lattice(89).generator(1), 55u);
  // The 13-point Fibonacci lattice by hand: i (1, 8) / 13.
  EXPECT_DOUBLE_EQ(fibonacci_lattice(13).sample(5, 1), 1.0 / 13);  // 40 mod 13 = 1
}

TEST(Korobov, GeneratorIsPowersOfA) {
  const auto z = korobov_generator(1021, 76, 4);
  EXPECT_EQ(z[0], 1u);
  EXPECT_EQ(z[1], 76u);
  EXPECT_EQ(z[2], 76u * 76 % 1021);
  EXPECT_EQ(z[3], 76u * 76 % 1021 * 76 % 1021);
  for (std::uint64_t a : {0ull, 1021ull, 2000ull}) {
    try {
      korobov_generator(1021, a, 3);
      FAIL() << a;
    } catch (const invalid_argument& e) {
      EXPECT_EQ(e.argument(), "a");
    }
  }
  EXPECT_THROW(korobov_generator(1000, 4, 3), invalid_argument);  // gcd(4, 1000) = 4: not coprime
}

// e²(z) straight from its definition on the lattice's own points, in long
// double: −1 + mean over points of Π_j (1 + γ_j 2π² B₂(x_j)).
long double error2_from_points(const Rank1Lattice& lattice, long double gamma) {
  const long double pi = 3.141592653589793238462643383279502884L;
  long double sum = 0;
  for (std::uint64_t i = 0; i < lattice.count(); ++i) {
    long double product = 1, weight = 1;
    for (unsigned j = 0; j < lattice.dimensions(); ++j) {
      weight *= gamma;
      const long double x = static_cast<long double>(lattice.numerator(i, j)) / lattice.count();
      product *= 1 + weight * 2 * pi * pi * (x * x - x + 1.0L / 6);
    }
    sum += product;
  }
  return sum / lattice.count() - 1;
}

TEST(Korobov, CriterionMatchesTheDefinitionOnThePoints) {
  for (double gamma : {1.0, 0.5}) {
    const auto z = korobov_generator(1009, 331, 5);
    const Rank1Lattice lattice(1009, std::span<const std::uint64_t>(z.data(), 5));
    const double fast = korobov_space_error2(1009, std::span<const std::uint64_t>(z.data(), 5), gamma);
    EXPECT_NEAR(fast, static_cast<double>(error2_from_points(lattice, gamma)), 1e-12 * (1 + std::abs(fast)));
  }
}

// e² is also the dual-lattice sum Σ_{h ≠ 0, h·z ≡ 0 (mod n)} Π_{h_j ≠ 0} γ_j / h_j²
// (Sloan & Joe 1994, P_α with α = 2), independent of the B₂ closed form.
// Truncated at |h_j| ≤ H; the omitted terms sum to at most
// 2 · (2/H) · (1 + 2 Σ_t 1/(1 + 13 t)²) < 12.2 / H.
TEST(Korobov, CriterionMatchesTheDualLatticeSum) {
  const std::int64_t n = 13, z = 5, H = 3000;
  for (double gamma : {1.0, 0.5}) {
    long double sum = 0;
    for (std::int64_t h2 = -H; h2 <= H; ++h2) {
      // h1 ≡ −z h2 (mod n)
      const std::int64_t r = ((-z * h2) % n + n) % n;
      for (std::int64_t h1 = r - (H + r) / n * n; h1 <= H; h1 += n) {
        if (h1 == 0 && h2 == 0) continue;
        long double term = 1;
        if (h1 != 0) term *= gamma / (static_cast<long double>(h1) * h1);
        if (h2 != 0) term *= gamma * gamma / (static_cast<long double>(h2) * h2);
        sum += term;
      }
    }
    const std::array<std::uint64_t, 2> generator = {1, 5};
    const double closed = korobov_space_error2(13, generator, gamma);
    EXPECT_NEAR(closed, static_cast<double>(sum), 12.2 / H) << gamma;
    EXPECT_GE(closed, static_cast<double>(sum));  // the truncated sum misses only positive terms
  }
}

TEST(Korobov, SearchFindsTheBestParameterAndBeatsRandomVectors) {
  const std::uint64_t n = 1009;  // prime: every a in [1, n) is a candidate
  const unsigned d = 4;
  const KorobovSearch search(n, d);
  ASSERT_EQ(search.candidate_count(), 504u);  // all a <= n/2 fit the budget
  const std::uint64_t best = search.best();
  const double best_score = search.score(best);
  // Brute force over every a in [1, n): nothing is better, and a, n − a tie.
  for (std::uint64_t a = 1; a < n; ++a) {
    const double s = search.score(a);
    ASSERT_GE(s, best_score) << a;
    ASSERT_NEAR(s, search.score(n - a), 1e-12 * s) << a;
  }
  // The criterion of the chosen lattice, from its points.
  const auto z = korobov_generator(n, best, d);
  const Rank1Lattice lattice(n, std::span<const std::uint64_t>(z.data(), d));
  EXPECT_NEAR(best_score, static_cast<double>(error2_from_points(lattice, 1.0L)), 1e-12);
  // Better than the median of 101 random generating vectors.
  std::vector<double> random_scores;
  for (std::uint64_t t = 0; t < 101; ++t) {
    std::array<std::uint64_t, 4> random_z{};
    for (unsigned j = 0; j < d; ++j) random_z[j] = 1 + uniform_below(n - 1, 77, t, j);
    random_scores.push_back(korobov_space_error2(n, random_z));
  }
  std::nth_element(random_scores.begin(), random_scores.begin() + 50, random_scores.end());
  // Measured: best e² = 0.0863 (a = 39), median of random vectors 0.185.
  EXPECT_LT(best_score, 0.6 * random_scores[50]);
  // Parallel evaluation picks the same answer as the serial best().
  std::vector<double> scores;
  std::vector<std::uint64_t> parameters;
  for (std::uint64_t t = search.candidate_count(); t-- > 0;) {
    parameters.push_back(search.candidate(t));
    scores.push_back(search.score(parameters.back()));
  }
  EXPECT_EQ(parameters[KorobovSearch::best_of(scores, parameters)], best);
}

// In 2D with n = F_k the search recovers the Fibonacci lattice (up to the
// reflection a -> n - a), the classic optimum for P_2 (Zaremba 1966).
TEST(Korobov, SearchFindsTheFibonacciLatticeIn2D) {
  for (unsigned k : {11u, 16u}) {  // n = 89, 987
    const std::uint64_t n = fibonacci_number(k), fib = fibonacci_number(k - 1);
    const std::uint64_t a = KorobovSearch(n, 2).best();
    EXPECT_TRUE(a == fib || a == n - fib) << "n=" << n << " a=" << a;
  }
}

TEST(Korobov, CappedSearchSpreadsCoprimeCandidates) {
  const std::uint64_t n = 1 << 16;
  const KorobovSearch search(n, 3, 1.0, std::uint64_t{1} << 22);
  ASSERT_EQ(search.candidate_count(), 21u);  // 2^22 / (3 · 2^16)
  std::uint64_t previous = 0;
  for (std::uint64_t t = 0; t < search.candidate_count(); ++t) {
    const std::uint64_t a = search.candidate(t);
    EXPECT_EQ(a % 2, 1u);
    EXPECT_GT(a, previous);
    EXPECT_LE(a, n / 2);
    previous = a;
  }
  EXPECT_EQ(KorobovSearch(n, 3, 1.0, 1).candidate_count(), KorobovSearch::min_candidates);
  EXPECT_EQ(KorobovSearch(n, 1).candidate_count(), 1u);
  EXPECT_THROW(KorobovSearch(n, 3, 1.5), invalid_argument);
  EXPECT_THROW(KorobovSearch(n, 3, 0.0), invalid_argument);
}

}  // namespace
}  // namespace stratum
