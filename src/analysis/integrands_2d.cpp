/// The 2D integrands of the lecture (§2–4) on [0,1]²: indicator functions
/// whose edges make stratification pay only along the edge (variance N^-1.5
/// for jittered sampling), and smooth functions where it pays everywhere
/// (N^-2 jittered, N^-3 for scrambled nets: Owen 1997).
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "integrand_families.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::analysis::integrand_families {

namespace {

using Point = std::array<double, 2>;

/// Area of the part of the unit square where (x − p)·normal < 0: the square
/// clipped by one half-plane (one Sutherland–Hodgman stage: Sutherland and
/// Hodgman 1974, "Reentrant polygon clipping"), then the shoelace formula.
double clipped_square_area(Point p, Point normal) {
  const std::array<Point, 4> square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  auto side = [&](Point q) { return (q[0] - p[0]) * normal[0] + (q[1] - p[1]) * normal[1]; };
  std::vector<Point> polygon;
  for (std::size_t k = 0; k < square.size(); ++k) {
    const Point a = square[k];
    const Point b = square[(k + 1) % square.size()];
    const double sa = side(a);
    const double sb = side(b);
    if (sa < 0) polygon.push_back(a);
    if ((sa < 0) != (sb < 0)) {
      const double t = sa / (sa - sb);
      polygon.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  double twice_area = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Point a = polygon[k];
    const Point b = polygon[(k + 1) % polygon.size()];
    twice_area += a[0] * b[1] - a[1] * b[0];
  }
  return std::abs(twice_area) / 2;
}

IntegrandInfo planar_entry(std::string name, std::string description, std::vector<std::string> properties) {
  IntegrandInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  info.min_dim = 2;
  info.max_dim = 2;
  info.default_dim = 2;
  info.properties = std::move(properties);
  return info;
}

}  // namespace

std::vector<IntegrandInfo> planar() {
  std::vector<IntegrandInfo> list;
  using std::numbers::pi;

  // The quarter disk of area 1/2: r² = 2/π, so π r²/4 = 1/2; its curved edge
  // crosses O(√N) of N strata.
  auto disk = planar_entry("disk", "1[x^2 + y^2 < 2/pi]: quarter disk of area 1/2 (curved edge)",
                           {"indicator", "discontinuous"});
  disk.make = [](unsigned, const IntegrandParams&) {
    return make_function_integrand(
        2, 0.5, [](const double* x) { return x[0] * x[0] + x[1] * x[1] < 2 / std::numbers::pi ? 1.0 : 0.0; });
  };
  list.push_back(std::move(disk));

  auto triangle = planar_entry("triangle", "1[y < x]: the lower-right triangle, area 1/2 (diagonal edge)",
                               {"indicator", "discontinuous"});
  triangle.make = [](unsigned, const IntegrandParams&) {
    return make_function_integrand(2, 0.5, [](const double* x) { return x[1] < x[0] ? 1.0 : 0.0; });
  };
  list.push_back(std::move(triangle));

  // An axis-aligned edge at an irrational position, so no grid of strata
  // ever lines up with it.
  auto step = planar_entry("step", "1[x < 1/pi]: a vertical edge at x = 1/pi, integral 1/pi",
                           {"indicator", "discontinuous", "axis-aligned edge"});
  step.make = [](unsigned, const IntegrandParams&) {
    return make_function_integrand(2, 1 / pi, [](const double* x) { return x[0] < 1 / std::numbers::pi ? 1.0 : 0.0; });
  };
  list.push_back(std::move(step));

  auto gaussian = planar_entry("gaussian", "exp(-x^2 - y^2): smooth, integral (sqrt(pi)/2 erf(1))^2", {"smooth"});
  gaussian.make = [](unsigned, const IntegrandParams&) {
    const double one_d = std::sqrt(pi) / 2 * std::erf(1.0);
    return make_function_integrand(2, one_d * one_d,
                                   [](const double* x) { return std::exp(-x[0] * x[0] - x[1] * x[1]); });
  };
  list.push_back(std::move(gaussian));

  auto bilinear = planar_entry("bilinear", "x y: smooth, integral 1/4", {"smooth", "polynomial"});
  bilinear.make = [](unsigned, const IntegrandParams&) {
    return make_function_integrand(2, 0.25, [](const double* x) { return x[0] * x[1]; });
  };
  list.push_back(std::move(bilinear));

  // A half-plane through a uniform point of the square with a uniform
  // direction: the "random edge" of the lecture's pixel (§4), one per seed.
  auto edge = planar_entry("edge-random",
                           "1[(x - p).n < 0] for a point p uniform in the square and a direction n uniform on the "
                           "circle, both from `seed`; exact area by clipping the square",
                           {"indicator", "discontinuous", "random edge"});
  // The integrands' numbers travel as doubles: seeds stop at 2^53, where doubles stop being exact.
  edge.params = {params::integer("seed", "which random edge", "0", half_open(0, 0x1p53))};
  edge.make = [](unsigned, const IntegrandParams& params) {
    const auto seed = static_cast<std::uint64_t>(params.at("seed").front());
    const Point p{uniform01(seed, 0), uniform01(seed, 1)};
    const double angle = 2 * std::numbers::pi * uniform01(seed, 2);
    const Point normal{std::cos(angle), std::sin(angle)};
    return make_function_integrand(2, clipped_square_area(p, normal), [p, normal](const double* x) {
      return (x[0] - p[0]) * normal[0] + (x[1] - p[1]) * normal[1] < 0 ? 1.0 : 0.0;
    });
  };
  list.push_back(std::move(edge));
  return list;
}

}  // namespace stratum::analysis::integrand_families
