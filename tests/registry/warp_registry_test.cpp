// Generic tests over every registry warp (every entry, including any
// added later): each is built with its defaults, plus a few extra
// configurations, and checked through the registry's array calls.
#include "stratum/warp_registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/warps/densities_1d.hpp"
#include "stratum/warps/disk.hpp"
#include "stratum/warps/sphere.hpp"

namespace stratum {
namespace {

struct Configuration {
  std::string name;
  WarpParams params;
};

/// Parameters for warps that have required (default-less) parameters; a new
/// warp with required parameters needs a line here (its tests fail until then).
WarpParams example_parameters(const std::string& name) {
  if (name == "piecewise-1d") return {{"values", {1, 3, 0.5, 2, 4}}, {"width", {5}}};
  if (name == "piecewise-2d")
    return {{"values", {1, 2, 0.5, 3, 0.2, 1, 2, 1, 4, 1, 1, 2}}, {"width", {4}}, {"height", {3}}};
  if (name == "alias") return {{"values", {1, 3, 0.5, 2, 4}}};
  return {};
}

/// Every warp once (its defaults, or the example above), then extra configurations.
std::vector<Configuration> configurations() {
  std::vector<Configuration> list;
  for (const auto& info : warps()) list.push_back({info.name, example_parameters(info.name)});
  // Non-default parameters of the basic warps, by name: a renamed or lost warp
  // fails make_warp in every test below rather than dropping its configuration.
  list.push_back({"triangle", {{"vertices", {1, 0, 0.5, 0, 2, -1, -1, -0.5, 2}}}});
  list.push_back({"cone", {{"cos_theta_max", {-0.6}}}});
  list.push_back({"linear", {{"a", {0}}, {"b", {1}}}});
  list.push_back({"normal", {{"mu", {-3}}, {"sigma", {0.1}}}});
  list.push_back({"bilinear", {{"weights", {0, 0, 0, 1}}}});
  // The default rectangle is centred over a +z normal: its four corner cosines
  // are equal and the projected warp is uniform there; a tilted normal is not.
  list.push_back({"spherical-rectangle-projected", {{"normal", {0.6, 0, 0.8}}}});
  return list;
}

std::string label(const Configuration& c) {
  std::string text = c.name;
  for (const auto& [key, value] : c.params) text += " " + key + "=" + std::to_string(value.size()) + " numbers";
  return text;
}

/// n random u's in [0,1)^dim with a fixed seed.
std::vector<double> uniforms(std::size_t n, unsigned dim, std::uint64_t seed) {
  std::vector<double> u(n * dim);
  for (std::size_t i = 0; i < n; ++i)
    for (unsigned j = 0; j < dim; ++j) u[i * dim + j] = uniform01(seed, i, j);
  return u;
}

TEST(WarpRegistry, EntriesAreComplete) {
  std::set<std::string> names;
  for (const auto& info : warps()) {
    const WarpParams params = example_parameters(info.name);
    EXPECT_TRUE(names.insert(info.name).second) << "duplicate " << info.name;
    EXPECT_FALSE(info.description.empty()) << info.name;
    EXPECT_FALSE(info.domain.empty()) << info.name;
    EXPECT_TRUE(info.measure == "area" || info.measure == "solid angle" || info.measure == "length") << info.name;
    const auto warp = make_warp(info.name, params);
    EXPECT_TRUE(warp->input_dim() == 1 || warp->input_dim() == 2) << info.name;
    EXPECT_TRUE(warp->output_dim() >= 1 && warp->output_dim() <= 3) << info.name;
  }
  for (const char* name : {"disk-polar", "disk-concentric", "hemisphere-uniform", "hemisphere-cosine", "sphere-uniform",
                           "cone", "triangle", "linear", "tent", "exponential", "normal", "bilinear"})
    EXPECT_TRUE(names.count(name)) << name;
}

// Every sampled point has a positive, finite density.
TEST(WarpRegistry, SampledPointsHavePositiveDensity) {
  for (const auto& c : configurations()) {
    const auto warp = make_warp(c.name, c.params);
    const std::size_t n = 4000;
    const auto u = uniforms(n, warp->input_dim(), 17);
    const auto p = warp_sample(*warp, u.data(), n);
    const auto pdf = warp_pdf(*warp, p.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_TRUE(std::isfinite(pdf[i]) && pdf[i] > 0) << label(c) << " row " << i << " pdf " << pdf[i];
    }
  }
}

// invert(sample(u)) = u and sample(invert(p)) = p, to 1e-9 relative to the
// point's size; rows whose azimuth is ill-conditioned (within 1e-6 of a pole)
// are compared as points only.
TEST(WarpRegistry, InverseRoundTrip) {
  for (const auto& c : configurations()) {
    const auto warp = make_warp(c.name, c.params);
    const unsigned in = warp->input_dim(), out = warp->output_dim();
    const std::size_t n = 4000;
    const auto u = uniforms(n, in, 23);
    const auto p = warp_sample(*warp, u.data(), n);
    const auto back = warp_invert(*warp, p.data(), n);
    const auto again = warp_sample(*warp, back.data(), n);
    std::size_t mismatched_u = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double scale = 1;
      for (unsigned k = 0; k < out; ++k) scale = std::max(scale, std::abs(p[i * out + k]));
      for (unsigned k = 0; k < out; ++k)
        ASSERT_NEAR(again[i * out + k], p[i * out + k], 1e-9 * scale) << label(c) << " row " << i;
      const bool near_pole = out == 3 && std::abs(p[i * out + 2]) > 1 - 1e-6;
      for (unsigned j = 0; j < in; ++j) mismatched_u += !near_pole && std::abs(back[i * in + j] - u[i * in + j]) > 1e-9;
    }
    EXPECT_EQ(mismatched_u, 0u) << label(c);
  }
}

/// |Jacobian| of sample at u by central differences with step h, or NaN.
double jacobian(const Warp& warp, const double* u, double h) {
  const unsigned in = warp.input_dim(), out = warp.output_dim();
  double columns[2][3];
  for (unsigned j = 0; j < in; ++j) {
    double up[2] = {u[0], in > 1 ? u[1] : 0}, down[2] = {u[0], in > 1 ? u[1] : 0};
    up[j] += h, down[j] -= h;
    double pu[3], pd[3];
    warp.sample(up, 1, pu);
    warp.sample(down, 1, pd);
    for (unsigned k = 0; k < out; ++k) columns[j][k] = (pu[k] - pd[k]) / (2 * h);
  }
  if (in == 1) {
    double norm = 0;
    for (unsigned k = 0; k < out; ++k) norm += columns[0][k] * columns[0][k];
    return std::sqrt(norm);
  }
  if (out == 2) return std::abs(columns[0][0] * columns[1][1] - columns[0][1] * columns[1][0]);
  const double* a = columns[0];
  const double* b = columns[1];
  const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
  return std::sqrt(cx * cx + cy * cy + cz * cz);
}

// The density is the inverse Jacobian of the map: pdf(sample(u)) |∂sample/∂u|
// = 1 (per area, solid angle or length), checked by central differences
// (h = 1e-6, relative tolerance 1e-4) at 500 interior u's. Points where
// steps of h and 2h disagree by more than 1e-4 sit on a kink or seam of the
// map and are skipped; at most 2% may be. Together with the round trip this
// is the change of variables that makes the pdf integrate to 1 over the image.
TEST(WarpRegistry, DensityIsTheInverseJacobian) {
  for (const auto& c : configurations()) {
    const auto warp = make_warp(c.name, c.params);
    const unsigned in = warp->input_dim();
    const std::size_t n = 500;
    auto u = uniforms(n, in, 29);
    for (double& v : u) v = 0.001 + 0.998 * v;  // keep the stencil inside [0,1)
    const auto p = warp_sample(*warp, u.data(), n);
    const auto pdf = warp_pdf(*warp, p.data(), n);
    int skipped = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double j1 = jacobian(*warp, &u[i * in], 1e-6), j2 = jacobian(*warp, &u[i * in], 2e-6);
      if (std::abs(j1 - j2) > 1e-4 * std::abs(j1)) {
        ++skipped;
        continue;
      }
      ASSERT_NEAR(pdf[i] * j1, 1.0, 1e-4) << label(c) << " row " << i << " u0 " << u[i * in];
    }
    EXPECT_LE(skipped, 10) << label(c);
  }
}

