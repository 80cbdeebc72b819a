#pragma once
/// Integrating to a tolerance: double the points per run until the
/// confidence interval's half-width t·SE meets max(abs_tol, rel_tol·|estimate|),
/// as QMCPy's replicated stopping rules do (Choi, Hickernell, Jagadeeswaran,
/// McCourt, Sorokin 2022, "Quasi-Monte Carlo software", §3; the IID and
/// replicated-QMC criteria of its CubMCCLT / CubQMCRep).
///
/// What holds: each step is the replicated RQMC interval of `integrate`
/// (Student-t over independent randomizations), and the run seeds are the
/// same at every step, so a sequence's step 2N extends step N's points.
/// What does not: stopping the first time the interval is narrow selects a
/// step whose variance estimate happened to be small (optional stopping),
/// so the final interval's coverage can fall below its nominal level,
/// mostly with few runs; more runs (16 or more) make the variance estimate
/// steady and the shortfall small (measured in the tests and the docs).
#include <cstdint>
#include <optional>
#include <vector>

#include "stratum/analysis/convergence.hpp"

namespace stratum::analysis {

struct ToleranceRequest {
  IntegrationRequest integration;                ///< its n is the first step's points per run
  double abs_tol = 0;                            ///< ≥ 0
  double rel_tol = 0;                            ///< in [0, 1); at least one of the two > 0
  std::uint64_t max_n = std::uint64_t{1} << 24;  ///< the most points per run a step may take
};

struct ToleranceStep {
  std::uint64_t n = 0;
  double estimate = 0, half_width = 0, target = 0, seconds = 0;
};

struct ToleranceResult {
  IntegrationResult result;  ///< the last step's
  bool met = false;          ///< the last step's half-width meets its target
  double target = 0;         ///< max(abs_tol, rel_tol · |estimate|) at the last step
  std::vector<ToleranceStep> steps;
};

/// Validates everything before the first step (the tolerances, max_n ≥ n,
/// and that the sampler can take every n of the doubling up to max_n),
/// then integrates step by step. A step without an error estimate
/// (identical runs: a deterministic sampler) is an error naming the sampler.
ToleranceResult integrate_to_tolerance(const ToleranceRequest& request);

/// The tolerance options of `integrate` on every face: none given, or abs
/// and rel tolerances with an optional max_n.
struct ToleranceOptions {
  std::optional<double> abs_tol, rel_tol;
  std::optional<std::uint64_t> max_n;  ///< default ToleranceRequest's
  bool any() const noexcept { return abs_tol || rel_tol; }
};

/// What `integrate` does on every face: integrate(request) when no
/// tolerance is given (the result alone, no steps), else
/// integrate_to_tolerance; a max_n without a tolerance is refused (it
/// would be ignored).
ToleranceResult integrate_with(const IntegrationRequest& request, const ToleranceOptions& tolerance);

}  // namespace stratum::analysis
