#include "stratum/warps/disk.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "chi2.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

using A2 = std::array<double, 2>;

testing::SampleFn sampler(A2 (*map)(A2)) {
  return [map](const double* u, double* out) {
    const A2 p = map({u[0], u[1]});
    out[0] = p[0], out[1] = p[1];
  };
}
const testing::PdfFn disk_pdf = [](const double* p) { return uniform_disk_pdf<double>({p[0], p[1]}); };

// χ² against the uniform density, binned on the disk in equal-area (r², φ)
// cells and, independently, on the bounding box grid: one test of the χ²
// family (tests/warps/chi2.hpp: Šidák at family α = 0.01) per map and binning.
struct DiskCase {
  const char* name;
  A2 (*map)(A2);
  bool box_bins;  // false: equal-area polar cells
};

void PrintTo(const DiskCase& c, std::ostream* out) { *out << c.name; }  // ctest's names show the case

class WarpDiskChi2 : public testing::Chi2Fixture<::testing::TestWithParam<DiskCase>> {};

TEST_P(WarpDiskChi2, UniformOnTheDisk) {
  const DiskCase& c = GetParam();
  testing::Chi2Options options;
  if (c.box_bins) options.subdivisions = 32;  // the disk's rim cuts the box cells: a finer quadrature subgrid
  const auto domain = c.box_bins ? testing::Domain::box(-1, 1, -1, 1, 16, 16) : testing::Domain::disk(1, 10, 20);
  testing::expect_chi2(testing::chi2_test(sampler(c.map), disk_pdf, domain, options), c.name);
}

INSTANTIATE_TEST_SUITE_P(Maps, WarpDiskChi2,
                         ::testing::Values(DiskCase{"polar, polar bins", sample_polar_disk<double>, false},
                                           DiskCase{"polar, box bins", sample_polar_disk<double>, true},
                                           DiskCase{"concentric, polar bins", sample_concentric_disk<double>, false},
                                           DiskCase{"concentric, box bins", sample_concentric_disk<double>, true}),
                         [](const auto& info) { return testing::chi2_param_name(info.param.name); });

// The χ² test can fail: a disk sampled with r = u1 (not √u1) is rejected.
TEST(WarpDisk, Chi2RejectsWrongRadius) {
  const testing::SampleFn wrong = [](const double* u, double* out) {
    out[0] = u[1] * std::cos(2 * std::numbers::pi * u[0]), out[1] = u[1] * std::sin(2 * std::numbers::pi * u[0]);
  };
  EXPECT_LT(testing::chi2_test(wrong, disk_pdf, testing::Domain::disk(1, 10, 20)).p_value, 1e-12);
}

