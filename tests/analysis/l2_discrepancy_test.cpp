// Oracles for the L2 discrepancies (l2_discrepancy.hpp):
// - brute force: the L2-star and centered discrepancies integrated exactly
//   from their definitions (squared local discrepancy over anchored boxes,
//   or over boxes to the nearest vertex for every projection), cell by cell
//   of the grid the points' coordinates cut the cube into;
// - the closed form of the 2D Hammersley set's L2-star discrepancy at
//   N = 2^m (Halton & Zaremba 1969, as restated by Faure & Pillichshammer);
// - published values (Fang et al. 2006; Zhou, Fang, Ning 2013; Pillards et
//   al. 2005) that scipy's own tests use;
// - a plain double loop over all ordered pairs against the tiled, symmetric,
//   threaded kernel; fast (Heinrich) against Warnock; WD's invariance under
//   shifts mod 1; scipy's update recurrence against recomputation.
#include "stratum/analysis/l2_discrepancy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "stratum/analysis/measures.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {
namespace {

using Points = std::vector<double>;

PointView view(const Points& x, std::size_t d) { return {x.data(), x.size() / d, d}; }

Points uniform(std::size_t n, std::size_t d, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points x(n * d);
  for (auto& v : x) v = u(rng);
  return x;
}

double squared(L2Kind kind, const Points& x, std::size_t d, L2Algorithm algorithm = L2Algorithm::automatic,
               unsigned threads = 1) {
  L2Options options;
  options.algorithm = algorithm;
  options.threads = threads;
  return l2_discrepancy_squared(kind, view(x, d), options);
}

/// ∫ over the cells of the grid cut by {0, 1, the coordinates} (and ½ for the
/// centered discrepancy) of (count/N − volume)², for the coordinates in `axes`.
/// In a cell the count is constant and the volume a product of one-variable
/// factors t = x (anchored at 0) or t = |x − a| (nearest vertex a), so the
/// integral is c²/N²·Π len − 2c/N·Π ∫t + Π ∫t², exactly.
double box_integral(const Points& x, std::size_t d, const std::vector<std::size_t>& axes, bool centered) {
  const std::size_t n = x.size() / d;
  std::vector<std::vector<double>> cuts;
  for (std::size_t k : axes) {
    std::vector<double> c = {0.0, 1.0};
    if (centered) c.push_back(0.5);
    for (std::size_t i = 0; i < n; ++i) c.push_back(x[i * d + k]);
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    cuts.push_back(c);
  }
  double total = 0.0;
  std::vector<std::size_t> cell(axes.size(), 0);
  std::function<void(std::size_t)> walk = [&](std::size_t level) {
    if (level < axes.size()) {
      for (cell[level] = 0; cell[level] + 1 < cuts[level].size(); ++cell[level]) walk(level + 1);
      return;
    }
    double length = 1, first = 1, second = 1;
    std::size_t count = 0;
    std::vector<double> lo(axes.size()), hi(axes.size());
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const double l = cuts[a][cell[a]], h = cuts[a][cell[a] + 1], mid = 0.5 * (l + h);
      const double vertex = centered && mid >= 0.5 ? 1.0 : 0.0;
      const double t0 = std::min(std::abs(l - vertex), std::abs(h - vertex));
      const double t1 = std::max(std::abs(l - vertex), std::abs(h - vertex));
      length *= h - l;
      first *= (t1 * t1 - t0 * t0) / 2;
      second *= (t1 * t1 * t1 - t0 * t0 * t0) / 3;
      lo[a] = std::min(vertex, mid);
      hi[a] = std::max(vertex, mid);
    }
    for (std::size_t i = 0; i < n; ++i) {
      bool inside = true;
      for (std::size_t a = 0; a < axes.size(); ++a) {
        const double p = x[i * d + axes[a]];
        inside = inside && p >= lo[a] && p <= hi[a];  // a cell interior never meets a coordinate
      }
      count += inside;
    }
    const double c = static_cast<double>(count) / n;
    total += c * c * length - 2 * c * first + second;
  };
  walk(0);
  return total;
}

