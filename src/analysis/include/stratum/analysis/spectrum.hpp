#pragma once
/// Fourier spectra of point sets (LECTURE.md §8, §12, §13): the periodogram
///   P(k) = |Σ_j exp(−2πi k·x_j)|² / N
/// on the integer frequency grid k ∈ [−K, K]^d (d = 1 or 2), averaged over
/// realizations, its radial average over rings one frequency wide with the
/// anisotropy of Lagae & Dutré (2008, "A comparison of methods for generating
/// Poisson disk distributions"), and the effective Nyquist frequency and
/// oscillation of Heck, Schlömer & Deussen (2013, "Blue noise sampling with
/// controlled aliasing").
///
/// With this normalization a uniform random set has E[P(k)] = 1 for every
/// k ≠ 0 (white noise), P(0) = N for any set, and a blue-noise set has P ≪ 1
/// at low frequencies. Frequencies are integers on the unit torus; divided by
/// √N they are in "units of the mean sample spacing" (radial_frequency_scale),
/// the scale on which patterns of different N compare.
///
/// The sums are evaluated directly (no FFT, so no binning of the points):
/// per point the complex exponentials of consecutive frequencies come from a
/// recurrence e^{−2πi(k+1)x} = e^{−2πi kx}·e^{−2πi x}, re-anchored with an
/// exact sincos every few dozen steps, and the frequency rows are spread over
/// oneTBB tasks; every sum is accumulated in the same order for any thread
/// count, so results are bitwise deterministic.
#include <cstddef>
#include <vector>

#include "stratum/analysis/measures.hpp"  // PointView

namespace stratum::analysis {

/// The mean periodogram of one or more realizations.
struct Periodogram {
  int max_frequency = 0;  ///< K: frequencies in [−K, K] per axis
  std::size_t d = 0;      ///< 1 or 2
  /// d = 2: power[(ky + K) * (2K + 1) + (kx + K)]; d = 1: power[k + K].
  std::vector<double> power;
  std::size_t points = 0;  ///< N of each realization
  std::size_t realizations = 0;

  std::size_t side() const noexcept { return static_cast<std::size_t>(2 * max_frequency + 1); }
  /// P at integer frequency (kx, ky) (ky ignored for d = 1).
  double at(int kx, int ky = 0) const noexcept {
    const std::size_t column = static_cast<std::size_t>(kx + max_frequency);
    if (d == 1) return power[column];
    return power[static_cast<std::size_t>(ky + max_frequency) * side() + column];
  }
};

/// Largest K accepted: the grid (2K+1)^d must stay at most 2^25 values
/// (256 MiB of doubles); beyond that the caller is told to lower K.
std::size_t max_periodogram_values();

/// The periodogram averaged over realizations (all with the same n and d,
/// d ∈ {1, 2}, coordinates finite and in [0, 1]). Throws
/// stratum::invalid_argument naming the argument (max_frequency ≤ 0 or grid
/// too large, d, n, realizations). Deterministic for any `threads` (0: all
/// cores).
Periodogram mean_periodogram(const std::vector<PointView>& realizations, int max_frequency, unsigned threads);

/// The same quantity by the brute-force O(N·(2K+1)^d) sum with std::complex
/// and one std::exp per term: the reference the fast recurrence is tested
/// against. Single-threaded; for tests and small inputs.
Periodogram mean_periodogram_reference(const std::vector<PointView>& realizations, int max_frequency);

/// Radially averaged power over rings one frequency wide: ring r holds the
/// integer frequencies k ≠ 0 with round(|k|) = r, r = 1..K (rings beyond K
/// would be cut by the square grid; the DC term P(0) = N is left out). For
/// d = 1 ring r is {−r, r}.
/// anisotropy_db[r] = 10·log10(s²_r / P̄_r²), with s²_r the unbiased sample
/// variance of the ring's values and P̄_r their mean (Lagae & Dutré 2008, §3,
/// after Ulichney 1987, "Digital halftoning"): for an isotropic pattern
/// averaged over K realizations the periodogram values of a ring are ~
/// Gamma(K, 1/K), so the anisotropy is about −10·log10(K) dB (0 dB for one;
/// Lagae & Dutré average 10 realizations and read −10 dB as isotropic). Each
/// value is counted once: the variance runs over the half plane
/// {ky > 0} ∪ {ky = 0, kx > 0}, since P(−k) = P(k) repeats the other half.
/// NaN where a ring has fewer than 2 distinct values (every ring for d = 1) or
/// zero mean power.
struct RadialPower {
  std::vector<double> frequency;      ///< ring radius / √N (units of the mean sample spacing)
  std::vector<double> power;          ///< mean periodogram over the ring
  std::vector<double> anisotropy_db;  ///< see above
  std::vector<double> radius;         ///< ring radius r (integer frequency)
  std::vector<double> count;          ///< frequencies in the ring (both half planes)
  std::size_t points = 0;             ///< N (0 if unknown: then frequency = radius)
};
RadialPower radial_average(const Periodogram& periodogram);

/// √N: divide an integer frequency by this to express it in units of the
/// mean sample spacing (N points on the unit torus).
double radial_frequency_scale(std::size_t points);

/// Effective Nyquist frequency and oscillation (Heck, Schlömer & Deussen
/// 2013, "Blue noise sampling with controlled aliasing", §4; the forms follow
/// their psa tool, adapted to rings one integer frequency wide):
/// - cumulative power C(r) = mean of P(k) over 0 < |k| ≤ r (ring-count
///   weighted). From the first ring where C > 0.5, step down to the last ring
///   j with C(j) < 0.1: a pattern has (almost) no power below j, so it samples
///   frequencies up to ν_eff = j / 2 without aliasing, as a regular grid of
///   spacing 1/√N has zero power below √N and Nyquist √N / 2. Reported
///   normalized by √N (a regular m×m grid: (m − 1)/(2m); a random set: 0).
///   If C never exceeds 0.5 up to K the value is only a lower bound.
/// - oscillation Ω = 10·sqrt(mean of (P̄_r − 1)² over the rings from the
///   first ring with P̄_r ≥ 0.98 to 5√N rings further, ring-count weighted),
///   i.e. 10 × the RMS deviation of the radial power from white noise over
///   that annulus: the peaks that cause structured aliasing. The annulus is cut
///   at K (window_is_cut) when K is too small; NaN if P̄ never reaches 0.98.
struct BlueNoiseFigures {
  double effective_nyquist = 0;  ///< normalized by √N
  bool nyquist_is_lower_bound = false;
  double oscillation = 0;
  double oscillation_from = 0, oscillation_to = 0;  ///< the annulus, normalized by √N
  bool window_is_cut = false;
};
BlueNoiseFigures blue_noise_figures(const RadialPower& radial);

}  // namespace stratum::analysis
