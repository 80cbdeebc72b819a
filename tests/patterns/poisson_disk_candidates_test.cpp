#include "stratum/patterns/poisson_disk_candidates.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <numbers>
#include <vector>

namespace stratum::poisson_detail {
namespace {

// Šidák-corrected critical value: 12 χ² tests below at family-wise level 1e-3.
double critical(double dof) {
  const double alpha = 1 - std::pow(1 - 1e-3, 1.0 / 12);
  return boost::math::quantile(boost::math::complement(boost::math::chi_squared(dof), alpha));
}

// χ² of the radius |offset| against the uniform-by-volume law on [r, 2r):
// P(|o| < t) = (t^d - r^d) / ((2r)^d - r^d), in 20 equiprobable bins.
template <class Offset>
double radial_chi2(unsigned d, double r, Offset offset, int samples) {
  std::vector<int> bins(20, 0);
  double o[8];
  for (int k = 0; k < samples; ++k) {
    offset(static_cast<std::uint64_t>(k / 64), static_cast<unsigned>(k % 64), o);
    double norm2 = 0;
    for (unsigned j = 0; j < d; ++j) norm2 += o[j] * o[j];
    const double t = std::sqrt(norm2);
    EXPECT_GE(t, r * (1 - 1e-12));
    EXPECT_LT(t, 2 * r * (1 + 1e-12));
    const double u = (std::pow(t / r, d) - 1) / (std::pow(2.0, d) - 1);
    ++bins[std::min(19, static_cast<int>(u * 20))];
  }
  double chi2 = 0;
  for (int b : bins) chi2 += (b - samples / 20.0) * (b - samples / 20.0) / (samples / 20.0);
  return chi2;
}

TEST(AnnulusOffset, UniformByVolumeInTheAnnulus) {
  for (unsigned d = 1; d <= 6; ++d) {
    const double r = 0.01;
    const double chi2 = radial_chi2(
        d, r, [&](std::uint64_t step, unsigned c, double* o) { annulus_offset(d, r, hash64(7, step), c, o); }, 40000);
    EXPECT_LT(chi2, critical(19)) << "d=" << d;
  }
  const double chi2 = radial_chi2(
      2, 0.3, [](std::uint64_t step, unsigned c, double* o) { annulus_offset_2d(0.3, hash64(7, step), c, o); }, 40000);
  EXPECT_LT(chi2, critical(19));
}

// Directions are uniform: angles of the 2D offsets in 64 bins (the table
// has 256 sectors; 64 bins test the sector choice and the turn together),
// and for d = 3..6 the sign pattern of the first two coordinates (4 bins).
TEST(AnnulusOffset, DirectionsAreUniform) {
  const int samples = 64000;
  std::vector<int> bins(64, 0);
  for (int k = 0; k < samples; ++k) {
    double o[2];
    annulus_offset_2d(1.0, hash64(3, k / 16), static_cast<unsigned>(k % 16), o);
    const double angle = std::atan2(o[1], o[0]) / (2 * std::numbers::pi) + 0.5;
    ++bins[std::min(63, static_cast<int>(angle * 64))];
  }
  double chi2 = 0;
  for (int b : bins) chi2 += (b - samples / 64.0) * (b - samples / 64.0) / (samples / 64.0);
  EXPECT_LT(chi2, critical(63));
  for (unsigned d = 3; d <= 6; ++d) {
    std::vector<int> quadrants(4, 0);
    for (int k = 0; k < 20000; ++k) {
      double o[8];
      annulus_offset(d, 1.0, hash64(5, k / 8), static_cast<unsigned>(k % 8), o);
      ++quadrants[(o[0] > 0) + 2 * (o[1] > 0)];
    }
    double q2 = 0;
    for (int b : quadrants) q2 += (b - 5000.0) * (b - 5000.0) / 5000.0;
    EXPECT_LT(q2, critical(3)) << "d=" << d;
  }
}

// The 2D fast path's directions are unit vectors to rounding: |offset| is
// exactly the radius drawn from the word's low 28 bits.
TEST(AnnulusOffset, TableDirectionsHaveUnitLength) {
  for (int k = 0; k < 1000; ++k) {
    double o[2];
    annulus_offset_2d(1.0, hash64(1, k), 0, o);
    const double length = std::hypot(o[0], o[1]);
    const std::uint64_t bits = mix64(hash64(1, k) + 0x9e3779b97f4a7c15ULL);
    const double expected = std::sqrt(1 + 3 * static_cast<double>(bits & 0xfffffffu) * 0x1.0p-28);
    EXPECT_NEAR(length / expected, 1.0, 1e-15);
  }
}

// The float screen of the batched Bridson kernel approximates the exact
// candidates within the bound its safety margin assumes (10^-5·2r; see
// CompactPoissonDisk::grow_plane), for small and large radii alike.
TEST(AnnulusOffset, FloatScreenIsWithinItsErrorBound) {
  for (double r : {1e-5, 0.01, 0.3}) {
    double worst = 0;
    for (int step = 0; step < 5000; ++step) {
      const std::uint64_t key = hash64(9, step);
      const unsigned first = 8 * static_cast<unsigned>(step % 5);
      floats8 x, y;
      annulus_offsets_2d_float(static_cast<float>(r), key, first, x, y, unit_circle_256_float());
      for (unsigned lane = 0; lane < 8; ++lane) {
        double o[2];
        annulus_offset_2d(r, key, first + lane, o);
        worst = std::max(worst, std::hypot(x[lane] - o[0], y[lane] - o[1]));
      }
    }
    EXPECT_LT(worst, 1e-5 * 2 * r) << "r=" << r;
    EXPECT_GT(worst, 0.0) << "a float screen differs from the double candidates";
  }
}

}  // namespace
}  // namespace stratum::poisson_detail