/// Hickernell's centered discrepancy: the sum over every nonempty projection.
double centered_brute_force(const Points& x, std::size_t d) {
  double total = 0;
  for (unsigned mask = 1; mask < (1u << d); ++mask) {
    std::vector<std::size_t> axes;
    for (std::size_t k = 0; k < d; ++k)
      if (mask & (1u << k)) axes.push_back(k);
    total += box_integral(x, d, axes, true);
  }
  return total;
}

/// The formulas of l2_discrepancy.hpp transcribed as a plain loop over all ordered pairs.
double naive(L2Kind kind, const Points& x, std::size_t d) {
  const std::size_t n = x.size() / d;
  long double pairs = 0, single = 0;  // long double: the plain sums must not be the less accurate side
  for (std::size_t i = 0; i < n; ++i) {
    double h = 1;
    for (std::size_t k = 0; k < d; ++k) {
      const double v = x[i * d + k], c = std::abs(v - 0.5);
      h *= kind == L2Kind::star       ? 1 - v * v
           : kind == L2Kind::centered ? 1 + c / 2 - c * c / 2
                                      : 5.0 / 3 - c / 4 - c * c / 4;
    }
    single += h;
    for (std::size_t j = 0; j < n; ++j) {
      double g = 1;
      for (std::size_t k = 0; k < d; ++k) {
        const double a = x[i * d + k], b = x[j * d + k], t = std::abs(a - b);
        const double ca = std::abs(a - 0.5), cb = std::abs(b - 0.5);
        switch (kind) {
          case L2Kind::star:
            g *= 1 - std::max(a, b);
            break;
          case L2Kind::centered:
            g *= 1 + ca / 2 + cb / 2 - t / 2;
            break;
          case L2Kind::wrap_around:
            g *= 1.5 - t + t * t;
            break;
          case L2Kind::mixture:
            g *= 15.0 / 8 - ca / 4 - cb / 4 - 3 * t / 4 + t * t / 2;
            break;
        }
      }
      pairs += g;
    }
  }
  const long double dd = static_cast<long double>(d), nn = static_cast<long double>(n);
  switch (kind) {
    case L2Kind::star:
      return double(std::pow(3.0L, -dd) - std::pow(2.0L, 1 - dd) / nn * single + pairs / (nn * nn));
    case L2Kind::centered:
      return double(std::pow(13.0L / 12, dd) - 2 / nn * single + pairs / (nn * nn));
    case L2Kind::wrap_around:
      return double(-std::pow(4.0L / 3, dd) + pairs / (nn * nn));
    case L2Kind::mixture:
      return double(std::pow(19.0L / 12, dd) - 2 / nn * single + pairs / (nn * nn));
  }
  return 0;
}

TEST(L2Discrepancy, StarMatchesExactIntegrationOfTheLocalDiscrepancy) {
  for (std::size_t d = 1; d <= 3; ++d)
    for (std::size_t n = 1; n <= 7; ++n)
      for (unsigned seed = 0; seed < 3; ++seed) {
        Points x = uniform(n, d, 100 * seed + 10 * d + n);
        if (seed == 2) {  // ties, and points on the faces
          for (auto& v : x) v = std::round(v * 4) / 4;
        }
        std::vector<std::size_t> axes(d);
        for (std::size_t k = 0; k < d; ++k) axes[k] = k;
        const double exact = box_integral(x, d, axes, false);
        for (auto algorithm : {L2Algorithm::pairwise, L2Algorithm::fast})
          EXPECT_NEAR(squared(L2Kind::star, x, d, algorithm), exact, 1e-13 + 1e-11 * exact) << d << " " << n;
      }
}

TEST(L2Discrepancy, CenteredMatchesExactIntegrationOverProjections) {
  for (std::size_t d = 1; d <= 3; ++d)
    for (std::size_t n = 1; n <= 6; ++n)
      for (unsigned seed = 0; seed < 3; ++seed) {
        Points x = uniform(n, d, 7 + 100 * seed + 10 * d + n);
        if (seed == 2) {
          for (auto& v : x) v = std::round(v * 4) / 4;
        }
        const double exact = centered_brute_force(x, d);
        EXPECT_NEAR(squared(L2Kind::centered, x, d), exact, 1e-13 + 1e-11 * exact) << d << " " << n;
      }
}

