#include "stratum/render/integrators.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "stratum/estimators/mis.hpp"
#include "stratum/render/bsdf.hpp"
#include "stratum/render/lights.hpp"
#include "stratum/warps/sphere.hpp"

namespace stratum::render {

namespace {

constexpr double pi = std::numbers::pi;

bool is_black(Vec3 c) { return c.x <= 0 && c.y <= 0 && c.z <= 0; }

/// Per-shading-point scratch (2D samples, candidate shadow rays): on the
/// stack for up to 16 (the usual case; no allocation per eye ray, and no
/// initialization: every element is written before it is read), on the heap beyond.
template <class T>
class Buffer {
 public:
  explicit Buffer(std::uint32_t n) {
    if (n > local_size) heap_ = std::make_unique<T[]>(n), data_ = heap_.get();
  }
  T* data() { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }

 private:
  static constexpr std::size_t local_size = 16;
  union {
    T local_[local_size];  // not initialized
  };
  std::unique_ptr<T[]> heap_;
  T* data_ = local_;
};
using SampleBuffer = Buffer<std::array<double, 2>>;

/// A light sample's shadow ray and what it adds when unoccluded.
struct ShadowRay {
  Vec3 direction;
  double distance = 0;
  Vec3 contribution;
};

/// How the settings' --light-strategy splits the work between the lights'
/// own sampling and BSDF sampling.
struct Strategy {
  LightStrategy light = LightStrategy::area;  ///< the technique used when lights are sampled
  bool sample_lights = true;                  ///< light sampling for area lights and the environment
  bool sample_bsdf = false;                   ///< BSDF sampling finds emitters (weighted by MIS if both)

  explicit Strategy(const std::string& name) {
    if (name == "solid-angle") light = LightStrategy::solid_angle;
    if (name == "projected-solid-angle") light = LightStrategy::projected_solid_angle;
    if (name == "bsdf") sample_lights = false, sample_bsdf = true;
    if (name == "mis") light = LightStrategy::solid_angle, sample_bsdf = true;
  }
  bool mis() const { return sample_lights && sample_bsdf; }
};

enum class Kind { direct, irradiance, path };

}  // namespace

/// What the integrators need from the settings and scene, computed once.
struct Integrator::Prepared {
  const Scene& scene;
  const Accelerator& accelerator;
  const RenderSettings& settings;
  Strategy strategy{settings.light_strategy};
  Kind kind = settings.integrator == "irradiance" ? Kind::irradiance
              : settings.integrator == "path"     ? Kind::path
                                                  : Kind::direct;
  bool cosine = settings.hemisphere == "cosine";
  Vec3 environment;                     ///< the sum of the environment lights' radiance
  std::vector<LightGeometry> geometry;  ///< by light
  /// By light, how sample_lights takes it: skipped (found by BSDF sampling
  /// instead), a quad by area (inline), or through sample_light.
  enum class Take : std::uint8_t { skip, quad_by_area, general };
  std::vector<Take> take;

  Prepared(const Scene& s, const Accelerator& a, const RenderSettings& r) : scene(s), accelerator(a), settings(r) {
    for (const Light& light : scene.lights) {
      if (light.type == LightType::environment) environment += light.radiance;
      geometry.push_back(light_geometry(scene, light));
      const bool quad_by_area =
          geometry.back().quad && strategy.light == LightStrategy::area && light.type == LightType::area;
      take.push_back(!strategy.sample_lights && light.type != LightType::point ? Take::skip
                     : quad_by_area                                            ? Take::quad_by_area
                                                                               : Take::general);
    }
  }
};

namespace {

/// What the integrators share for one camera ray.
struct Context {
  const Integrator::Prepared& prepared;
  PixelSampler& sampler;
  const Scene& scene = prepared.scene;
  const Accelerator& accelerator = prepared.accelerator;
  const RenderSettings& settings = prepared.settings;
  const Strategy& strategy = prepared.strategy;

