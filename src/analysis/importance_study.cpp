/// Importance-sampling studies (LECTURE.md §3): see
/// src/analysis/include/stratum/analysis/importance_study.hpp.
#include "stratum/analysis/importance_study.hpp"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "stratum/analysis/dimension_study.hpp"
#include "stratum/distributed.hpp"
#include "stratum/estimators/efficiency.hpp"
#include "stratum/estimators/importance.hpp"
#include "stratum/estimators/running_stats.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/warps/sphere.hpp"
#include "stratum/warps/spherical_rectangle.hpp"
#include "stratum/warps/vector3.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::analysis {

namespace {

using Vec = std::array<double, 3>;
constexpr double pi = std::numbers::pi;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

std::string text(const Vec& v) {
  return to_message_string(v[0]) + "," + to_message_string(v[1]) + "," + to_message_string(v[2]);
}

std::array<Vec, 4> corners(const RectangleLight& light) {
  using namespace vector3;
  return {light.corner, add(light.corner, light.edge_u), add(add(light.corner, light.edge_u), light.edge_v),
          add(light.corner, light.edge_v)};
}

/// The scene one comparison estimates: a uniform sky or a rectangle light.
struct Scene {
  std::optional<SphericalRectangle<double>> rectangle;  // empty: uniform sky
  RectangleLight light;
  double radiance = 1;
  double area = 0;
  Vec light_normal{};

  explicit Scene(double sky_radiance) : radiance(sky_radiance) {}
  explicit Scene(const RectangleLight& l) : light(l), radiance(l.radiance) {
    using namespace vector3;
    rectangle.emplace(l.corner, l.edge_u, l.edge_v);
    const Vec n = cross(l.edge_u, l.edge_v);
    area = length(n);
    light_normal = scale(n, 1 / area);
  }
  /// L cos θ for a direction ω (0 where it misses the light).
  double incident(const Vec& w) const noexcept {
    if (w[2] <= 0) return 0;
    if (rectangle && !rectangle->contains(w)) return 0;
    return radiance * w[2];
  }
};

enum class Method { uniform, cosine, area, solid_angle };

Method method_of(std::string_view name) {
  if (name == "uniform") return Method::uniform;
  if (name == "cosine") return Method::cosine;
  if (name == "area") return Method::area;
  return Method::solid_angle;
}

/// One sample of method M from u ∈ [0,1)²: f(ω)/p(ω). A template, so the
/// timed loop carries no per-sample dispatch.
template <Method M>
double weighted_sample(const Scene& scene, double u0, double u1) noexcept {
  if constexpr (M == Method::uniform) {
    const Vec w = sample_uniform_hemisphere<double>({u0, u1});
    return estimators::importance_weighted(scene.incident(w), uniform_hemisphere_pdf(w));
  } else if constexpr (M == Method::cosine) {
    const Vec w = sample_cosine_hemisphere<double>({u0, u1});
    return estimators::importance_weighted(scene.incident(w), cosine_hemisphere_pdf(w));
  } else if constexpr (M == Method::area) {  // uniform point on the light; p_ω = r² / (A cos θ_light)
    using namespace vector3;
    const Vec q = add(scene.light.corner, add(scale(scene.light.edge_u, u0), scale(scene.light.edge_v, u1)));
    const double r2 = dot(q, q);
    const Vec w = scale(q, 1 / std::sqrt(r2));
    const double cos_light = std::abs(dot(w, scene.light_normal));
    return estimators::importance_weighted(scene.radiance * w[2], r2 / (scene.area * cos_light));
  } else {  // uniform in the light's solid angle, p_ω = 1/Ω everywhere on it
    const Vec w = scene.rectangle->sample({u0, u1});
    return estimators::importance_weighted(scene.radiance * std::max(0.0, w[2]), 1 / scene.rectangle->solid_angle());
  }
}

struct ReplicateResult {
  double mean = 0, variance = 0, seconds = 0;
};

template <Method M>
ReplicateResult run_replicate(const Scene& scene, std::uint64_t samples, std::uint64_t stream, std::uint64_t run) {
  estimators::RunningStats stats;
  const auto start = std::chrono::steady_clock::now();
  for (std::uint64_t i = 0; i < samples; ++i)
    stats.add(weighted_sample<M>(scene, uniform01(stream, run, i, 0), uniform01(stream, run, i, 1)));
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  return {stats.mean(), stats.variance(), elapsed.count()};
}

ReplicateResult run_replicate(const Scene& scene, std::string_view method, std::uint64_t samples, std::uint64_t stream,
                              std::uint64_t run) {
  switch (method_of(method)) {
    case Method::uniform:
      return run_replicate<Method::uniform>(scene, samples, stream, run);
    case Method::cosine:
      return run_replicate<Method::cosine>(scene, samples, stream, run);
    case Method::area:
      return run_replicate<Method::area>(scene, samples, stream, run);
    case Method::solid_angle:
      break;
  }
  return run_replicate<Method::solid_angle>(scene, samples, stream, run);
}

MethodResult summarize(std::string method, const std::vector<ReplicateResult>& replicates, std::uint64_t samples,
                       double predicted) {
  estimators::RunningStats means, variances;
  std::vector<double> seconds;
  for (const auto& r : replicates) means.add(r.mean), variances.add(r.variance), seconds.push_back(r.seconds);
  // The median replicate time: robust to a replicate preempted by other work.
  std::nth_element(seconds.begin(), seconds.begin() + static_cast<std::ptrdiff_t>(seconds.size() / 2), seconds.end());
  const double median_seconds = seconds[seconds.size() / 2];
  MethodResult result;
  result.method = std::move(method);
  result.estimate = means.mean();
  result.estimate_stderr = means.standard_error();
  result.variance = std::max(0.0, variances.mean());
  result.variance_stderr = variances.standard_error();
  result.predicted_variance = predicted;
  result.seconds_per_sample = std::max(median_seconds, 1e-9) / static_cast<double>(samples);  // clock floor
  result.efficiency = estimators::efficiency(result.variance, result.seconds_per_sample);
  return result;
}

void fill_ratios(ImportanceComparison& c) {
  const double va = c.a.variance, vb = c.b.variance;
  c.variance_ratio = vb > 0 ? va / vb : (va > 0 ? inf : nan);
  c.variance_ratio_stderr =
      (va > 0 && vb > 0) ? c.variance_ratio * std::hypot(c.a.variance_stderr / va, c.b.variance_stderr / vb) : nan;
  c.predicted_variance_ratio = c.b.predicted_variance > 0 ? c.a.predicted_variance / c.b.predicted_variance : inf;
  c.time_ratio = c.a.seconds_per_sample / c.b.seconds_per_sample;
  if (va > 0 && vb > 0)
    c.efficiency_ratio =
        estimators::compare_efficiency(va, c.a.seconds_per_sample, vb, c.b.seconds_per_sample).efficiency_ratio;
  else c.efficiency_ratio = vb == 0 && va > 0 ? inf : nan;
}

}  // namespace