TEST(WarpDisk, ClosedForms) {
  const A2 center = sample_concentric_disk<double>({0.5, 0.5});
  EXPECT_EQ(center[0], 0.0);
  EXPECT_EQ(center[1], 0.0);
  // (1, 0.5) is the middle of the right edge: a = 1, b = 0 → (1, 0); (0.5, 1) → top (0, 1).
  const A2 right = sample_concentric_disk<double>({1.0, 0.5});
  EXPECT_NEAR(right[0], 1.0, 1e-15);
  EXPECT_NEAR(right[1], 0.0, 1e-15);
  const A2 top = sample_concentric_disk<double>({0.5, 1.0});
  EXPECT_NEAR(top[0], 0.0, 1e-15);
  EXPECT_NEAR(top[1], 1.0, 1e-15);
  // Corner (1, 1): a = b = 1 → r = 1, φ = π/4.
  const A2 corner = sample_concentric_disk<double>({1.0, 1.0});
  EXPECT_NEAR(corner[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(corner[1], std::sqrt(0.5), 1e-15);
  // Polar: u = (0.25, 0.25) → θ = π/2, r = 0.5.
  const A2 polar = sample_polar_disk<double>({0.25, 0.25});
  EXPECT_NEAR(polar[0], 0.0, 1e-15);
  EXPECT_NEAR(polar[1], 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(polar_disk_pdf<double>({0.3, 0.4}), 1 / std::numbers::pi);
  EXPECT_EQ(concentric_disk_pdf<double>({0.8, 0.7}), 0.0);
}

TEST(WarpDisk, InverseRoundTrip) {
  for (int k = 0; k < 20000; ++k) {
    const A2 u = {uniform01(7, k, 0), uniform01(7, k, 1)};
    for (auto [map, inverse] : {std::pair{&sample_polar_disk<double>, &invert_polar_disk<double>},
                                std::pair{&sample_concentric_disk<double>, &invert_concentric_disk<double>}}) {
      const A2 p = map(u);
      const A2 back = inverse(p);
      ASSERT_NEAR(back[0], u[0], 1e-12) << k;
      ASSERT_NEAR(back[1], u[1], 1e-12) << k;
      const A2 again = map(back);
      ASSERT_NEAR(again[0], p[0], 1e-12) << k;
      ASSERT_NEAR(again[1], p[1], 1e-12) << k;
    }
  }
  const A2 origin = invert_concentric_disk<double>({0, 0});
  EXPECT_EQ(origin[0], 0.5);
  EXPECT_EQ(origin[1], 0.5);
}

// The pdf integrates to 1 over the bounding box (midpoint rule on a 2048² grid;
// the rim cuts cells, so the tolerance is that of an indicator: 1e-3).
TEST(WarpDisk, PdfIntegratesToOne) {
  const int m = 2048;
  double sum = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) sum += uniform_disk_pdf<double>({-1 + (i + 0.5) * 2.0 / m, -1 + (j + 0.5) * 2.0 / m});
  EXPECT_NEAR(sum * 4.0 / (double(m) * m), 1.0, 1e-3);
}

// Stratification: an n × n jittered grid through the polar map puts one point
// in each annular sector r² ∈ [j/n, (j+1)/n), θ ∈ [2πi/n, 2π(i+1)/n); through
// the concentric map, one point in each image of a square cell, identified by
// the concentric rings (|a| or |b| = r) and wedge positions written out here.
TEST(WarpDisk, StratifiedInputStaysStratified) {
  const int n = 16;
  const auto sector = [](const double* p) -> long {
    const double r2 = p[0] * p[0] + p[1] * p[1];
    const double theta = angle_0_2pi(p[1], p[0]);
    const long i = std::min<long>(n - 1, static_cast<long>(theta / (2 * std::numbers::pi) * n));
    const long j = std::min<long>(n - 1, static_cast<long>(r2 * n));
    return j * n + i;
  };
  auto hits = testing::stratum_hits(sampler(sample_polar_disk<double>), n, n, 3, sector, n * n);
  for (long c = 0; c < n * n; ++c) EXPECT_EQ(hits[c], 1) << "polar cell " << c;
  // Concentric: on the wedge |x| >= |y| the point came from a = ±r, b = a φ/(π/4) with φ the angle from the x axis.
  const auto square_cell = [](const double* p) -> long {
    const double r = std::hypot(p[0], p[1]);
    double a, b;
    if (std::abs(p[0]) >= std::abs(p[1])) {
      a = p[0] >= 0 ? r : -r;
      b = a * std::atan(p[1] / p[0]) / (std::numbers::pi / 4);
    } else {
      b = p[1] >= 0 ? r : -r;
      a = b * std::atan(p[0] / p[1]) / (std::numbers::pi / 4);
    }
    const long i = std::min<long>(n - 1, static_cast<long>((a + 1) / 2 * n));
    const long j = std::min<long>(n - 1, static_cast<long>((b + 1) / 2 * n));
    return j * n + i;
  };
  hits = testing::stratum_hits(sampler(sample_concentric_disk<double>), n, n, 4, square_cell, n * n);
  for (long c = 0; c < n * n; ++c) EXPECT_EQ(hits[c], 1) << "concentric cell " << c;
}

TEST(WarpDisk, FloatAgreesWithDouble) {
  for (int k = 0; k < 5000; ++k) {
    const float u0 = uniform01<float>(9, k, 0), u1 = uniform01<float>(9, k, 1);
    for (auto [mf, md] : {std::pair{&sample_polar_disk<float>, &sample_polar_disk<double>},
                          std::pair{&sample_concentric_disk<float>, &sample_concentric_disk<double>}}) {
      const auto pf = mf({u0, u1});
      const auto pd = md({u0, u1});
      ASSERT_NEAR(pf[0], pd[0], 4e-6) << k;
      ASSERT_NEAR(pf[1], pd[1], 4e-6) << k;
    }
    const auto bf = invert_concentric_disk<float>(sample_concentric_disk<float>({u0, u1}));
    ASSERT_NEAR(bf[0], u0, 4e-6) << k;
    ASSERT_NEAR(bf[1], u1, 4e-6) << k;
  }
}

}  // namespace
}  // namespace stratum
