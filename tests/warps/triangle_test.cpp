#include "stratum/warps/triangle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "chi2.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

using A2 = std::array<double, 2>;
using A3 = std::array<double, 3>;

const UniformTriangle<double, 2> planar({0.2, -0.5}, {1.5, 0.3}, {-0.4, 1.1});
// A triangle in space, tilted out of every coordinate plane.
const UniformTriangle<double, 3> spatial({1, 0, 0.5}, {0, 2, -1}, {-1, -0.5, 2});

// Two members of the χ² family (tests/warps/chi2.hpp: Šidák at family α = 0.01).
class WarpTriangleChi2 : public testing::Chi2Fixture<> {};

// χ² on the bounding box grid; the edges cut cells, hence the fine quadrature subgrid.
TEST_F(WarpTriangleChi2, Planar) {
  const testing::SampleFn sample = [](const double* u, double* out) {
    const A2 p = planar.sample({u[0], u[1]});
    out[0] = p[0], out[1] = p[1];
  };
  const testing::PdfFn pdf = [](const double* p) { return planar.pdf({p[0], p[1]}); };
  testing::Chi2Options options;
  options.subdivisions = 32;
  testing::expect_chi2(testing::chi2_test(sample, pdf, testing::Domain::box(-0.4, 1.5, -0.5, 1.1, 16, 16), options));
}

// The spatial triangle: χ² on its points' first two barycentric coordinates,
// which are uniform on the reference triangle {b0, b1 >= 0, b0 + b1 <= 1} with
// density 2 (an affine image keeps uniformity; the barycentrics come from an
// independent least-squares solve here).
TEST_F(WarpTriangleChi2, Spatial) {
  const A3 v0 = {1, 0, 0.5}, v1 = {0, 2, -1}, v2 = {-1, -0.5, 2};
  const testing::SampleFn sample = [&](const double* u, double* out) {
    const A3 p = spatial.sample({u[0], u[1]});
    // Solve p − v2 = b0 (v0 − v2) + b1 (v1 − v2) with the x and y rows (Cramer).
    const double a = v0[0] - v2[0], b = v1[0] - v2[0], c = v0[1] - v2[1], d = v1[1] - v2[1];
    const double rx = p[0] - v2[0], ry = p[1] - v2[1], det = a * d - b * c;
    out[0] = (rx * d - b * ry) / det, out[1] = (a * ry - c * rx) / det;
  };
  const testing::PdfFn pdf = [](const double* b) { return b[0] >= 0 && b[1] >= 0 && b[0] + b[1] <= 1 ? 2.0 : 0.0; };
  testing::Chi2Options options;
  options.subdivisions = 32;
  testing::expect_chi2(testing::chi2_test(sample, pdf, testing::Domain::box(0, 1, 0, 1, 14, 14), options));
}

TEST(WarpTriangle, ClosedForms) {
  // Area by the shoelace formula: |(1.3)(1.6) − (0.8)(−0.6)| / 2 = 1.28.
  EXPECT_NEAR(planar.area(), 1.28, 1e-14);
  EXPECT_NEAR(planar.pdf({0.4, 0.3}), 1 / 1.28, 1e-14);
  EXPECT_EQ(planar.pdf({1.5, 1.1}), 0.0);
  // Spatial area: |e0 × e1| / 2 with e0 = (2, 0.5, −1.5), e1 = (1, 2.5, −3).
  const A3 e0 = {2, 0.5, -1.5}, e1 = {1, 2.5, -3};
  const double cx = e0[1] * e1[2] - e0[2] * e1[1], cy = e0[2] * e1[0] - e0[0] * e1[2],
               cz = e0[0] * e1[1] - e0[1] * e1[0];
  EXPECT_NEAR(spatial.area(), std::sqrt(cx * cx + cy * cy + cz * cz) / 2, 1e-14);
  // Heitz's map sends the corners (0,0), (1,0), (1,1) to v2, v0, v1... u = (1, 0) → b = (1, 0) = v0.
  const A2 corner = planar.sample({1, 0});
  EXPECT_NEAR(corner[0], 0.2, 1e-15);
  EXPECT_NEAR(corner[1], -0.5, 1e-15);
  // The centroid is u = (2/3, 1/3)·... b = (1/3, 1/3): u0 ≥ u1 branch, u1 = 2/3, u0 = 2/3 → tie goes to b0 ≥ b1.
  const A2 centroid = planar.sample({2.0 / 3, 2.0 / 3});
  EXPECT_NEAR(centroid[0], (0.2 + 1.5 - 0.4) / 3, 1e-15);
  EXPECT_NEAR(centroid[1], (-0.5 + 0.3 + 1.1) / 3, 1e-15);
  // A point off the spatial triangle's plane has density 0.
  const A3 on = spatial.sample({0.3, 0.6});
  EXPECT_GT(spatial.pdf(on), 0.0);
  EXPECT_EQ(spatial.pdf({on[0] + 1e-3, on[1], on[2]}), 0.0);
}

