#pragma once
/// Importance sampling, measured (LECTURE.md §3): irradiance
/// E = ∫_H L(ω) cos θ dω at a point with normal +z, estimated two ways per
/// scene, with each way's per-sample variance, its time and the ratios
/// (variance ratio, efficiency ratio = variance ratio × time ratio; lecture
/// §2: efficiency = 1 / (variance × cost)).
///
/// (a) "hemisphere": uniform-hemisphere directions (p = 1/2π) against
///     cosine-weighted ones (p = cos θ/π, Malley's method), under a uniform
///     sky (E = πL; cosine sampling is then the zero-variance estimator) and
///     under a rectangular area light (E from Lambert's polygon formula).
/// (b) "light": a rectangular light sampled by area (uniform points on it,
///     density converted to solid angle by r²/(A cos θ_light)) against
///     uniformly in its solid angle (Ureña, Fajardo, King 2013, "An
///     area-preserving parametrization for spherical rectangles"), as the
///     light's size and distance vary.
///
/// Each method runs `runs` independent plain Monte Carlo replicates of
/// `samples` samples (counter-based uniform numbers, so results are a pure
/// function of the request); the per-sample variance is the mean of the
/// replicates' sample variances and its standard error their spread / √runs.
/// Plain MC, not RQMC, because the per-sample variance is what importance
/// sampling changes; RQMC would mix in the pattern's own gain.
///
/// The predicted variances (second moment minus E²) are computed from their
/// integrals by composite Gauss–Legendre quadrature over the light's area or
/// in closed form where one exists (sky: π²L²/3 uniform, 0 cosine; light,
/// cosine sampling: πL·E − E²), so a test can check the measured ones.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace stratum::analysis {

/// A rectangle corner + s·edge_u + t·edge_v (s, t ∈ [0,1], edges
/// perpendicular) of uniform radiance, seen from the origin, whose receiver
/// normal is +z. The whole rectangle must lie above the receiver's plane (z > 0).
struct RectangleLight {
  std::array<double, 3> corner{};
  std::array<double, 3> edge_u{};
  std::array<double, 3> edge_v{};
  double radiance = 1;
};

/// A square light of side `size`, parallel to the receiver, centred on its
/// normal at height `distance`.
RectangleLight centered_square_light(double size, double distance, double radiance = 1);

/// Checks a light: finite, perpendicular non-zero edges, every corner above
/// the receiver plane, radiance finite and > 0; throws invalid_argument.
void validate(const RectangleLight& light);

/// Irradiance at the origin (normal +z) from the light, by Lambert's formula
/// for a polygon of uniform radiance (Lambert 1760, "Photometria"; Arvo 1995,
/// "Applications of irradiance tensors to the simulation of non-Lambertian
/// phenomena", eq. 11): E = (L/2) Σ_i Θ_i (n · Γ_i), Θ_i the angle the edge
/// (v_i, v_{i+1}) subtends and Γ_i the unit normal of the plane through it and
/// the origin.
double rectangle_irradiance(const RectangleLight& light);

/// ∫_light g(θ, θ_light, r) dA by composite Gauss–Legendre (panels × panels
/// panels of `order` points each) for the integrands the study needs:
/// power k of cos θ and power j of cos θ_light over r^(2·q).
/// With (1, 1, 1) it is the irradiance / L (brute force for the closed form).
double rectangle_area_integral(const RectangleLight& light, int cos_power, int light_cos_power, int r_power,
                               unsigned panels = 32, unsigned order = 8);

/// One method's measurements.
struct MethodResult {
  std::string method;             ///< "uniform", "cosine", "area", "solid-angle"
  double estimate = 0;            ///< mean over all runs × samples
  double estimate_stderr = 0;     ///< standard error of that mean (replicate spread / √runs)
  double variance = 0;            ///< per-sample variance (mean of the replicates' sample variances)
  double variance_stderr = 0;     ///< its standard error
  double predicted_variance = 0;  ///< from the integrals above
  double seconds_per_sample = 0;  ///< median replicate's wall time / samples
  double efficiency = 0;          ///< 1 / (variance × seconds per sample); +inf when variance is 0
};

/// Method a against method b (ratios > 1 favour b).
struct ImportanceComparison {
  std::string scene;    ///< "sky" or "light"
  std::string study;    ///< "hemisphere" (uniform vs cosine) or "light" (area vs solid-angle)
  double size = 0;      ///< light side (0 for the sky)
  double distance = 0;  ///< light height (0 for the sky)
  double exact = 0;     ///< irradiance, closed form
  MethodResult a, b;
  double variance_ratio = 0;         ///< a.variance / b.variance (+inf when b's is 0)
  double variance_ratio_stderr = 0;  ///< delta method from both standard errors
  double predicted_variance_ratio = 0;
  double time_ratio = 0;        ///< a.seconds / b.seconds
  double efficiency_ratio = 0;  ///< b.efficiency / a.efficiency
};

struct ImportanceStudyRequest {
  unsigned runs = 16;                ///< independent replicates per method
  std::uint64_t samples = 4096;      ///< samples per replicate
  double radiance = 1;               ///< L of the sky and of the lights
  double hemisphere_light_size = 1;  ///< light of study (a)
  double hemisphere_light_distance = 1;
  std::vector<double> sizes{0.25, 1, 4};      ///< study (b): light sides
  std::vector<double> distances{0.25, 1, 4};  ///< study (b): light heights
  std::uint64_t seed = 0;
  unsigned threads = 1;
};

/// Throws invalid_argument naming a bad field (runs ≥ 2, samples ≥ 2,
/// sizes and distances finite and > 0, at most 64 of each, every
/// size/distance in [1/1000, 64], ...).
void validate(const ImportanceStudyRequest& request);

struct ImportanceStudy {
  unsigned runs = 0;
  std::uint64_t samples = 0;
  std::vector<ImportanceComparison> hemisphere;  ///< sky, then the light
  std::vector<ImportanceComparison> light;       ///< one per (size, distance), sizes outer
};

/// Runs both studies; parallel over (comparison, method, run) with oneTBB.
/// Everything but the timings depends only on the request.
ImportanceStudy run_importance_study(const ImportanceStudyRequest& request);

}  // namespace stratum::analysis