  Vec3 environment() const { return prepared.environment; }
  const Material& material_of(const Hit& hit) const { return scene.materials[scene.shapes[hit.shape].material]; }
  /// Emitted radiance towards -direction (one-sided: on the normal's side).
  Vec3 emitted(const Hit& hit, Vec3 direction) const {
    const Material& m = material_of(hit);
    return dot(hit.normal, direction) < 0 ? m.emission : Vec3{};
  }
  bool visible(Vec3 from, Vec3 direction, double distance, double time) const {
    if (!std::isfinite(distance)) return !accelerator.occluded({from, direction, time});
    const double eps = accelerator.epsilon();
    return !accelerator.occluded({from, direction, time, distance - 2 * eps});
  }
  Vec3 facing(const Hit& hit, Vec3 direction) const {
    return dot(hit.normal, direction) < 0 ? hit.normal : -hit.normal;
  }
  Bsdf bsdf_at(const Hit& hit, Vec3 direction) const {
    return Bsdf(material_of(hit), facing(hit, direction), -normalize(direction));
  }
  static double mis_weight(double n_self, double pdf_self, double n_other, double pdf_other) {
    return estimators::power_heuristic(n_self, pdf_self, n_other, pdf_other);  // β = 2 (Veach 1997, §9.2.4)
  }

  /// M light samples spread over the lights (light i + offset mod L for
  /// sample i, the offset random: each sample's light is uniform, so the
  /// technique's density is p_light/L), each weighted L/M: unbiased for any M.
  /// With MIS each sample is weighted against `bsdf_samples` BSDF samples.
  Vec3 sample_lights(const Bsdf& bsdf, Vec3 x, double time, std::uint32_t m, std::uint32_t bsdf_samples) const {
    const std::size_t lights = scene.lights.size();
    if (lights == 0 || m == 0) return {};
    SampleBuffer u(m);
    sampler.get_2d_array(m, u.data());
    const auto offset = static_cast<std::size_t>(sampler.get_1d() * double(lights));
    const Vec3 n = bsdf.normal();
    // A diffuse BSDF is the constant ρ/π above the surface: evaluated once
    // (eval(n) returns exactly what eval(wi) does for any wi above).
    const bool diffuse = !bsdf.glossy();
    const Vec3 f_diffuse = diffuse ? bsdf.eval(n) : Vec3{};
    // Two phases: the M samples first (independent arithmetic that the CPU
    // overlaps), then their shadow rays; the sum keeps the order of i.
    Buffer<ShadowRay> rays(m);
    std::uint32_t count = 0;
    std::size_t index = offset % lights;  // (i + offset) mod lights, without a division per sample
    for (std::uint32_t i = 0; i < m; ++i, index = index + 1 == lights ? 0 : index + 1) {
      const auto take = prepared.take[index];
      if (take == Integrator::Prepared::Take::skip) continue;  // found by BSDF sampling instead
      const Light& light = scene.lights[index];
      const LightGeometry& geometry = prepared.geometry[index];
      const auto s = take == Integrator::Prepared::Take::quad_by_area
                         ? sample_quad_by_area(scene.shapes[light.shape], geometry, x, time, u[i])
                         : sample_light(scene, light, geometry, x, n, time, u[i], strategy.light);
      if (!s) continue;
      const double cos_x = dot(n, s->wi);
      if (cos_x <= 0) continue;
      const Vec3 f = diffuse ? f_diffuse : bsdf.eval(s->wi);
      if (is_black(f)) continue;
      double w = 1;
      if (!s->delta && bsdf_samples > 0) w = mis_weight(m, s->pdf / double(lights), bsdf_samples, bsdf.pdf(s->wi));
      rays[count++] = {s->wi, s->distance, (w * cos_x / s->pdf) * (f * s->radiance)};
    }
    Vec3 sum{};
    for (std::uint32_t k = 0; k < count; ++k)
      if (visible(x, rays[k].direction, rays[k].distance, time)) sum += rays[k].contribution;
    return (double(lights) / double(m)) * sum;
  }

