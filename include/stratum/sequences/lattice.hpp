#pragma once
/// Rank-1 lattices x_i = frac(i z / n), i = 0 … n−1, for a generating vector
/// z ∈ {1, …, n−1}^d (Korobov 1959, "The approximate computation of multiple
/// integrals"; Sloan, Joe 1994, "Lattice methods for multiple integration").
/// For smooth periodic integrands their error decays almost as 1/n² (much
/// faster than the 1/n of digital nets), and in 2D the Fibonacci lattice
/// (n = F_k, z = (1, F_{k−1})) is the best-known point set for many
/// criteria (Zaremba 1966; Niederreiter 1992, Sec. 5.3). Every coordinate
/// with gcd(z_j, n) = 1 is a permutation of {0, 1/n, …, (n−1)/n}: one point
/// per row and column of the n × n grid (Latin). A Cranley–Patterson
/// rotation keeps that (it is a shift modulo 1) and makes the rule unbiased.
///
/// Three ways to get z, all validated at construction:
///   - given explicitly;
///   - Korobov's form z = (1, a, a², …) mod n;
///   - a search over Korobov parameters a minimizing the squared worst-case
///     error in the weighted Korobov space of smoothness α = 2 with product
///     weights γ_j (Sloan, Joe 1994's P_2 when all γ_j = 1; Sloan,
///     Woźniakowski 1998; Dick, Kuo, Sloan 2013, "High-dimensional
///     integration: the quasi-Monte Carlo way", Sec. 5):
///       e²(z) = −1 + (1/n) Σ_k Π_j (1 + γ_j 2π² B₂({k z_j / n})),
///     B₂(x) = x² − x + 1/6 the Bernoulli polynomial. One evaluation costs
///     O(n d); the search caps the number of candidates (spread evenly over
///     a ≤ n/2, since a and n − a give the same e²).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>

#include "stratum/util/error.hpp"
#include "stratum/util/host_device.hpp"
#include "stratum/util/real.hpp"

namespace stratum {

class Rank1Lattice {
 public:
  static constexpr unsigned max_dimensions = 256;

  /// Throws invalid_argument("generator", …) unless 1 ≤ d ≤ 256 and every
  /// z_j is in [1, n) (the single point of n = 1 takes z_j = 1).
  Rank1Lattice(std::uint64_t count, std::span<const std::uint64_t> generator)
      : count_(count), dimensions_(static_cast<unsigned>(generator.size())) {
    require(count >= 1, "n", count, "a rank-1 lattice needs n >= 1");
    require(!generator.empty() && generator.size() <= max_dimensions, "generator", generator.size(),
            "a generating vector needs 1 to 256 entries, one per dimension");
    for (std::size_t j = 0; j < generator.size(); ++j) {
      const std::uint64_t z = generator[j];
      if (z < 1 || z >= std::max<std::uint64_t>(count, 2))  // message built only on failure
        throw invalid_argument("generator", "entry " + std::to_string(j) + " = " + std::to_string(z),
                               "entries must be in [1, n) = [1, " + std::to_string(count) + ")");
      generator_[j] = z % count;
    }
  }

  STRATUM_HOST_DEVICE std::uint64_t count() const noexcept { return count_; }
  STRATUM_HOST_DEVICE unsigned dimensions() const noexcept { return dimensions_; }
  STRATUM_HOST_DEVICE std::uint64_t generator(unsigned dim) const noexcept { return count_ == 1 ? 1 : generator_[dim]; }

  /// (index · z_dim) mod n: the point's coordinate times n, exactly.
  STRATUM_HOST_DEVICE constexpr std::uint64_t numerator(std::uint64_t index, unsigned dim) const noexcept {
    const std::uint64_t i = index < count_ ? index : index % count_;  // a set's own indices: no division
    // n ≤ 2^32: the product of two residues fits in 64 bits (a 128-bit remainder is a library call).
    if (count_ <= (std::uint64_t{1} << 32)) return i * generator_[dim] % count_;
    return static_cast<std::uint64_t>(static_cast<unsigned __int128>(i) * generator_[dim] % count_);
  }

  /// frac(index · z_dim / n), correctly rounded for n < 2^53.
  template <class Real = double>
  STRATUM_HOST_DEVICE constexpr Real sample(std::uint64_t index, unsigned dim) const noexcept {
    const double value = static_cast<double>(numerator(index, dim)) / static_cast<double>(count_);
    return to_unit<Real>(one_minus_epsilon_double < value ? one_minus_epsilon_double : value);
  }

