#include "stratum/render/lights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "stratum/render/bsdf.hpp"
#include "stratum/util/error.hpp"
#include "stratum/warps/disk.hpp"
#include "stratum/warps/projected_solid_angle.hpp"
#include "stratum/warps/sphere.hpp"
#include "stratum/warps/spherical_rectangle.hpp"
#include "stratum/warps/spherical_triangle.hpp"

namespace stratum::render {

namespace {

constexpr double pi = std::numbers::pi;

std::array<double, 3> to_array(Vec3 v) { return {v.x, v.y, v.z}; }
Vec3 to_vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

/// Whether the spherical-rectangle strategies apply: a quad with perpendicular edges.
bool rectangular_quad(const Shape& shape) {
  return shape.type == ShapeType::quad &&
         std::abs(dot(shape.edge_u, shape.edge_v)) <= 1e-9 * length(shape.edge_u) * length(shape.edge_v);
}

/// Below this height over a plane (a quad's or a triangle's) the spherical
/// polygon warps would refuse the point (their own tolerance is 1e-9 of the
/// same scale): no solid angle, and no exception thrown per sample.
double on_plane_tolerance(Vec3 offset, double size) { return 1e-8 * (length(offset) + size); }

SphericalRectangle<double> spherical_rectangle(const Shape& quad, Vec3 x, double time) {
  return SphericalRectangle<double>(to_array(quad.corner + time * quad.motion), to_array(quad.edge_u),
                                    to_array(quad.edge_v), to_array(x));
}

/// The sphere's centre at `time`, and whether x lies outside it (with a
/// margin): the cone strategy needs a point outside; inside, area sampling.
struct SphereView {
  Vec3 center;
  double distance2 = 0;
  bool outside = false;
};
SphereView sphere_view(const Shape& sphere, Vec3 x, double time) {
  SphereView view;
  view.center = sphere.center + time * sphere.motion;
  const Vec3 to = view.center - x;
  view.distance2 = dot(to, to);
  view.outside = view.distance2 > sphere.radius * sphere.radius * (1 + 1e-6);
  return view;
}
/// 1 − cos θ_max of the cone that meets the sphere, without cancellation
/// for small cones: sin²/(1 + cos).
double cone_one_minus_cos(double radius2, double distance2) {
  const double sin2 = radius2 / distance2;
  return sin2 / (1 + std::sqrt(std::max(0.0, 1 - sin2)));
}

/// Triangle k of a mesh at `time`.
struct Triangle {
  Vec3 a, b, c;
};
Triangle triangle_at(const Shape& shape, std::size_t k, double time) {
  const auto& t = shape.indices[k];
  const Vec3 shift = time * shape.motion;
  return {shape.vertices[t[0]] + shift, shape.vertices[t[1]] + shift, shape.vertices[t[2]] + shift};
}
/// Area of triangle k from the running sums.
double triangle_area(const Shape& shape, std::size_t k) {
  return shape.triangle_cdf[k] - (k == 0 ? 0.0 : shape.triangle_cdf[k - 1]);
}
/// A triangle picked by area with u0 (returned rescaled to [0, 1) for reuse).
std::size_t pick_triangle(const Shape& shape, double& u0) {
  const std::vector<double>& cdf = shape.triangle_cdf;
  const double pick = u0 * cdf.back();
  const std::size_t k =
      std::min<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), pick) - cdf.begin(), cdf.size() - 1);
  const double lo = k == 0 ? 0 : cdf[k - 1];
  u0 = std::clamp((pick - lo) / (cdf[k] - lo), 0.0, 1.0);
  return k;
}
/// The spherical triangle triangle k subtends from x, if x is on its
/// emitting side (n = (b − a) × (c − a)) and it subtends a measurable solid
/// angle: not when area/distance² < 1e-10 (≈ Ω; SphericalTriangle refuses
/// Ω < 1e-12, and an exception per sample would be slow), where callers
/// sample the triangle by area instead.
std::optional<SphericalTriangle<double>> spherical_triangle(const Triangle& t, Vec3 x, Vec3& normal) {
  const Vec3 twice_area = cross(t.b - t.a, t.c - t.a);
  normal = normalize(twice_area);
  if (dot(x - t.a, normal) <= on_plane_tolerance(x - t.a, length(t.b - t.a) + length(t.c - t.a))) return std::nullopt;
  if (0.5 * length(twice_area) < 1e-10 * dot(t.a - x, t.a - x)) return std::nullopt;
  try {
    return SphericalTriangle<double>(to_array(t.a), to_array(t.b), to_array(t.c), to_array(x));
  } catch (const invalid_argument&) {
    return std::nullopt;  // subtends no measurable solid angle from x
  }
}