  /// The radiance a BSDF-sampled ray (from x along wi, drawn with density
  /// pdf_bsdf, one of bsdf_samples) finds in an emitter or the environment,
  /// MIS-weighted against the light_samples light samples taken at x.
  Vec3 emitter_found(Vec3 x, Vec3 n, double time, Vec3 wi, double pdf_bsdf, double bsdf_samples, double light_samples,
                     const std::optional<Hit>& next) const {
    const Vec3 le = next ? emitted(*next, wi) : environment();
    if (is_black(le) || !strategy.mis()) return le;
    const double lights = double(scene.lights.size());
    double pdf_light = 0;
    for (std::size_t index = 0; index < scene.lights.size(); ++index) {
      const Light& light = scene.lights[index];
      const bool match =
          next ? light.type == LightType::area && light.shape == next->shape : light.type == LightType::environment;
      if (match) {  // each environment light is sampled with the same density
        pdf_light =
            light_pdf(scene, light, prepared.geometry[index], x, n, time, wi, next ? &*next : nullptr, strategy.light);
        break;
      }
    }
    return mis_weight(bsdf_samples, pdf_bsdf, light_samples, pdf_light / lights) * le;
  }

  /// M light samples and, for the bsdf and mis strategies, M BSDF samples.
  Vec3 direct(const Bsdf& bsdf, Vec3 x, double time, std::uint32_t m) const {
    const std::uint32_t b = strategy.sample_bsdf ? m : 0;
    Vec3 sum = sample_lights(bsdf, x, time, m, strategy.mis() ? b : 0);
    if (b == 0) return sum;
    SampleBuffer u(b);
    sampler.get_2d_array(b, u.data());
    Vec3 found{};
    for (std::uint32_t i = 0; i < b; ++i) {
      const auto& ui = u.data()[i];
      const BsdfSample s = bsdf.sample(ui);
      if (!(s.pdf > 0) || is_black(s.weight)) continue;
      const auto next = accelerator.intersect({x, s.wi, time});
      found += s.weight * emitter_found(x, bsdf.normal(), time, s.wi, s.pdf, b, m, next);
    }
    return sum + found / double(b);
  }

  /// Follows mirrors from `ray`; returns the first diffuse or glossy hit (or
  /// none), adding what is seen directly (emitters, the environment) to `seen`.
  std::optional<Hit> first_non_specular(Ray& ray, Vec3& throughput, Vec3& seen) const {
    for (std::uint32_t depth = 0; depth <= settings.max_depth; ++depth) {
      auto hit = accelerator.intersect(ray);
      if (!hit) {
        seen += throughput * environment();
        return std::nullopt;
      }
      seen += throughput * emitted(*hit, ray.direction);
      const Material& m = material_of(*hit);
      if (m.type != MaterialType::mirror) return hit;
      throughput = throughput * m.reflectance;
      const Vec3 d = ray.direction;
      ray = Ray{hit->position, d - (2 * dot(d, hit->normal)) * hit->normal, ray.time};
    }
    return std::nullopt;
  }

  Vec3 direct_lighting(Ray ray) const {
    Vec3 throughput{1, 1, 1}, result{};
    const auto hit = first_non_specular(ray, throughput, result);
    if (!hit) return result;
    return result + throughput * direct(bsdf_at(*hit, ray.direction), hit->position, ray.time, settings.light_samples);
  }

