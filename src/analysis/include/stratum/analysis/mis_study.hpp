#pragma once
/// Multiple importance sampling, measured (Veach & Guibas 1995, "Optimally
/// combining sampling techniques for Monte Carlo rendering"; Veach 1997,
/// thesis §9.1–9.2 and Fig. 9.2): the light a glossy surface reflects from a
/// round light, estimated four ways as the light's size and the surface's
/// glossiness vary.
///
/// The surface: a normalized Phong lobe about the normal, whose BRDF × cos θ
/// is the density p_bsdf(ω) = (e + 1)/(2π) cos^e θ on the hemisphere
/// (Lafortune & Willems 1994); the light: radiance L = 1 inside a cone of
/// half-angle α about the normal. The reflected radiance is
///   I = ∫_cap p_bsdf dω = 1 − cos^(e+1) α   (closed form).
/// Methods, each with N samples:
///  - light: uniform in the light's solid angle (p = 1/(2π(1 − cos α)));
///    good for small lights, bad for sharp lobes;
///  - bsdf: from the lobe (cos θ = u^(1/(e+1))); good for sharp lobes, bad
///    for small lights;
///  - balance, power: N/2 samples of each, weighted by the balance and the
///    power (β = 2) heuristics (estimators/mis.hpp): close to the better of
///    the two everywhere (Veach 1997, Theorem 9.2).
/// Per-sample variance = N × variance of one N-sample estimate, so the four
/// are compared at equal cost in samples. Predicted variances come from the
/// integrals by graded Gauss–Legendre quadrature in cos θ (light and bsdf
/// also in closed form), so the tests can check the measured ones.
#include <cstdint>
#include <string>
#include <vector>

namespace stratum::analysis {

struct MisStudyRequest {
  std::vector<double> exponents{1, 10, 100, 1000};  ///< Phong exponents e, in [0, 100000]
  std::vector<double> angles{2, 10, 30, 60};        ///< light half-angles α in degrees, in (0, 90]
  unsigned runs = 16;                               ///< independent replicates per method, ≥ 2
  std::uint64_t samples = 1024;                     ///< N per replicate: even, ≥ 4
  double beta = 2;                                  ///< the power heuristic's exponent, > 0
  std::uint64_t seed = 0;
  unsigned threads = 1;
};

/// Throws invalid_argument naming the bad field.
void validate(const MisStudyRequest& request);

struct MisMethodResult {
  std::string method;          ///< "light", "bsdf", "balance", "power"
  double estimate = 0;         ///< mean over the runs
  double estimate_stderr = 0;  ///< replicate spread / √runs
  double variance = 0;         ///< per-sample variance, mean over the runs
  double variance_stderr = 0;
  double predicted_variance = 0;  ///< from the integrals
};

struct MisCase {
  double exponent = 0, angle = 0;        ///< e, α in degrees
  double exact = 0;                      ///< 1 − cos^(e+1) α
  std::vector<MisMethodResult> methods;  ///< light, bsdf, balance, power
  std::string best_single;               ///< "light" or "bsdf": the lower predicted variance
  /// Predicted variance of each heuristic / that of the better single
  /// strategy (+inf when that is 0).
  double balance_over_best = 0, power_over_best = 0;
  /// Veach's bound on the balance heuristic's per-sample variance at N/2 + N/2
  /// samples (Theorem 9.2 against the better strategy alone with its N/2):
  /// 2 · min(V_light, V_bsdf) + I². Where one strategy is nearly exact (small
  /// light, broad lobe) the I² term dominates: the balance heuristic is then
  /// far from the best, and the power heuristic close (§9.2.4).
  double balance_bound = 0;
};

struct MisStudy {
  unsigned runs = 0;
  std::uint64_t samples = 0;
  double beta = 2;
  std::vector<MisCase> cases;  ///< exponents outer, angles inner
};

/// Predicted per-sample variance of one method (as in MisMethodResult),
/// for exponent e and half-angle α in degrees.
double mis_predicted_variance(const std::string& method, double exponent, double angle_degrees, double beta = 2);

/// Runs every (exponent, angle, method, run); parallel with oneTBB, and over
/// the ranks of a distributed job. Results depend only on the request.
MisStudy run_mis_study(const MisStudyRequest& request);

}  // namespace stratum::analysis
