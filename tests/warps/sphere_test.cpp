#include "stratum/warps/sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "chi2.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

using A2 = std::array<double, 2>;
using A3 = std::array<double, 3>;

struct Triad {
  const char* name;
  std::function<A3(A2)> sample;
  std::function<double(A3)> pdf;
  std::function<A2(A3)> invert;
  double z_min;  // the domain is z >= z_min
  bool area_preserving;
};

std::vector<Triad> triads() {
  const UniformCone<double> cone(0.5), wide_cone(-0.3);
  return {
      {"hemisphere-uniform", sample_uniform_hemisphere<double>, uniform_hemisphere_pdf<double>,
       invert_uniform_hemisphere<double>, 0, true},
      {"hemisphere-cosine", sample_cosine_hemisphere<double>, cosine_hemisphere_pdf<double>,
       invert_cosine_hemisphere<double>, 0, false},
      {"sphere-uniform", sample_uniform_sphere<double>, uniform_sphere_pdf<double>, invert_uniform_sphere<double>, -1,
       true},
      {"cone 0.5", [cone](A2 u) { return cone.sample(u); }, [cone](A3 p) { return cone.pdf(p); },
       [cone](A3 p) { return cone.invert(p); }, 0.5, true},
      {"cone -0.3", [wide_cone](A2 u) { return wide_cone.sample(u); }, [wide_cone](A3 p) { return wide_cone.pdf(p); },
       [wide_cone](A3 p) { return wide_cone.invert(p); }, -0.3, true},
  };
}

// χ² with equal-solid-angle (cos θ, φ) bins over the whole sphere (so mass
// outside the domain would show), one test of the χ² family per triad
// (tests/warps/chi2.hpp: Šidák at family α = 0.01).
void PrintTo(const Triad& t, std::ostream* out) { *out << t.name; }  // ctest's names show the case

class WarpSphereChi2 : public testing::Chi2Fixture<::testing::TestWithParam<Triad>> {};

TEST_P(WarpSphereChi2, MatchesPdf) {
  const Triad& t = GetParam();
  const testing::SampleFn sample = [&](const double* u, double* out) {
    const A3 p = t.sample({u[0], u[1]});
    out[0] = p[0], out[1] = p[1], out[2] = p[2];
  };
  const testing::PdfFn pdf = [&](const double* p) { return t.pdf({p[0], p[1], p[2]}); };
  // The caps' edges z = 0, 0.5, −0.3 lie on bin edges, where the open quadrature rule is exact.
  testing::expect_chi2(testing::chi2_test(sample, pdf, testing::Domain::directions(-1, 1, 20, 24)), t.name);
}

INSTANTIATE_TEST_SUITE_P(Triads, WarpSphereChi2, ::testing::ValuesIn(triads()),
                         [](const auto& info) { return testing::chi2_param_name(info.param.name); });

TEST(WarpSphere, SamplesAreUnitVectorsInTheDomain) {
  for (const auto& t : triads())
    for (int k = 0; k < 5000; ++k) {
      const A3 p = t.sample({uniform01(2, k, 0), uniform01(2, k, 1)});
      ASSERT_NEAR(p[0] * p[0] + p[1] * p[1] + p[2] * p[2], 1.0, 1e-14) << t.name;
      ASSERT_GE(p[2], t.z_min - 1e-15) << t.name;
      ASSERT_GT(t.pdf(p), 0.0) << t.name;
    }
}

TEST(WarpSphere, ClosedForms) {
  EXPECT_DOUBLE_EQ(cosine_hemisphere_pdf<double>({0, 0, 1}), 1 / std::numbers::pi);  // the pole
  const A3 pole = sample_cosine_hemisphere<double>({0.5, 0.5});
  EXPECT_EQ(pole[2], 1.0);
  EXPECT_DOUBLE_EQ(uniform_hemisphere_pdf<double>({1, 0, 0}), 0.5 / std::numbers::pi);
  EXPECT_EQ(uniform_hemisphere_pdf<double>({0, 0.6, -0.8}), 0.0);
  EXPECT_EQ(cosine_hemisphere_pdf<double>({0, 0.6, -0.8}), 0.0);
  EXPECT_DOUBLE_EQ(uniform_sphere_pdf<double>({0, 0.6, -0.8}), 0.25 / std::numbers::pi);
  // Cone: solid angle 2π(1 − cos θmax); cos θmax = −1 is the whole sphere.
  EXPECT_DOUBLE_EQ(UniformCone<double>(0.5).pdf({0, 0, 1}), 1 / std::numbers::pi);
  EXPECT_DOUBLE_EQ(UniformCone<double>(-1).pdf({0, 0, -1}), 0.25 / std::numbers::pi);
  EXPECT_EQ(UniformCone<double>(0.5).pdf({0, 0.8, 0.49}), 0.0);
  // u = (0, 0.25) is φ = π/2 at the rim z = 0 of the uniform hemisphere, and the pole z = 1 of the sphere.
  const A3 rim = sample_uniform_hemisphere<double>({0, 0.25});
  EXPECT_NEAR(rim[0], 0, 1e-15);
  EXPECT_NEAR(rim[1], 1, 1e-15);
  EXPECT_EQ(sample_uniform_sphere<double>({0, 0.25})[2], 1.0);
  EXPECT_DOUBLE_EQ(UniformCone<double>(0.5).sample({0.999999999, 0})[2], 0.5 + 0.5e-9);
}