RectangleLight centered_square_light(double size, double distance, double radiance) {
  return {{-size / 2, -size / 2, distance}, {size, 0, 0}, {0, size, 0}, radiance};
}

void validate(const RectangleLight& light) {
  using namespace vector3;
  for (const Vec& v : {light.corner, light.edge_u, light.edge_v})
    for (double x : v) require(std::isfinite(x), "light", text(v), "coordinates must be finite");
  require(std::isfinite(light.radiance) && light.radiance > 0, "radiance", light.radiance,
          "must be positive and finite");
  for (const Vec& c : corners(light))
    require(c[2] > 0, "light", text(c), "every corner must lie above the receiver plane z = 0");
  (void)SphericalRectangle<double>(light.corner, light.edge_u, light.edge_v);  // edges: non-zero, perpendicular
}

double rectangle_irradiance(const RectangleLight& light) {
  using namespace vector3;
  validate(light);
  const auto v = corners(light);
  double sum = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec a = normalize(v[i]), b = normalize(v[(i + 1) % 4]);
    sum += angle_between(a, b) * normalize(cross(a, b))[2];
  }
  return light.radiance * std::abs(sum) / 2;  // the sign follows the vertex order
}

namespace {
/// ∫_light g(cos θ, cos θ_light, r²) dA by composite Gauss–Legendre.
template <class G>
double light_integral(const RectangleLight& light, unsigned panels, unsigned order, G&& g) {
  using namespace vector3;
  require(panels >= 1 && panels <= 4096, "panels", panels, "must be in [1, 4096]");
  const QuadratureRule1D rule = gauss_legendre_rule(order);
  const Vec n = cross(light.edge_u, light.edge_v);
  const double area = length(n);
  const Vec normal = scale(n, 1 / area);
  double total = 0;
  for (unsigned pu = 0; pu < panels; ++pu) {
    for (unsigned pv = 0; pv < panels; ++pv) {
      double panel = 0;
      for (unsigned i = 0; i < order; ++i) {
        for (unsigned j = 0; j < order; ++j) {
          const double s = (pu + rule.nodes[i]) / panels, t = (pv + rule.nodes[j]) / panels;
          const Vec q = add(light.corner, add(scale(light.edge_u, s), scale(light.edge_v, t)));
          const double r2 = dot(q, q), r = std::sqrt(r2);
          panel += rule.weights[i] * rule.weights[j] * g(q[2] / r, std::abs(dot(q, normal)) / r, r2);
        }
      }
      total += panel;
    }
  }
  return total * area / (static_cast<double>(panels) * panels);
}
}  // namespace