/// A uniform point on a sphere, disk or triangle mesh at time 0 (its normal written to ny).
Vec3 point_on_shape(const Shape& shape, std::array<double, 2> u, Vec3& ny) {
  if (shape.type == ShapeType::disk) {  // Shirley and Chiu's concentric map: uniform by area
    ny = shape.normal;
    const auto p = sample_concentric_disk(u);
    const Frame frame(shape.normal);
    return shape.center + shape.radius * (p[0] * frame.s + p[1] * frame.t);
  }
  if (shape.type == ShapeType::sphere) {
    ny = to_vec(sample_uniform_sphere(u));
    return shape.center + shape.radius * ny;
  }
  // A triangle picked by area with u[0] (then rescaled to [0, 1) and reused), then uniform in it.
  const std::size_t k = pick_triangle(shape, u[0]);
  const Triangle t = triangle_at(shape, k, 0.0);
  const double s = std::sqrt(u[0]);
  ny = normalize(cross(t.b - t.a, t.c - t.a));
  return (1 - s) * t.a + (s * (1 - u[1])) * t.b + (s * u[1]) * t.c;
}

std::optional<LightSample> sample_quad_solid_angle(const Shape& shape, const LightGeometry& geometry, Vec3 x, Vec3 n,
                                                   double time, std::array<double, 2> u, LightStrategy strategy) {
  const Vec3 ny = geometry.normal;
  const Vec3 corner = shape.corner + time * shape.motion;
  // Behind the emitting side, or on the light's plane (a shading point on the light itself).
  if (dot(x - corner, ny) <= on_plane_tolerance(x - corner, length(shape.edge_u) + length(shape.edge_v)))
    return std::nullopt;
  try {
    const auto rectangle = spherical_rectangle(shape, x, time);
    Vec3 wi;
    double pdf = 0;
    if (strategy == LightStrategy::projected_solid_angle) {
      const ProjectedSphericalRectangle<double> projected(rectangle, to_array(n));
      const auto v = projected.bilinear().sample(u);
      wi = normalize(to_vec(rectangle.sample(v)));
      pdf = projected.bilinear().pdf(v) / rectangle.solid_angle();
    } else {
      wi = normalize(to_vec(rectangle.sample(u)));
      pdf = 1 / rectangle.solid_angle();
    }
    const double d = dot(corner - x, ny) / dot(wi, ny);
    if (!(d > 0) || !(pdf > 0)) return std::nullopt;
    return LightSample{wi, d, geometry.emission, pdf, false};
  } catch (const invalid_argument&) {
    return std::nullopt;  // subtends no measurable solid angle from x
  }
}