// The area_preserving flag says the Jacobian is constant: pdf(sample(u)) is
// the same at 500 random u's in every configuration of a flagged warp, and
// varies in at least one configuration of every other warp.
TEST(WarpRegistry, AreaPreservingFlagMatchesTheDensity) {
  std::set<std::string> varies;
  for (const auto& c : configurations()) {
    const WarpInfo& info = find_warp(c.name);
    const auto warp = make_warp(c.name, c.params);
    const std::size_t n = 500;
    const auto u = uniforms(n, warp->input_dim(), 31);
    const auto p = warp_sample(*warp, u.data(), n);
    const auto pdf = warp_pdf(*warp, p.data(), n);
    const auto [lo, hi] = std::minmax_element(pdf.begin(), pdf.end());
    const bool constant = *hi - *lo <= 1e-9 * *hi;
    if (info.area_preserving) {
      EXPECT_TRUE(constant) << label(c) << " pdf in [" << *lo << ", " << *hi << "]";
    }
    if (!constant) varies.insert(c.name);
  }
  for (const auto& info : warps())
    if (!info.area_preserving) {
      EXPECT_TRUE(varies.count(info.name)) << info.name << " has a constant density";
    }
}

// ∫ pdf = 1 by quadrature over a region holding the support: 1D between the
// extreme samples of u ∈ {k/4096} ∪ {1 − 2⁻⁴⁰}, grown by 1% (3-point
// Gauss–Legendre, 20000 panels of width h; tolerance 1e-9 + 2 h max pdf for
// jumps at the support's ends; the tail mass beyond is < 1e-11); planar on
// the bounding box of a 65 × 65 grid of samples grown by 1% (midpoint rule,
// 1200², tolerance 3e-3 as the support's edge cuts cells); directions over the whole sphere in (z, φ)
// (midpoint, 1200², tolerance 3e-3). Points in space off the unit sphere (a
// triangle in 3D) have no 2D chart here and are left to the Jacobian test.
TEST(WarpRegistry, PdfIntegratesToOne) {
  for (const auto& c : configurations()) {
    const auto warp = make_warp(c.name, c.params);
    const unsigned in = warp->input_dim(), out = warp->output_dim();
    double total = 0;
    if (out == 1) {
      // The support's ends from 4097 u's (the alias map is not monotone).
      std::vector<double> grid_u;
      for (int k = 0; k < 4096; ++k) grid_u.push_back(k / 4096.0);
      grid_u.push_back(1 - 0x1p-40);
      const auto grid_x = warp_sample(*warp, grid_u.data(), grid_u.size());
      const auto [lo, hi] = std::minmax_element(grid_x.begin(), grid_x.end());
      const double grow = 0.01 * (*hi - *lo), ends[2] = {*lo - grow, *hi + grow};
      const int panels = 20000;
      const double h = (ends[1] - ends[0]) / panels, offset = std::sqrt(0.15);
      std::vector<double> x;
      for (int k = 0; k < panels; ++k)
        for (double node : {0.5 - offset, 0.5, 0.5 + offset}) x.push_back(ends[0] + h * (k + node));
      const auto pdf = warp_pdf(*warp, x.data(), x.size());
      for (std::size_t k = 0; k < pdf.size(); ++k) total += pdf[k] * h * (k % 3 == 1 ? 8.0 / 18 : 5.0 / 18);
      // A jump of the density inside a panel costs at most h × (its height).
      const double jumps = 2 * h * *std::max_element(pdf.begin(), pdf.end());
      EXPECT_NEAR(total, 1.0, 1e-9 + jumps) << label(c);
      continue;
    }
    const int m = 1200;
    std::vector<double> points(static_cast<std::size_t>(m) * out);
    if (out == 2) {
      double box[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
      for (int a = 0; a <= 64; ++a)
        for (int b = 0; b <= 64; ++b) {
          const double u[2] = {std::min(a / 64.0, 1 - 0x1p-40), std::min(b / 64.0, 1 - 0x1p-40)};
          double p[2];
          warp->sample(u, 1, p);
          box[0] = std::min(box[0], p[0]), box[1] = std::max(box[1], p[0]);
          box[2] = std::min(box[2], p[1]), box[3] = std::max(box[3], p[1]);
        }
      const double gx = 0.01 * (box[1] - box[0]), gy = 0.01 * (box[3] - box[2]);
      box[0] -= gx, box[1] += gx, box[2] -= gy, box[3] += gy;
      const double hx = (box[1] - box[0]) / m, hy = (box[3] - box[2]) / m;
      for (int j = 0; j < m; ++j) {
        for (int i = 0; i < m; ++i)
          points[2 * i] = box[0] + (i + 0.5) * hx, points[2 * i + 1] = box[2] + (j + 0.5) * hy;
        const auto pdf = warp_pdf(*warp, points.data(), m);
        for (double v : pdf) total += v * hx * hy;
      }
    } else {
      double probe[3];
      const double u_mid[2] = {0.3, 0.6};
      warp->sample(u_mid, 1, probe);
      if (std::abs(std::hypot(probe[0], probe[1], probe[2]) - 1) > 1e-9) continue;  // not directions
      const double hz = 2.0 / m, hphi = 2 * std::numbers::pi / m;
      for (int j = 0; j < m; ++j) {
        const double z = -1 + (j + 0.5) * hz, s = std::sqrt(1 - z * z);
        for (int i = 0; i < m; ++i) {
          const double phi = (i + 0.5) * hphi;
          points[3 * i] = s * std::cos(phi), points[3 * i + 1] = s * std::sin(phi), points[3 * i + 2] = z;
        }
        const auto pdf = warp_pdf(*warp, points.data(), m);
        for (double v : pdf) total += v * hz * hphi;
      }
    }
    (void)in;
    EXPECT_NEAR(total, 1.0, 3e-3) << label(c);
  }
}

// The registry entries compute what the core headers compute.
TEST(WarpRegistry, EntriesMatchTheCoreHeaders) {
  const auto u = uniforms(50, 2, 37);
  const auto check = [&](const char* name, const WarpParams& params, auto core) {
    const auto warp = make_warp(name, params);
    const auto p = warp_sample(*warp, u.data(), 50);
    for (std::size_t i = 0; i < 50; ++i) {
      const auto expected = core(std::array<double, 2>{u[2 * i], u[2 * i + 1]});
      for (std::size_t k = 0; k < expected.size(); ++k) ASSERT_EQ(p[i * expected.size() + k], expected[k]) << name;
    }
  };
  check("disk-polar", {}, sample_polar_disk<double>);
  check("disk-concentric", {}, sample_concentric_disk<double>);
  check("hemisphere-uniform", {}, sample_uniform_hemisphere<double>);
  check("hemisphere-cosine", {}, sample_cosine_hemisphere<double>);
  check("sphere-uniform", {}, sample_uniform_sphere<double>);
  const UniformCone<double> cone(0.2);
  check("cone", {{"cos_theta_max", {0.2}}}, [&](std::array<double, 2> v) { return cone.sample(v); });
  const BilinearDensity<double> bilinear(std::array<double, 4>{1, 0, 2, 5});
  check("bilinear", {{"weights", {1, 0, 2, 5}}}, [&](std::array<double, 2> v) { return bilinear.sample(v); });
  const auto tent = make_warp("tent", {{"radius", {3}}});
  const double half = 0.5;
  EXPECT_EQ(warp_sample(*tent, &half, 1)[0], 0.0);
}

std::string error_of_make(const std::string& name, const WarpParams& params) {
  try {
    make_warp(name, params);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WarpRegistry, BadParameters) {
  const struct {
    const char* name;
    WarpParams params;
    const char* message;
  } cases[] = {
      {"cone", {{"cos_theta_max", {1.5}}}, "invalid cos_theta_max = 1.5: must be a finite real in [-1, 1)"},
      {"cone", {{"cos_theta_max", {-1.01}}}, "invalid cos_theta_max = -1.01"},
      {"cone", {{"cos_theta_max", {1}}}, "invalid cos_theta_max = 1"},
      {"cone", {{"cos_theta_max", {0.1, 0.2}}}, "invalid cos_theta_max = (2 values): must be a finite real in [-1, 1)"},
      {"cone", {{"cos_theta_max", {NAN}}}, "invalid cos_theta_max = nan: must be a finite real"},
      {"triangle", {{"vertices", {0, 0, 1, 1, 2, 2}}}, "invalid vertices"},
      {"triangle", {{"vertices", {0, 0, 1, 0, 0}}}, "invalid vertices = (5 values): must be 6 to 9 finite reals"},
      {"triangle", {{"vertices", {1, 2, 3, 1, 2, 3, 1, 2, 3}}}, "degenerate"},
      {"tent", {{"radius", {0}}}, "invalid radius = 0: must be a finite real in (0, inf)"},
      {"tent", {{"radius", {-2}}}, "invalid radius = -2"},
      {"exponential", {{"rate", {0}}}, "invalid rate = 0: must be a finite real in (0, inf)"},
      {"normal", {{"sigma", {-1}}}, "invalid sigma = -1: must be a finite real in (0, inf)"},
      {"normal", {{"sigma", {0}}}, "invalid sigma = 0"},
      {"linear", {{"a", {-1}}}, "invalid a = -1"},
      {"linear", {{"a", {0}}, {"b", {0}}}, "must not both be zero"},
      {"bilinear", {{"weights", {0, 0, 0, 0}}}, "invalid weights = 0, 0, 0, 0"},
      {"bilinear", {{"weights", {1, -1, 1, 1}}}, "invalid weights"},
      {"bilinear", {{"weights", {1, 1, 1}}}, "invalid weights = (3 values): must be 4 finite reals"},
      {"disk-polar", {{"radius", {1}}}, "invalid warp-param = radius=1: disk-polar takes no parameters"},
      {"cone", {{"angle", {1}}}, "invalid warp-param = angle=1: cone takes cos_theta_max"},
      {"no-such-map", {}, "invalid map = no-such-map: valid maps are disk-polar"},
  };
  for (const auto& c : cases) {
    const std::string message = error_of_make(c.name, c.params);
    EXPECT_NE(message.find(c.message), std::string::npos) << c.name << ": '" << message << "'";
  }
}

// u outside [0, 1) or NaN is rejected by every warp, naming row and column.
TEST(WarpRegistry, BadUniformsNameRowAndColumn) {
  for (const auto& info : warps()) {
    const auto warp = make_warp(info.name, example_parameters(info.name));
    const unsigned in = warp->input_dim();
    for (double bad : {1.0, -0.25, std::nan(""), std::numeric_limits<double>::infinity()}) {
      auto u = uniforms(4, in, 41);
      u[2 * in + in - 1] = bad;
      std::string message;
      try {
        warp_sample(*warp, u.data(), 4);
      } catch (const invalid_argument& e) {
        message = e.what();
      }
      const std::string where = "invalid u[2][" + std::to_string(in - 1) + "] = ";
      EXPECT_NE(message.find(where), std::string::npos) << info.name << ": '" << message << "'";
      EXPECT_NE(message.find("must be in [0, 1)"), std::string::npos) << info.name << ": '" << message << "'";
    }
    std::vector<double> p(3 * warp->output_dim(), 0.5);
    p[warp->output_dim()] = std::nan("");
    std::string message;
    try {
      warp_pdf(*warp, p.data(), 3);
    } catch (const invalid_argument& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("invalid p[1][0] = nan: must be finite"), std::string::npos) << info.name << message;
  }
}

}  // namespace
}  // namespace stratum