double rectangle_area_integral(const RectangleLight& light, int cos_power, int light_cos_power, int r_power,
                               unsigned panels, unsigned order) {
  validate(light);
  return light_integral(light, panels, order, [&](double c, double c_light, double r2) {
    return std::pow(c, cos_power) * std::pow(c_light, light_cos_power) / std::pow(r2, r_power);
  });
}

void validate(const ImportanceStudyRequest& request) {
  require(request.runs >= 2 && request.runs <= 100000, "runs", request.runs, "must be in [2, 100000]");
  require(request.samples >= 2 && request.samples <= (std::uint64_t{1} << 30), "samples", request.samples,
          "must be in [2, 2^30]");
  require(std::isfinite(request.radiance) && request.radiance > 0, "radiance", request.radiance,
          "must be positive and finite");
  require(request.threads >= 1 && request.threads <= 1024, "threads", request.threads, "must be in [1, 1024]");
  require(!request.sizes.empty() && request.sizes.size() <= 64, "sizes", request.sizes.size(),
          "needs 1 to 64 light sizes");
  require(!request.distances.empty() && request.distances.size() <= 64, "distances", request.distances.size(),
          "needs 1 to 64 light distances");
  for (double s : request.sizes) require(std::isfinite(s) && s > 0 && s <= 1e6, "size", s, "must be in (0, 1e6]");
  for (double d : request.distances)
    require(std::isfinite(d) && d > 0 && d <= 1e6, "distance", d, "must be in (0, 1e6]");
  for (double s : request.sizes)
    for (double d : request.distances)
      // Above 64 the predicted variances' quadrature (512² panels) no longer resolves the peak under the
      // receiver; below 1/1000 the light subtends too little for a meaningful ratio.
      require(s / d <= 64 && d / s <= 1e3, "size", s,
              "must lie in [distance/1000, 64 distance] for every distance (distance " + to_message_string(d) + ")");
  require(std::isfinite(request.hemisphere_light_size) && request.hemisphere_light_size > 0, "hemisphere_light_size",
          request.hemisphere_light_size, "must be positive and finite");
  require(std::isfinite(request.hemisphere_light_distance) && request.hemisphere_light_distance > 0,
          "hemisphere_light_distance", request.hemisphere_light_distance, "must be positive and finite");
}