TEST(L2Discrepancy, HammersleyClosedForm) {
  // N = 2^m points (i/N, φ2(i)): (N·L2*)² = m²/64 + 29m/192 + 3/8 − m/2^(m+4) + 1/2^(m+2) − 1/(72·4^m)
  // (Halton & Zaremba 1969, "The extreme and L2 discrepancies of some plane sets").
  for (unsigned m = 1; m <= 16; ++m) {
    const std::size_t n = std::size_t{1} << m;
    Points x(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t reversed = 0;
      for (unsigned b = 0; b < m; ++b) reversed |= ((i >> b) & 1u) << (m - 1 - b);
      x[2 * i] = static_cast<double>(i) / n;
      x[2 * i + 1] = static_cast<double>(reversed) / n;
    }
    const double mm = m, nn = static_cast<double>(n);
    const double closed =
        (mm * mm / 64 + 29 * mm / 192 + 3.0 / 8 - mm / (16 * nn) + 1 / (4 * nn) - 1 / (72 * nn * nn)) / (nn * nn);
    // D² is a difference of O(1/9) terms: long double (eps 1.1e-19) bounds its absolute accuracy near 1e-19,
    // which is 6e-11 relative at m = 16 (D² = 1.6e-9); below m = 15 the 1e-12 relative bound is the tighter one.
    EXPECT_NEAR(squared(L2Kind::star, x, 2, L2Algorithm::fast), closed, std::max(1e-12 * closed, 1e-19)) << m;
    if (m <= 11) {
      EXPECT_NEAR(squared(L2Kind::star, x, 2, L2Algorithm::pairwise), closed, 1e-10 * closed) << m;
    }
  }
}

TEST(L2Discrepancy, PublishedValues) {
  // Fang, Li, Sudjianto 2006, "Design and modeling for computer experiments": CD² of two 6-run designs.
  auto design = [](std::vector<int> levels, int q) {
    Points x;
    for (int v : levels) x.push_back((2.0 * v - 1) / (2.0 * q));
    return x;
  };
  const Points space1 = design({1, 3, 2, 6, 3, 2, 4, 5, 5, 1, 6, 4}, 6);
  const Points space2 = design({1, 5, 2, 4, 3, 3, 4, 2, 5, 1, 6, 6}, 6);
  EXPECT_NEAR(squared(L2Kind::centered, space1, 2), 0.0081, 5e-5);
  EXPECT_NEAR(squared(L2Kind::centered, space2, 2), 0.0105, 5e-5);
  // Zhou, Fang, Ning 2013, "Mixture discrepancy for quasi-random point sets", Example 4: a 7-run, 2-level design in 6D.
  const Points zhou = design({2, 1, 1, 2, 2, 2, 1, 2, 2, 2, 2, 2, 2, 1, 1, 1, 1, 1, 1, 1, 1,
                              1, 2, 2, 1, 2, 2, 2, 1, 1, 2, 2, 2, 2, 1, 1, 2, 2, 2, 1, 2, 2},
                             2);
  EXPECT_NEAR(squared(L2Kind::mixture, zhou, 6), 2.5000, 5e-5);
  EXPECT_NEAR(squared(L2Kind::wrap_around, zhou, 6), 1.3680, 5e-5);
  EXPECT_NEAR(squared(L2Kind::centered, zhou, 6), 0.3172, 5e-5);
  // Pillards, Vandewoestyne, Cools 2005: one point at the far corner has L2* = 3^(−d/2).
  for (std::size_t d : {2, 4, 8, 16, 32, 64}) {
    const Points corner(d, 1.0);
    EXPECT_NEAR(squared(L2Kind::star, corner, d, L2Algorithm::pairwise), std::pow(3.0, -double(d)),
                1e-14 * std::pow(3.0, -double(d)));
  }
}