/// Uniform in the cone from x towards the sphere: cos θ uniform on
/// [cos θ_max, 1], φ uniform; the distance is the nearer root of the
/// ray–sphere intersection, d cos θ − sqrt(r² − d² sin² θ). The map is the
/// core UniformCone's (warps/sphere.hpp), written here in 1 − cos θ: from
/// cos θ_max a small far sphere's cap (sin² θ_max < 1e-16) rounds to nothing.
std::optional<LightSample> sample_sphere_cone(const Shape& shape, const LightGeometry& geometry, const SphereView& view,
                                              Vec3 x, std::array<double, 2> u) {
  const double r2 = shape.radius * shape.radius, d = std::sqrt(view.distance2);
  const double cone = cone_one_minus_cos(r2, view.distance2);
  const double one_minus_cos = u[0] * cone;
  const double cos_t = 1 - one_minus_cos, sin2 = one_minus_cos * (2 - one_minus_cos);
  const double sin_t = std::sqrt(std::max(0.0, sin2)), phi = 2 * pi * u[1];
  const Vec3 axis = (view.center - x) / d;
  const Vec3 wi = normalize(Frame(axis).to_world({sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t}));
  const double distance = d * cos_t - std::sqrt(std::max(0.0, r2 - view.distance2 * sin2));
  if (!(distance > 0)) return std::nullopt;
  return LightSample{wi, distance, geometry.emission, 1 / (2 * pi * cone), false};
}

std::optional<LightSample> sample_triangle_solid_angle(const Shape& shape, const LightGeometry& geometry, Vec3 x,
                                                       double time, std::array<double, 2> u) {
  const std::size_t k = pick_triangle(shape, u[0]);
  const Triangle corners = triangle_at(shape, k, time);
  Vec3 ny;
  const auto triangle = spherical_triangle(corners, x, ny);
  if (!triangle) {
    // Too small to sample by solid angle (or facing away): uniform on triangle
    // k, p = (A_k/A)·d²/(cos θ_y A_k) = d²/(cos θ_y A), as light_pdf assumes.
    const double s = std::sqrt(u[0]);
    const Vec3 to = (1 - s) * corners.a + (s * (1 - u[1])) * corners.b + (s * u[1]) * corners.c - x;
    const double d2 = dot(to, to), d = std::sqrt(d2);
    if (!(d > 0)) return std::nullopt;
    const double cos_y = -dot(ny, to / d);
    if (cos_y <= 0) return std::nullopt;
    return LightSample{to / d, d, geometry.emission, d2 / (cos_y * geometry.area), false};
  }
  const Vec3 wi = normalize(to_vec(triangle->sample(u)));
  const double d = dot(corners.a - x, ny) / dot(wi, ny);
  const double pdf = triangle_area(shape, k) / (geometry.area * triangle->solid_angle());
  if (!(d > 0) || !(pdf > 0)) return std::nullopt;
  return LightSample{wi, d, geometry.emission, pdf, false};
}

}  // namespace

double shape_area(const Shape& shape) {
  if (shape.type == ShapeType::quad) return length(cross(shape.edge_u, shape.edge_v));
  if (shape.type == ShapeType::sphere) return 4 * pi * shape.radius * shape.radius;
  if (shape.type == ShapeType::disk) return pi * shape.radius * shape.radius;
  return shape.triangle_cdf.empty() ? 0.0 : shape.triangle_cdf.back();
}

LightGeometry light_geometry(const Scene& scene, const Light& light) {
  LightGeometry geometry;
  if (light.type != LightType::area) return geometry;
  const Shape& shape = scene.shapes[light.shape];
  if (shape.type == ShapeType::quad) geometry.normal = normalize(cross(shape.edge_u, shape.edge_v));
  if (shape.type == ShapeType::disk) geometry.normal = shape.normal;
  geometry.area = shape_area(shape);
  geometry.rectangular = rectangular_quad(shape);
  geometry.quad = shape.type == ShapeType::quad;
  geometry.emission = scene.materials[shape.material].emission;
  return geometry;
}

std::optional<LightSample> sample_light(const Scene& scene, const Light& light, Vec3 x, Vec3 n, double time,
                                        std::array<double, 2> u, LightStrategy strategy) {
  return sample_light(scene, light, light_geometry(scene, light), x, n, time, u, strategy);
}