 private:
  std::uint64_t count_;
  unsigned dimensions_;
  std::array<std::uint64_t, max_dimensions> generator_{};
};

// ---------------------------------------------------------------------------
// Fibonacci lattices

/// F_k with F_0 = 0, F_1 = 1 (k ≤ 93 fits in 64 bits).
constexpr std::uint64_t fibonacci_number(unsigned k) noexcept {
  std::uint64_t a = 0, b = 1;
  for (unsigned i = 0; i < k; ++i) {
    const std::uint64_t next = a + b;
    a = b;
    b = next;
  }
  return a;
}

/// k ≥ 2 with F_k = n, or 0 when n is not a Fibonacci number.
constexpr unsigned fibonacci_index(std::uint64_t n) noexcept {
  for (unsigned k = 2; k <= 93; ++k) {
    if (fibonacci_number(k) == n) return k;
    if (fibonacci_number(k) > n) break;
  }
  return 0;
}

/// The second entry of the golden-ratio lattice (1, g) for n points: F_{k−1}
/// when n = F_k (the Fibonacci lattice), otherwise the integer nearest n/φ
/// that is coprime to n (ties to the smaller), which keeps the set Latin.
/// For n = F_k the nearest integer to n/φ is F_{k−1} anyway (Binet's formula
/// gives |F_k/φ − F_{k−1}| = φ^(−k) < 1/2 for k ≥ 2), so this is one rule.
/// Host only (not constexpr): its long double has no device counterpart.
inline std::uint64_t golden_generator(std::uint64_t n) noexcept {
  if (n <= 2) return 1;
  if (const unsigned k = fibonacci_index(n)) return fibonacci_number(k - 1);
  const long double target = static_cast<long double>(n) * 0.6180339887498948482045868343656381L;
  std::uint64_t low = static_cast<std::uint64_t>(target);  // floor (target > 0)
  std::uint64_t high = low + 1;
  for (;;) {
    const bool take_low =
        low >= 1 && (high >= n || target - static_cast<long double>(low) <= static_cast<long double>(high) - target);
    const std::uint64_t candidate = take_low ? low : high;
    if (std::gcd(candidate, n) == 1) return candidate;
    if (take_low) --low;
    else ++high;
  }
}

/// The golden-ratio (Fibonacci when n = F_k) lattice with n points in 2D.
inline Rank1Lattice fibonacci_lattice(std::uint64_t n) {
  const std::array<std::uint64_t, 2> z = {1, golden_generator(n)};
  return Rank1Lattice(n, z);
}

// ---------------------------------------------------------------------------
// Korobov lattices and the search for a good parameter

/// z = (1, a, a², …, a^(d−1)) mod n. Throws invalid_argument("a", …) unless
/// a is in [1, n) and coprime to n (then no entry is 0 and every coordinate
/// is Latin); n = 1 takes a = 1.
inline std::array<std::uint64_t, Rank1Lattice::max_dimensions> korobov_generator(std::uint64_t n, std::uint64_t a,
                                                                                 unsigned d) {
  require(d >= 1 && d <= Rank1Lattice::max_dimensions, "d", d, "a Korobov lattice supports 1 to 256 dimensions");
  require(n >= 1, "n", n, "a rank-1 lattice needs n >= 1");
  if (a < 1 || a >= std::max<std::uint64_t>(n, 2) || std::gcd(a, n) != 1)
    throw invalid_argument("a", std::to_string(a),
                           "the Korobov parameter must be in [1, n) = [1, " + std::to_string(n) + ") and coprime to n");
  std::array<std::uint64_t, Rank1Lattice::max_dimensions> z{};
  std::uint64_t power = 1 % n;
  for (unsigned j = 0; j < d; ++j) {
    z[j] = n == 1 ? 1 : power;
    power = static_cast<std::uint64_t>(static_cast<unsigned __int128>(power) * a % n);
  }
  return z;
}

/// Squared worst-case error e²(z) of the lattice rule in the weighted Korobov
/// space with α = 2 and product weights γ_j = gamma^(j+1), j = 0 … d−1
/// (gamma = 1: Sloan & Joe's P_2). O(n d), no allocation.
inline double korobov_space_error2(std::uint64_t n, std::span<const std::uint64_t> generator, double gamma = 1.0) {
  constexpr double two_pi_squared = 2.0 * 3.14159265358979323846 * 3.14159265358979323846;
  const std::size_t d = generator.size();
  std::array<double, Rank1Lattice::max_dimensions> weight{};
  std::array<std::uint64_t, Rank1Lattice::max_dimensions> step{}, numerator{};
  double g = 1.0;
  for (std::size_t j = 0; j < d; ++j) {
    g *= gamma;
    weight[j] = g * two_pi_squared;
    step[j] = generator[j] % n;
  }
  const double inverse_n = 1.0 / static_cast<double>(n);
  double sum = 0.0;
  for (std::uint64_t k = 0; k < n; ++k) {
    double product = 1.0;
    for (std::size_t j = 0; j < d; ++j) {
      const double x = static_cast<double>(numerator[j]) * inverse_n;
      product *= 1.0 + weight[j] * (x * x - x + 1.0 / 6.0);
      // (k+1) z_j mod n without a division (and without overflow near 2^64)
      numerator[j] = numerator[j] >= n - step[j] ? numerator[j] - (n - step[j]) : numerator[j] + step[j];
    }
    sum += product;
  }
  return sum * inverse_n - 1.0;
}

/// Search over Korobov parameters: the candidates, their criterion, the best.
class KorobovSearch {
 public:
  /// Work budget of the default search, in point-coordinates evaluated.
  static constexpr std::uint64_t default_budget = std::uint64_t{1} << 23;
  /// At least this many candidates (when that many exist), whatever n.
  static constexpr std::uint64_t min_candidates = 16;