TEST(L2Discrepancy, TiledSymmetricKernelEqualsPlainLoop) {
  for (std::size_t d : {1, 4, 7})
    for (std::size_t n : {1, 2, 31, 32, 33, 255, 257, 600}) {
      const Points x = uniform(n, d, static_cast<unsigned>(n * 13 + d));
      for (auto kind : {L2Kind::star, L2Kind::centered, L2Kind::wrap_around, L2Kind::mixture}) {
        const double reference = naive(kind, x, d);
        const double one = squared(kind, x, d, L2Algorithm::pairwise, 1);
        EXPECT_NEAR(one, reference, 1e-12 * std::abs(reference) + 1e-15) << int(kind) << " " << d << " " << n;
        EXPECT_EQ(one, squared(kind, x, d, L2Algorithm::pairwise, 3)) << "thread count changed the result";
      }
    }
}

TEST(L2Discrepancy, FastStarEqualsWarnockOnRandomInputs) {
  for (std::size_t d = 1; d <= 3; ++d)
    for (std::size_t n : {2, 3, 17, 100, 1000, 4000}) {
      const Points x = uniform(n, d, static_cast<unsigned>(7 * n + d));
      const double fast = squared(L2Kind::star, x, d, L2Algorithm::fast);
      const double slow = squared(L2Kind::star, x, d, L2Algorithm::pairwise);
      EXPECT_NEAR(fast, slow, 1e-10 * slow) << d << " " << n;
    }
  const Points x = uniform(10, 4, 1);
  EXPECT_THROW(squared(L2Kind::star, x, 4, L2Algorithm::fast), invalid_argument);
  EXPECT_THROW(squared(L2Kind::centered, x, 4, L2Algorithm::fast), invalid_argument);
}

TEST(L2Discrepancy, WrapAroundIsInvariantUnderShiftsModuloOne) {
  const std::size_t d = 3;
  const Points x = uniform(200, d, 11);
  Points shifted = x;
  const double shift[d] = {0.3, 0.77, 0.05};
  for (std::size_t i = 0; i < shifted.size(); ++i) shifted[i] = std::fmod(shifted[i] + shift[i % d], 1.0);
  const double original = squared(L2Kind::wrap_around, x, d);
  EXPECT_NEAR(squared(L2Kind::wrap_around, shifted, d), original, 1e-11 * original);
  // ... while the star and centered discrepancies do change.
  EXPECT_GT(std::abs(squared(L2Kind::centered, shifted, d) - squared(L2Kind::centered, x, d)), 1e-6);
}

TEST(L2Discrepancy, CenteredUpdateEqualsRecomputation) {
  for (std::size_t d : {1, 2, 10})
    for (std::size_t n : {2, 5, 100}) {
      const Points x = uniform(n, d, static_cast<unsigned>(n + 31 * d));
      const Points head(x.begin(), x.end() - static_cast<std::ptrdiff_t>(d));
      L2Options iterative;
      iterative.iterative = true;
      const double initial = l2_discrepancy_squared(L2Kind::centered, view(head, d), iterative);
      const double updated = l2_centered_update(x.data() + (n - 1) * d, view(head, d), initial);
      const double direct = squared(L2Kind::centered, x, d);
      EXPECT_NEAR(updated, direct, 1e-12 * direct) << d << " " << n;
    }
}

TEST(L2Discrepancy, RegistryReportsTheRootWithTheSquareInExtras) {
  const Points x = uniform(300, 3, 5);
  const std::pair<const char*, L2Kind> names[] = {
      {"l2-star", L2Kind::star}, {"cd", L2Kind::centered}, {"wd", L2Kind::wrap_around}, {"md", L2Kind::mixture}};
  for (const auto& [name, kind] : names) {
    const MeasureResult r = compute_measure(name, view(x, 3), {});
    EXPECT_EQ(r.kind, "exact");
    EXPECT_NEAR(r.extras.at("squared"), squared(kind, x, 3), 1e-12 * r.extras.at("squared")) << name;
    EXPECT_DOUBLE_EQ(r.value, std::sqrt(r.extras.at("squared"))) << name;
  }
  const Points wide = uniform(10, 5, 2);
  try {
    compute_measure("l2-star", view(wide, 5), {{{"algorithm", "fast"}}, 1});
    ADD_FAILURE() << "fast accepted d = 5";
  } catch (const invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("algorithm=warnock"), std::string::npos) << error.what();
  }
  EXPECT_THROW(compute_measure("l2-star", view(x, 3), {{{"algorithm", "quick"}}, 1}), invalid_argument);
}

}  // namespace
}  // namespace stratum::analysis
