#pragma once
/// Integration with any registry sampler, and convergence studies (lecture
/// §2–4): for a list of samplers and point counts N, R independent
/// randomizations per N give the mean error, RMSE, variance, seconds and
/// efficiency 1/(variance × seconds), and a least-squares fit of
/// log variance against log N whose slope is the convergence rate (random −1;
/// jittered −1.5 on an edge, −2 on a smooth 2D integrand; Owen-scrambled
/// Sobol −3 on smooth 2D integrands at powers of two: Owen 1997, "Scrambled
/// net variance for integrals of smooth functions").
///
/// Run r of sampler s at count N uses seed hash64(seed, s, N, r), and runs are
/// spread over oneTBB threads and reduced in a fixed order, so every number
/// except the timings is the same for any thread count.
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "stratum/analysis/integrands.hpp"

namespace stratum::analysis {

/// A registry sampler and how to randomize it ("" = the sampler's default).
struct SamplerChoice {
  std::string name;
  std::string randomize;
  std::map<std::string, std::string> params;  ///< sampler parameters, as text
};

/// Parses a sampler spec NAME[(KEY=VALUE,...)][:RANDOMIZER] ("sobol:owen",
/// "jittered(strata=4x8)") through parse_sampler_spec (registry/spec.hpp).
SamplerChoice parse_sampler_choice(std::string_view text);

/// The integrand part of a request.
struct IntegrandChoice {
  std::string name;
  unsigned d = 0;  ///< 0: the integrand's default dimension
  IntegrandParams params;
};

// ---------------------------------------------------------------- integrate

struct IntegrationRequest {
  IntegrandChoice integrand;
  SamplerChoice sampler;
  std::uint64_t n = 0;  ///< points per run
  unsigned runs = 1;    ///< independent randomizations (seeds hash64(seed, 0, n, r))
  std::uint64_t seed = 0;
  unsigned threads = 1;
  double confidence = 0.95;  ///< level of the confidence interval, in (0, 1)
};

struct IntegrationResult {
  std::string integrand;
  std::string sampler;
  std::string randomize;  ///< the resolved randomizer
  unsigned d = 0;
  std::uint64_t n = 0;
  unsigned runs = 0;
  double estimate = 0;        ///< mean over runs of each run's mean of f
  double standard_error = 0;  ///< runs ≥ 2: from the replicates (RQMC); runs = 1: s/√n of the n values
  /// "replicates" (valid for any unbiased randomized sampler), "iid" (s/√n:
  /// right for `random`, only indicative for stratified and QMC points), or
  /// "identical-runs": every run gave the same estimate (a deterministic
  /// sampler such as grid:none, zaremba:none, hammersley:none), so there is
  /// no error estimate and standard_error is NaN (never a false 0).
  std::string standard_error_kind;
  double exact = 0;
  double error = 0;    ///< estimate − exact
  double seconds = 0;  ///< wall time for all runs (generation + evaluation)
  std::vector<double> run_estimates;
  /// The confidence interval estimate ± t · standard_error at level
  /// `confidence`, t the Student-t quantile t_{ν, (1 + confidence)/2}: over
  /// the runs (ν = runs − 1; the RQMC interval, valid for any unbiased
  /// randomized sampler since the runs are independent, exact when their
  /// estimates are normal and asymptotically in runs otherwise), or with
  /// runs = 1 from the n values (ν = n − 1; right for `random` only). NaN
  /// bounds when there is no standard error (identical runs, n = 1).
  double confidence = 0.95;
  double interval_low = 0, interval_high = 0;
  double half_width = 0;  ///< t · standard_error
  /// 1 / (variance × seconds) as in converge: the variance of one run's
  /// estimate (runs ≥ 2: of the run estimates; runs = 1: s²/n) and the mean
  /// wall time of one run; NaN without a standard error, +inf when it is 0.
  double efficiency = 0;
  double seconds_per_run = 0;
};

/// Validates everything first (names, d, n ≥ 1, runs ≥ 1, threads ≥ 1, the
/// sampler's own rules for n), then integrates.
IntegrationResult integrate(const IntegrationRequest& request);

// -------------------------------------------------------------- convergence

struct ConvergenceRequest {
  IntegrandChoice integrand;
  std::vector<SamplerChoice> samplers;
  std::vector<std::uint64_t> counts;  ///< N values, each ≥ 1, strictly increasing
  unsigned runs = 32;                 ///< R ≥ 2 randomizations per (sampler, N)
  std::uint64_t seed = 0;
  unsigned threads = 1;
  /// false: a count a sampler refuses fails the request. true (the faces set
  /// it for their default counts, which must work for every sampler): each
  /// sampler skips the counts it refuses (jittered in 2D takes only squares)
  /// and lists them in SamplerConvergence::skipped; a sampler that takes none
  /// of the counts still fails.
  bool skip_refused_counts = false;
  double confidence = 0.95;  ///< level of each slope's confidence interval, in (0, 1)
};

/// The counts of the faces' default N list (`converge --n`): every power of
/// two from 16 to 65536.
inline constexpr const char* default_counts = "16:65536";

/// A count a sampler refused (skip_refused_counts), with the sampler's reason.
struct SkippedCount {
  std::uint64_t n = 0;
  std::string reason;
};

/// One (sampler, N) cell of the study.
struct ConvergenceRow {
  std::uint64_t n = 0;
  double mean_error = 0;  ///< mean over runs of (estimate − exact): the bias, ≈ 0 for unbiased samplers
  double rmse = 0;        ///< sqrt(mean of (estimate − exact)²)
  double variance = 0;    ///< unbiased variance of the R estimates
  double seconds = 0;     ///< mean wall time of one run (generate N points, evaluate, average)
  double efficiency = 0;  ///< 1 / (variance × seconds); +inf when the variance is 0
};

/// Least-squares line log y = intercept + slope · log x, with the slope's
/// standard error sqrt(SSE / (m − 2) / Σ(log x − mean)²) (m ≥ 3 points;
/// with m = 2 the standard error is NaN).
struct SlopeFit {
  double slope = 0;
  double slope_standard_error = 0;
  double intercept = 0;
  std::size_t points = 0;
};

/// Fits log y against log x; x and y positive and finite, at least 2 points
/// with distinct x.
SlopeFit fit_log_log(std::span<const double> x, std::span<const double> y);

/// A confidence interval for the least-squares slope of log s²_k against
/// log N_k, where s²_k is the sample variance of R run estimates at N_k.
/// Run r is the vector of its estimates at every N_k (seeded hash64(seed, s,
/// N, r)), so the R runs are independent and identically distributed and
/// the slope is a smooth symmetric function of them: Tukey's jackknife over
/// runs (Tukey 1958, "Bias and confidence in not-quite large samples")
/// estimates its variance as (R − 1)/R Σ_r (slope_(−r) − mean)², slope_(−r)
/// the slope with run r left out of every cell, and that estimate is
/// conservative in expectation (Efron, Stein 1981, "The jackknife estimate of
/// variance"). The interval is slope ± t_{R−1, (1 + c)/2} · SE. It takes in
/// the spread of each log variance whatever the estimates' distribution
/// (for normal ones Var(log s²) is the trigamma ψ'((R − 1)/2); heavier tails
/// widen it), which the residual standard error of fit_log_log, a measure of
/// how straight the line is with m − 2 degrees of freedom, does not.
/// Coverage: tests/analysis/convergence_slope_interval_test.cpp (200
/// seeds); estimates far from normal (a peaked integrand at small N) also
/// bias log s², which no interval removes: docs/samplers.md gives the
/// measured coverage.
struct SlopeInterval {
  double slope = 0;           ///< the least-squares slope of log s² (as fit_log_log)
  double standard_error = 0;  ///< the jackknife standard error
  double confidence = 0.95;
  double low = 0, high = 0;
};

/// The interval for counts x (≥ 2 distinct), and `estimates` holding the R
/// run estimates of each count in turn (x.size() × runs values, runs ≥ 3,
/// a positive sample variance in every count and with any one run left out).
SlopeInterval slope_interval(std::span<const double> x, std::span<const double> estimates, unsigned runs,
                             double confidence);

struct SamplerConvergence {
  SamplerChoice sampler;  ///< randomize resolved to the name actually used
  std::vector<ConvergenceRow> rows;
  /// Slope of log variance vs log N, or of log MSE (RMSE²) when some variance
  /// is 0 (a deterministic sampler); `fitted` says which ("variance" or "mse";
  /// "none" with a NaN slope when fewer than 2 values are positive).
  SlopeFit slope;
  std::string fitted;
  /// The slope's confidence interval (slope_interval) when fitted is
  /// "variance"; NaN members otherwise (deterministic runs: no sampling error).
  SlopeInterval interval;
  std::vector<SkippedCount> skipped;  ///< counts left out (skip_refused_counts); rows hold the others
};

struct ConvergenceResult {
  std::string integrand;
  unsigned d = 0;
  double exact = 0;
  unsigned runs = 0;
  std::vector<SamplerConvergence> samplers;
};

/// Validates the whole request first (integrand, every sampler at every N,
/// runs ≥ 2, N ≥ 1 increasing, threads in [1, 1024]) so a bad item fails
/// before any work, then runs the study.
ConvergenceResult run_convergence(const ConvergenceRequest& request);

/// Parses the CLI's N list: "16:65536" (every power of two from 16 to 65536;
/// both ends powers of two), "16:65536:4" (16, 64, 256, ...: each the previous
/// times 4), or a comma list "100,1000,10000". Throws invalid_argument naming `n`.
std::vector<std::uint64_t> parse_counts(std::string_view text);

}  // namespace stratum::analysis