TEST(WarpTriangle, InverseRoundTrip) {
  for (int k = 0; k < 20000; ++k) {
    const A2 u = {uniform01(3, k, 0), uniform01(3, k, 1)};
    const A2 p2 = planar.sample(u);
    const A3 p3 = spatial.sample(u);
    const A2 b2 = planar.invert(p2), b3 = spatial.invert(p3);
    for (int c = 0; c < 2; ++c) {
      ASSERT_NEAR(b2[c], u[c], 1e-12) << k;
      ASSERT_NEAR(b3[c], u[c], 1e-12) << k;
    }
    const A3 again = spatial.sample(b3);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(again[c], p3[c], 1e-12) << k;
  }
}

// ∫ pdf dA over the bounding box by Gauss–Legendre on a 32 × 32 grid of
// cells of 64² sub-panels (the edges cut sub-panels: tolerance 2e-4 for this
// indicator, whose error is a fraction of a sub-panel per crossing).
TEST(WarpTriangle, PdfIntegratesToOne) {
  const auto domain = testing::Domain::box(-0.4, 1.5, -0.5, 1.1, 32, 32);
  double total = 0;
  for (long j = 0; j < 32; ++j)
    for (long i = 0; i < 32; ++i)
      total += testing::bin_mass([](const double* p) { return planar.pdf({p[0], p[1]}); }, domain, i, j, 64);
  EXPECT_NEAR(total, 1.0, 2e-4);
}

// Area-preserving: an n × n jittered grid puts one point in each image cell.
// Image cells of Heitz's map, written from its geometry: the square's lower
// triangle u0 ≥ u1 maps linearly to b0 ≥ b1, so a point's cell is found from
// (u0, u1) = (b0 + b1, 2 b1) there and (2 b0, b0 + b1) on the other half.
TEST(WarpTriangle, StratifiedInputStaysStratified) {
  const int n = 16;
  const testing::SampleFn sample = [](const double* u, double* out) {
    const A2 p = planar.sample({u[0], u[1]});
    out[0] = p[0], out[1] = p[1];
  };
  const auto cell = [](const double* p) -> long {
    // Barycentrics by Cramer's rule from the vertices directly.
    const double a = 0.2 + 0.4, b = 1.5 + 0.4, c = -0.5 - 1.1, d = 0.3 - 1.1;
    const double rx = p[0] + 0.4, ry = p[1] - 1.1, det = a * d - b * c;
    const double b0 = (rx * d - b * ry) / det, b1 = (a * ry - c * rx) / det;
    const double u0 = b0 >= b1 ? b0 + b1 : 2 * b0, u1 = b0 >= b1 ? 2 * b1 : b0 + b1;
    return std::min<long>(n - 1, long(u1 * n)) * n + std::min<long>(n - 1, long(u0 * n));
  };
  const auto hits = testing::stratum_hits(sample, n, n, 5, cell, n * n);
  for (long c = 0; c < n * n; ++c) EXPECT_EQ(hits[c], 1) << c;
}

TEST(WarpTriangle, FloatAgreesWithDouble) {
  const UniformTriangle<float, 3> f({1, 0, 0.5f}, {0, 2, -1}, {-1, -0.5f, 2});
  for (int k = 0; k < 5000; ++k) {
    const float u0 = uniform01<float>(9, k, 0), u1 = uniform01<float>(9, k, 1);
    const auto pf = f.sample({u0, u1});
    const auto pd = spatial.sample({u0, u1});
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(pf[c], pd[c], 1e-5) << k;
    ASSERT_NEAR(f.pdf(pf), spatial.pdf(pd), 1e-5);
    const auto uf = f.invert(pf);
    ASSERT_NEAR(uf[0], u0, 1e-4) << k;
    ASSERT_NEAR(uf[1], u1, 1e-4) << k;
  }
}

TEST(WarpTriangle, DegenerateTriangleRejected) {
  const auto error_of = [](A2 a, A2 b, A2 c) -> std::string {
    try {
      UniformTriangle<double, 2> t(a, b, c);
    } catch (const invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of({0, 0}, {1, 1}, {2, 2}).find("invalid vertices"), std::string::npos);  // collinear
  EXPECT_NE(error_of({1, 1}, {1, 1}, {1, 1}).find("degenerate"), std::string::npos);        // one point
  EXPECT_NE(error_of({0, 0}, {1, 0}, {NAN, 1}).find("finite"), std::string::npos);
  EXPECT_EQ(error_of({0, 0}, {1e-3, 0}, {0, 1e-3}), "");  // small is fine
}

}  // namespace
}  // namespace stratum
