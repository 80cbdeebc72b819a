// The renderer's BSDFs (src/render/include/stratum/render/bsdf.hpp): the glossy lobe's
// sampling against its pdf (χ²), sample/pdf/eval consistency, and energy
// conservation of the normalized Phong lobe against quadrature.
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numbers>

#include "../warps/chi2.hpp"
#include "stratum/render/bsdf.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {
namespace {

constexpr double pi = std::numbers::pi;

Material glossy(double exponent, double rho = 0.8) {
  Material m;
  m.type = MaterialType::glossy;
  m.reflectance = {rho, rho, rho};
  m.exponent = exponent;
  return m;
}

/// wo at polar angle theta from the normal (0, 0, 1), in the xz-plane.
Vec3 incident(double theta_degrees) {
  const double t = theta_degrees * pi / 180;
  return {std::sin(t), 0, std::cos(t)};
}

// One test of the χ² family (tests/warps/chi2.hpp: Šidák at family α = 0.01)
// per exponent and incidence.
struct Lobe {
  const char* name;
  double exponent, theta_degrees;
};
void PrintTo(const Lobe& c, std::ostream* out) { *out << c.name; }  // ctest's names show the case

class RenderBsdfGlossyChi2 : public testing::Chi2Fixture<::testing::TestWithParam<Lobe>> {};

TEST_P(RenderBsdfGlossyChi2, SamplingMatchesItsPdf) {
  const Bsdf bsdf(glossy(GetParam().exponent), {0, 0, 1}, incident(GetParam().theta_degrees));
  const auto sample = [&](const double* u, double* out) {
    const Vec3 w = bsdf.sample({u[0], u[1]}).wi;
    out[0] = w.x, out[1] = w.y, out[2] = w.z;
  };
  const auto pdf = [&](const double* p) { return bsdf.pdf({p[0], p[1], p[2]}); };
  testing::expect_chi2(testing::chi2_test(sample, pdf, testing::Domain::directions(-1, 1, 40, 32)), GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(Lobes, RenderBsdfGlossyChi2,
                         ::testing::Values(Lobe{"exponent 3, theta 0", 3, 0}, Lobe{"exponent 3, theta 50", 3, 50},
                                           Lobe{"exponent 20, theta 0", 20, 0}, Lobe{"exponent 20, theta 50", 20, 50}),
                         [](const auto& info) { return testing::chi2_param_name(info.param.name); });

TEST(RenderBsdf, SamplesCarryTheirPdfAndWeight) {
  const Vec3 n = normalize(Vec3{0.3, -0.2, 1});
  const Vec3 wo = normalize(Vec3{-0.5, 0.4, 0.7});
  Material diffuse;
  diffuse.reflectance = {0.6, 0.5, 0.4};
  for (const Material& m : {diffuse, glossy(0), glossy(7), glossy(300)}) {
    const Bsdf bsdf(m, n, wo);
    int useful = 0;
    for (int i = 0; i < 2000; ++i) {
      const BsdfSample s = bsdf.sample({uniform01(5, i, 0), uniform01(5, i, 1)});
      EXPECT_NEAR(length(s.wi), 1.0, 1e-12);
      EXPECT_NEAR(bsdf.pdf(s.wi), s.pdf, 1e-9 * s.pdf);
      const Vec3 expected = bsdf.eval(s.wi) * (std::max(0.0, dot(n, s.wi)) / s.pdf);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], expected[c], 1e-9 * (1 + expected[c])) << m.exponent;
      useful += s.weight.x > 0;
    }
    EXPECT_GT(useful, 1000);  // most samples are above the surface
  }
}

/// Directional albedo ∫ f cos θ dω by a (θ, φ) midpoint rule on the hemisphere.
double albedo_by_quadrature(const Bsdf& bsdf) {
  const int nt = 800, np = 800;
  double sum = 0;
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const double t = (i + 0.5) * (pi / 2) / nt, p = (j + 0.5) * 2 * pi / np;
      const Vec3 w{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
      sum += bsdf.eval(w).x * std::cos(t) * std::sin(t);
    }
  return sum * (pi / 2 / nt) * (2 * pi / np);
}

TEST(RenderBsdf, GlossyLobeConservesEnergy) {
  // The Monte Carlo albedo E[f cos/p] agrees with quadrature of f cos (z-test,
  // Šidák over 9 cases at family α = 0.01), and never exceeds ρ; at normal
  // incidence it is ρ exactly (Lafortune, Willems 1994).
  const double rho = 0.8;
  const double z_max =
      boost::math::quantile(boost::math::complement(boost::math::normal(), testing::sidak_alpha(0.01, 9) / 2));
  for (double exponent : {1.0, 10.0, 100.0})
    for (double theta : {0.0, 45.0, 80.0}) {
      const Bsdf bsdf(glossy(exponent, rho), {0, 0, 1}, incident(theta));
      const int n = 200000;
      double sum = 0, sum2 = 0;
      for (int i = 0; i < n; ++i) {
        const double w = bsdf.sample({uniform01(9, i, 0), uniform01(9, i, 1)}).weight.x;
        sum += w, sum2 += w * w;
      }
      const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
      const double quadrature = albedo_by_quadrature(bsdf);
      EXPECT_LE(quadrature, rho * (1 + 1e-3)) << exponent << " " << theta;
      EXPECT_LT(std::abs(mean - quadrature), z_max * se + 1e-4) << exponent << " " << theta;
      EXPECT_LE(mean, rho + z_max * se);
      if (theta == 0) {
        EXPECT_NEAR(quadrature, rho, 2e-3) << exponent;
      }
    }
}

}  // namespace
}  // namespace stratum::render