std::optional<LightSample> sample_light(const Scene& scene, const Light& light, const LightGeometry& geometry, Vec3 x,
                                        Vec3 n, double time, std::array<double, 2> u, LightStrategy strategy) {
  if (light.type == LightType::point) {
    const Vec3 to = light.position - x;
    const double d = length(to);
    if (!(d > 0)) return std::nullopt;
    return LightSample{to / d, d, light.intensity / (d * d), 1.0, true};
  }
  if (light.type == LightType::environment) {
    const auto local = sample_cosine_hemisphere(u);
    if (local[2] <= 0) return std::nullopt;
    return LightSample{Frame(n).to_world(local), std::numeric_limits<double>::infinity(), light.radiance, local[2] / pi,
                       false};
  }
  const Shape& shape = scene.shapes[light.shape];
  if (shape.type == ShapeType::triangles && shape.triangle_cdf.empty()) return std::nullopt;  // no triangles left
  if (strategy != LightStrategy::area) {
    if (geometry.rectangular) return sample_quad_solid_angle(shape, geometry, x, n, time, u, strategy);
    if (shape.type == ShapeType::triangles) return sample_triangle_solid_angle(shape, geometry, x, time, u);
    if (shape.type == ShapeType::sphere) {
      const SphereView view = sphere_view(shape, x, time);
      if (view.outside) return sample_sphere_cone(shape, geometry, view, x, u);
    }
  }
  if (shape.type == ShapeType::quad) return sample_quad_by_area(shape, geometry, x, time, u);
  Vec3 ny;
  const Vec3 y = point_on_shape(shape, u, ny) + time * shape.motion;
  const Vec3 to = y - x;
  const double d2 = dot(to, to), d = std::sqrt(d2);
  if (!(d > 0)) return std::nullopt;
  const Vec3 wi = to / d;
  const double cos_y = -dot(ny, wi);
  if (cos_y <= 0) return std::nullopt;
  return LightSample{wi, d, geometry.emission, d2 / (cos_y * geometry.area), false};
}

double light_pdf(const Scene& scene, const Light& light, Vec3 x, Vec3 n, double time, Vec3 wi, const Hit* hit,
                 LightStrategy strategy) {
  return light_pdf(scene, light, light_geometry(scene, light), x, n, time, wi, hit, strategy);
}

double light_pdf(const Scene& scene, const Light& light, const LightGeometry& geometry, Vec3 x, Vec3 n, double time,
                 Vec3 wi, const Hit* hit, LightStrategy strategy) {
  if (light.type == LightType::point) return 0;
  if (light.type == LightType::environment) return std::max(0.0, dot(n, wi)) / pi;
  if (!hit) return 0;
  const Shape& shape = scene.shapes[light.shape];
  const double cos_y = -dot(hit->normal, wi);
  if (cos_y <= 0) return 0;
  if (strategy != LightStrategy::area) {
    if (geometry.rectangular) {
      try {
        const auto rectangle = spherical_rectangle(shape, x, time);
        if (strategy == LightStrategy::projected_solid_angle)
          return ProjectedSphericalRectangle<double>(rectangle, to_array(n)).pdf(to_array(wi));
        return rectangle.pdf(to_array(wi));
      } catch (const invalid_argument&) {
        return 0;
      }
    }
    if (shape.type == ShapeType::triangles) {
      if (shape.triangle_cdf.empty() || hit->primitive >= shape.indices.size()) return 0;
      Vec3 ny;
      const auto triangle = spherical_triangle(triangle_at(shape, hit->primitive, time), x, ny);
      if (triangle) return triangle_area(shape, hit->primitive) / (geometry.area * triangle->solid_angle());
      // else: sampled by area (below)
    }
    if (shape.type == ShapeType::sphere) {
      const SphereView view = sphere_view(shape, x, time);
      if (view.outside) return 1 / (2 * pi * cone_one_minus_cos(shape.radius * shape.radius, view.distance2));
    }
  }
  if (!(geometry.area > 0)) return 0;
  const Vec3 to = hit->position - x;
  return dot(to, to) / (cos_y * geometry.area);
}

}  // namespace stratum::render
