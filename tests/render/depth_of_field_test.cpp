// Depth of field against its closed form (src/render/camera_model.cpp): the
// image of an emitting edge out of focus.
//
// The camera model: a lens disk of radius A at the camera position, the plane
// in focus at distance F along the view axis, film coordinates s (tangents:
// s_y = (1 − 2y/h)·tan(fov/2)). The ray from lens point ℓ (lateral offset)
// for film point s passes through F·s on the plane in focus, so at depth d
// it is at s·d + ℓ(1 − d/F). An emitter covering the half-plane y > e at depth
// d is hit when ℓ_y (1/d − 1/F) > e/d − s_y: over the uniform lens disk the
// pixel's value is the fraction of the unit disk above τ = (e/d − s_y)/R,
//   G(τ) = (acos τ − τ √(1 − τ²))/π  (1 below τ = −1, 0 above τ = 1),
// with R = A·|1/d − 1/F| = A·|F − d|/(F·d): the circle of confusion of this
// camera has diameter 2R in film tangents, 2R·h/(2 tan(fov/2)) pixels.
#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numbers>

#include "stratum/render/render.hpp"

namespace stratum::render {
namespace {

constexpr double pi = std::numbers::pi;

/// Camera at the origin looking down +z (up +y), A = 0.5, F = 5; an emitting
/// quad (radiance 1) covering y ∈ [e, 10] at depth d, facing the camera.
Scene edge_scene(double d, double e) {
  Scene scene;
  scene.camera.position = {0, 0, 0};
  scene.camera.look_at = {0, 0, 1};
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_degrees = 30;
  scene.camera.width = 4;
  scene.camera.height = 64;
  scene.camera.aperture_radius = 0.5;
  scene.camera.focus_distance = 5;
  scene.materials = {{"glow", MaterialType::diffuse, {0, 0, 0}, {1, 1, 1}}};
  Shape quad;
  quad.type = ShapeType::quad;
  quad.corner = {-10, e, d};
  quad.edge_u = {0, 10 - e, 0};  // edge_u × edge_v = −z: emits towards the camera
  quad.edge_v = {20, 0, 0};
  scene.shapes.push_back(quad);
  validate_scene(scene);
  return scene;
}

/// The fraction of the unit disk whose y coordinate exceeds τ.
double disk_fraction_above(double tau) {
  if (tau <= -1) return 1;
  if (tau >= 1) return 0;
  return (std::acos(tau) - tau * std::sqrt(1 - tau * tau)) / pi;
}

TEST(RenderDepthOfField, BlurredEdgeHasTheThinLensCircleOfConfusion) {
  // Behind the plane in focus (d = 10) and in front of it (d = 3). Each
  // pixel (through its centre) is a mean of n = 1024 Bernoulli draws with the
  // predicted p. Checks, at family α = 0.01: exact values where p ∈ {0, 1}
  // (|τ| > 1.01); where n·p·(1 − p) ≥ 5 (normal approximation), a z-test per
  // pixel with the binomial standard error (Šidák over 2 × 4 × 64 pixels at
  // α = 0.005) and, more sensitive to a wrong radius, the sum of their z² per
  // depth against χ²(pixels) (Šidák over the 2 depths at α = 0.005).
  const double a = 0.5, f = 5, tan_half = std::tan(pi / 12);
  const int spp = 1024;
  const double alpha_z = 1 - std::pow(1 - 0.005, 1.0 / (2 * 4 * 64)), alpha_chi2 = 1 - std::pow(1 - 0.005, 0.5);
  const double z_max = boost::math::quantile(boost::math::complement(boost::math::normal(), alpha_z / 2));
  for (const double d : {10.0, 3.0}) {
    const double e = 0.03 * d;  // the edge at film tangent s_y = 0.03 (row ≈ 28)
    const double radius = a * std::abs(f - d) / (f * d);
    RenderSettings s;
    s.sampler.sampler = "random";
    s.sampler.spp = spp;
    s.sampler.seed = 41;
    s.pixel_centers = true;
    const Image image = render(edge_scene(d, e), s);
    int exact = 0, tested = 0, blurred_rows = 0;
    double chi2 = 0;
    for (int y = 0; y < 64; ++y) {
      const double s_y = (1 - 2 * (y + 0.5) / 64) * tan_half;
      const double tau = (e / d - s_y) / radius, p = disk_fraction_above(tau);
      bool blurred = false;
      for (int x = 0; x < 4; ++x) {
        const double value = image.rgb[3 * (std::size_t(y) * 4 + x)];
        blurred = blurred || (value > 0 && value < 1);
        if (std::abs(tau) > 1.01) {  // clear of the rim (Embree's float rays graze it inside 1%)
          EXPECT_EQ(value, p) << "d " << d << " row " << y;
          ++exact;
        } else if (spp * p * (1 - p) >= 5) {
          const double z = (value - p) / std::sqrt(p * (1 - p) / spp);
          EXPECT_LT(std::abs(z), z_max) << "d " << d << " row " << y << ": " << value << " vs " << p;
          chi2 += z * z;
          ++tested;
        }
      }
      blurred_rows += blurred;
    }
    ASSERT_GT(tested, 4 * 8) << d;
    EXPECT_GT(exact, 4 * 40) << d;
    const boost::math::chi_squared chi2_distribution(tested);
    EXPECT_LT(chi2, boost::math::quantile(boost::math::complement(chi2_distribution, alpha_chi2))) << d;
    // The blur spans the circle of confusion, 2R·h/(2 tan(fov/2)) rows: 11.9
    // behind the plane in focus, 15.9 in front (rows near its rim may see p ≈ 0 or 1).
    const double diameter_rows = 2 * radius * 64 / (2 * tan_half);
    EXPECT_LE(blurred_rows, diameter_rows + 1) << d;
    EXPECT_GE(blurred_rows, diameter_rows - 3) << d;
  }
}

TEST(RenderDepthOfField, APinholeKeepsTheEdgeSharp) {
  // Aperture 0: every ray of a pixel is the same, so each pixel is 0 or 1,
  // switching exactly at the edge's film position.
  Scene scene = edge_scene(10, 0.3);
  scene.camera.aperture_radius = 0;
  RenderSettings s;
  s.sampler.spp = 16;
  s.pixel_centers = true;
  const Image image = render(scene, s);
  const double tan_half = std::tan(pi / 12);
  for (int y = 0; y < 64; ++y) {
    const double s_y = (1 - 2 * (y + 0.5) / 64) * tan_half;
    EXPECT_EQ(image.rgb[3 * std::size_t(y) * 4], s_y > 0.03 ? 1.0 : 0.0) << y;
  }
}

}  // namespace
}  // namespace stratum::render