TEST(WarpSphere, InverseRoundTrip) {
  for (const auto& t : triads())
    for (int k = 0; k < 20000; ++k) {
      const A2 u = {uniform01(5, k, 0), uniform01(5, k, 1)};
      const A3 p = t.sample(u);
      const A2 back = t.invert(p);
      // Near the pole the azimuth is ill-conditioned: compare points there, not u.
      if (std::abs(p[2]) < 1 - 1e-6) {
        ASSERT_NEAR(back[0], u[0], 1e-10) << t.name << " " << k;
        ASSERT_NEAR(back[1], u[1], 1e-10) << t.name << " " << k;
      }
      const A3 again = t.sample(back);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(again[c], p[c], 1e-12) << t.name << " " << k;
    }
}

// ∫ pdf dω = 1 by Gauss–Legendre in (z, φ) (dω = dz dφ), 200 × 200 panels; the
// cone's edge is a line of the grid, so the tolerance is that of smooth
// integrands: 1e-9.
TEST(WarpSphere, PdfIntegratesToOne) {
  for (const auto& t : triads()) {
    const double total = testing::bin_mass(
        [&](const double* p) {
          return t.pdf({p[0], p[1], p[2]});
        },
        testing::Domain::directions(t.z_min, 1, 1, 1), 0, 0, 200);
    EXPECT_NEAR(total, 1.0, 1e-9) << t.name;
  }
}

// The uniform maps are area-preserving: an n × n jittered grid gives one
// direction in each (z, φ) cell of the image, z-cells of equal height.
TEST(WarpSphere, StratifiedInputStaysStratified) {
  const int n = 12;
  for (const auto& t : triads()) {
    if (!t.area_preserving) continue;
    const testing::SampleFn sample = [&](const double* u, double* out) {
      const A3 p = t.sample({u[0], u[1]});
      out[0] = p[0], out[1] = p[1], out[2] = p[2];
    };
    const auto cell = [&](const double* p) -> long {
      const double z_fraction = (1 - p[2]) / (1 - t.z_min);  // 0 at the pole, 1 at z_min
      const double phi = angle_0_2pi(p[1], p[0]) / (2 * std::numbers::pi);
      return std::min<long>(n - 1, long(phi * n)) * n + std::min<long>(n - 1, long(z_fraction * n));
    };
    const auto hits = testing::stratum_hits(sample, n, n, 11, cell, n * n);
    for (long c = 0; c < n * n; ++c) EXPECT_EQ(hits[c], 1) << t.name << " cell " << c;
  }
}

TEST(WarpSphere, FloatAgreesWithDouble) {
  const UniformCone<float> cone_f(0.25f);
  const UniformCone<double> cone_d(0.25);
  for (int k = 0; k < 5000; ++k) {
    const float u0 = uniform01<float>(9, k, 0), u1 = uniform01<float>(9, k, 1);
    const std::array<std::array<float, 3>, 4> f = {sample_uniform_hemisphere<float>({u0, u1}),
                                                   sample_cosine_hemisphere<float>({u0, u1}),
                                                   sample_uniform_sphere<float>({u0, u1}), cone_f.sample({u0, u1})};
    const std::array<A3, 4> d = {sample_uniform_hemisphere<double>({u0, u1}),
                                 sample_cosine_hemisphere<double>({u0, u1}), sample_uniform_sphere<double>({u0, u1}),
                                 cone_d.sample({u0, u1})};
    for (int m = 0; m < 4; ++m)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(f[m][c], d[m][c], 2e-3 * std::sqrt(1e-3) + 1e-5) << m << " " << k;
    ASSERT_NEAR(cosine_hemisphere_pdf<float>(f[1]), cosine_hemisphere_pdf<double>(d[1]), 1e-5);
  }
}

TEST(WarpSphere, BadConeAngle) {
  for (double c : {1.0, 1.5, -1.0000001, std::nan("")}) {
    try {
      UniformCone<double> cone(c);
      ADD_FAILURE() << c;
    } catch (const invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("invalid cos_theta_max"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace stratum