  Vec3 irradiance(Ray ray) const {
    Vec3 throughput{1, 1, 1}, result{};
    const auto hit = first_non_specular(ray, throughput, result);
    if (!hit) return result;
    const Bsdf bsdf = bsdf_at(*hit, ray.direction);
    const Frame frame(bsdf.normal());
    const std::uint32_t m = std::max<std::uint32_t>(1, settings.light_samples);
    SampleBuffer u(m);
    sampler.get_2d_array(m, u.data());
    const bool cosine = prepared.cosine;
    Vec3 sum{};
    for (std::uint32_t i = 0; i < m; ++i) {
      const auto& ui = u.data()[i];
      const auto local = cosine ? sample_cosine_hemisphere(ui) : sample_uniform_hemisphere(ui);
      const double pdf = cosine ? local[2] / pi : 1 / (2 * pi);
      if (pdf <= 0) continue;
      const Vec3 wi = frame.to_world(local);
      const auto next = accelerator.intersect({hit->position, wi, ray.time});
      const Vec3 li = next ? emitted(*next, wi) : environment();
      sum += (local[2] / pdf) * (bsdf.eval(wi) * li);
    }
    return result + throughput * (sum / double(m));
  }

  /// Path tracing: next-event estimation at every diffuse or glossy vertex
  /// (M light samples at the first, one after), continuation by BSDF
  /// sampling; emitters hit by a continuation ray count fully after a mirror,
  /// MIS-weighted with the mis strategy, fully with bsdf, not at all otherwise
  /// (NEE already counted them).
  Vec3 path(Ray ray) const {
    Vec3 beta{1, 1, 1}, result{};
    bool specular = true;  // camera rays and mirror bounces see emitters in full
    Vec3 x_prev, n_prev;
    double pdf_prev = 0, lights_prev = 0;
    for (std::uint32_t depth = 0;; ++depth) {
      const auto hit = accelerator.intersect(ray);
      if (specular) {
        result += beta * (hit ? emitted(*hit, ray.direction) : environment());
      } else if (strategy.sample_bsdf) {
        result += beta * emitter_found(x_prev, n_prev, ray.time, ray.direction, pdf_prev, 1, lights_prev, hit);
      }
      // The vertex at max_depth only shows what it emits: the light NEE at
      // the previous vertex reached, so that every strategy has the same estimand.
      if (!hit || depth == settings.max_depth) break;
      const Material& m = material_of(*hit);
      if (m.type == MaterialType::mirror) {
        beta = beta * m.reflectance;
        ray = Ray{hit->position, ray.direction - (2 * dot(ray.direction, hit->normal)) * hit->normal, ray.time};
        specular = true;
        continue;
      }
      const Bsdf bsdf = bsdf_at(*hit, ray.direction);
      const std::uint32_t light_samples = depth == 0 ? settings.light_samples : 1;
      result += beta * sample_lights(bsdf, hit->position, ray.time, light_samples, strategy.mis() ? 1 : 0);
      const BsdfSample s = bsdf.sample(sampler.get_2d());
      if (!(s.pdf > 0) || is_black(s.weight)) break;
      beta = beta * s.weight;
      x_prev = hit->position, n_prev = bsdf.normal(), pdf_prev = s.pdf, lights_prev = light_samples;
      ray = Ray{hit->position, s.wi, ray.time};
      specular = false;
      if (depth >= 2) {  // Russian roulette on the throughput (Arvo, Kirk 1990)
        const double q = std::min(0.95, std::max({beta.x, beta.y, beta.z}));
        if (sampler.get_1d() >= q) break;
        beta = beta / q;
      }
    }
    return result;
  }
};

}  // namespace

Integrator::Integrator(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings)
    : prepared_(std::make_unique<const Prepared>(scene, accelerator, settings)) {}

Integrator::~Integrator() = default;

Vec3 Integrator::radiance(const Ray& ray, PixelSampler& sampler) const {
  const Context context{*prepared_, sampler};
  if (prepared_->kind == Kind::irradiance) return context.irradiance(ray);
  if (prepared_->kind == Kind::path) return context.path(ray);
  return context.direct_lighting(ray);
}

Vec3 radiance(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings, const Ray& ray,
              PixelSampler& sampler) {
  return Integrator(scene, accelerator, settings).radiance(ray, sampler);
}

}  // namespace stratum::render