  KorobovSearch(std::uint64_t n, unsigned d, double gamma = 1.0, std::uint64_t budget = default_budget)
      : n_(n), d_(d), gamma_(gamma) {
    require(n >= 1, "n", n, "a rank-1 lattice needs n >= 1");
    require(d >= 1 && d <= Rank1Lattice::max_dimensions, "d", d, "a Korobov lattice supports 1 to 256 dimensions");
    require(gamma > 0 && gamma <= 1, "gamma", gamma, "product weights gamma^j need gamma in (0, 1]");
    half_ = std::max<std::uint64_t>(n / 2, 1);
    // d = 1, or n <= 3: every a gives the same lattice up to reflection.
    const std::uint64_t affordable = std::max(budget / n / d, min_candidates);
    candidates_ = (d == 1 || n <= 3) ? 1 : std::min(half_, affordable);
  }

  std::uint64_t candidate_count() const noexcept { return candidates_; }

  /// Candidate t: the first a ≥ 1 + t·⌊n/2⌋/count coprime to n (a = 1 if none
  /// up to n/2). With count = ⌊n/2⌋ these are all a ≤ n/2 (repeats of the
  /// next coprime value stand in for the others).
  std::uint64_t candidate(std::uint64_t t) const noexcept {
    std::uint64_t a = 1 + static_cast<std::uint64_t>(static_cast<unsigned __int128>(t) * half_ / candidates_);
    while (a <= half_ && std::gcd(a, n_) != 1) ++a;
    return a <= half_ ? a : 1;
  }

  /// e² of the Korobov lattice with parameter a.
  double score(std::uint64_t a) const {
    const auto z = korobov_generator(n_, a, d_);
    return korobov_space_error2(n_, std::span<const std::uint64_t>(z.data(), d_), gamma_);
  }

  /// Index of the best among scored candidates: smallest e², ties to the
  /// smaller a (so the result never depends on evaluation order).
  static std::uint64_t best_of(std::span<const double> scores, std::span<const std::uint64_t> parameters) noexcept {
    std::uint64_t best = 0;
    for (std::uint64_t t = 1; t < scores.size(); ++t)
      if (scores[t] < scores[best] || (scores[t] == scores[best] && parameters[t] < parameters[best])) best = t;
    return best;
  }

  /// Serial search: the best Korobov parameter.
  std::uint64_t best() const {
    std::uint64_t best_a = candidate(0);
    double best_score = score(best_a);
    for (std::uint64_t t = 1; t < candidates_; ++t) {
      const std::uint64_t a = candidate(t);
      const double s = score(a);
      if (s < best_score || (s == best_score && a < best_a)) best_a = a, best_score = s;
    }
    return best_a;
  }

 private:
  std::uint64_t n_;
  unsigned d_;
  double gamma_;
  std::uint64_t half_ = 1;
  std::uint64_t candidates_ = 1;
};

}  // namespace stratum