ImportanceStudy run_importance_study(const ImportanceStudyRequest& request) {
  validate(request);
  const double L = request.radiance;
  struct Setup {
    ImportanceComparison comparison;
    Scene scene;
  };
  std::vector<Setup> setups;
  {  // (a) sky: E = πL; uniform: Y = 2πL cos θ with cos θ ~ U(0,1) → Var = π²L²/3; cosine: Var = 0.
    ImportanceComparison c{"sky", "hemisphere", 0, 0, pi * L, {}, {}, 0, 0, 0, 0, 0};
    c.a.predicted_variance = pi * pi * L * L / 3, c.b.predicted_variance = 0;
    c.a.method = "uniform", c.b.method = "cosine";
    setups.push_back({c, Scene(L)});
  }
  const auto light_setup = [&](const std::string& study, double size, double distance) {
    const RectangleLight light = centered_square_light(size, distance, L);
    const Scene scene(light);
    const double e = rectangle_irradiance(light), omega = scene.rectangle->solid_angle(), area = size * size;
    // Variances as integrals of (Y − E)² p, not E[Y²] − E², which cancels
    // catastrophically for small lights. Denser panels for lights large
    // against their distance (the integrands peak over a width ~ distance).
    const auto panels = static_cast<unsigned>(std::clamp(8 * size / distance, 8.0, 512.0));
    const auto central = [&](auto&& y_of, auto&& p_area) {  // ∫ (Y − E)² p_A dA over the light
      return light_integral(light, panels, 8, [&](double c, double c_light, double r2) {
        const double y = y_of(c, c_light, r2);
        return (y - e) * (y - e) * p_area(c, c_light, r2);
      });
    };
    const auto solid_angle_density = [](double, double c_light, double r2) { return c_light / r2; };
    ImportanceComparison c{"light", study, size, distance, e, {}, {}, 0, 0, 0, 0, 0};
    if (study == "hemisphere") {
      c.a.method = "uniform", c.b.method = "cosine";
      // Y = 2πL cos θ on the light (p = 1/2π), 0 off it (solid angle 2π − Ω).
      c.a.predicted_variance =
          (central([&](double cs, double, double) { return 2 * pi * L * cs; }, solid_angle_density) +
           (2 * pi - omega) * e * e) /
          (2 * pi);
      // Y = πL on the light, 0 off it, p = cos θ/π: Var = πL·E − E² (no cancellation: E ≤ πL).
      c.b.predicted_variance = pi * L * e - e * e;
    } else {
      c.a.method = "area", c.b.method = "solid-angle";
      c.a.predicted_variance =
          central([&](double cs, double c_light, double r2) { return L * cs * area * c_light / r2; },
                  [&](double, double, double) { return 1 / area; });
      c.b.predicted_variance = central([&](double cs, double, double) { return L * omega * cs; },
                                       [&](double, double c_light, double r2) { return c_light / (r2 * omega); });
    }
    setups.push_back({c, scene});
  };
  light_setup("hemisphere", request.hemisphere_light_size, request.hemisphere_light_distance);
  for (double size : request.sizes)
    for (double distance : request.distances) light_setup("light", size, distance);

  // Tasks (setup, method, run); each result lands in its own slot.
  const std::size_t per_setup = 2 * static_cast<std::size_t>(request.runs);
  std::vector<ReplicateResult> results(setups.size() * per_setup);
  const distributed::Dealt mine = distributed::dealt(results.size());  // a distributed job's share, round-robin
  tbb::task_arena arena(static_cast<int>(request.threads));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, mine.size(), [&](std::size_t j) {
      check_interrupt();
      const std::size_t t = mine[j];
      const std::size_t s = t / per_setup, which = (t % per_setup) / request.runs, run = t % request.runs;
      const Setup& setup = setups[s];
      const std::string& method = which == 0 ? setup.comparison.a.method : setup.comparison.b.method;
      const std::uint64_t stream = hash64(request.seed, s, which);
      results[t] = run_replicate(setup.scene, method, request.samples, stream, run);
    });
  });
  if (distributed::size() > 1) {
    std::vector<double> packed(3 * results.size());
    for (std::size_t j = 0; j < mine.size(); ++j) {
      const std::size_t t = mine[j];
      packed[3 * t] = results[t].mean, packed[3 * t + 1] = results[t].variance, packed[3 * t + 2] = results[t].seconds;
    }
    distributed::gather_dealt(packed, results.size());
    for (std::size_t t = 0; t < results.size(); ++t) results[t] = {packed[3 * t], packed[3 * t + 1], packed[3 * t + 2]};
  }
  ImportanceStudy study{request.runs, request.samples, {}, {}};
  for (std::size_t s = 0; s < setups.size(); ++s) {
    ImportanceComparison c = setups[s].comparison;
    const auto first = results.begin() + static_cast<std::ptrdiff_t>(s * per_setup);
    const std::vector<ReplicateResult> a(first, first + request.runs), b(first + request.runs, first + per_setup);
    c.a = summarize(c.a.method, a, request.samples, c.a.predicted_variance);
    c.b = summarize(c.b.method, b, request.samples, c.b.predicted_variance);
    fill_ratios(c);
    (c.study == "hemisphere" ? study.hemisphere : study.light).push_back(std::move(c));
  }
  return study;
}

}  // namespace stratum::analysis
