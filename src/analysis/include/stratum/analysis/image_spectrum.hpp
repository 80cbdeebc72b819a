#pragma once
/// The power spectrum of an image: where the error of a render goes
/// (LECTURE.md §8; Georgiev & Fajardo 2016, Heitz et al. 2019, Ahmed & Wonka
/// 2020 measure blue-noise error this way). Point-set spectra are in
/// spectrum.hpp; this is the spectrum of a W × H grid of values, e.g. the
/// luminance of render − reference.
///
/// With F(k) the discrete Fourier transform of the values minus their mean,
/// P(k) = |F(k)|² / (W·H) is normalized by its mean over the nonzero
/// frequencies (by Parseval, the values' variance), so that white noise has
/// E[P(k)] = 1 at every k ≠ 0 whatever its amplitude: the spectrum shows the
/// *shape* of the error, the MSE its size. Frequencies are in cycles per
/// pixel, (kx/W, ky/H) folded into [−½, ½)².
#include <cstddef>
#include <vector>

namespace stratum::analysis {

struct ImageSpectrum {
  int width = 0, height = 0;
  /// P(k) on the folded grid, power[(ky + H/2)·W + (kx + W/2)] with
  /// kx ∈ [−⌊W/2⌋, ⌈W/2⌉), ky likewise (zero frequency at the centre).
  std::vector<double> power;
  /// Radial average over rings one frequency step wide: ring b = 1 … ⌊min(W, H)/2⌋
  /// holds the frequencies with |f| within Δ/2 of b·Δ, Δ = 1/min(W, H) cycles
  /// per pixel (the last ring reaches the Nyquist circle |f| = ½).
  std::vector<double> radial_frequency;  ///< b·Δ (cycles per pixel)
  std::vector<double> radial_power;      ///< mean P over each ring (rings without a frequency: NaN)
  /// Mean P over 0 < |f| < ⅛ (a quarter of Nyquist): 1 for white noise, < 1
  /// when the error is pushed to high frequencies (blue noise), > 1 when it
  /// is clumped (low-frequency blotches).
  double low_frequency_power = 0;
  double variance = 0;  ///< of the values (the mean P before normalization)
};

/// The spectrum of `values` (row-major, width × height, finite), by FFT
/// (kissfft, mixed radix: any size). Throws stratum::invalid_argument for
/// width or height < 4, a size mismatch or a non-finite value, and for a
/// constant image (its spectrum has no shape).
ImageSpectrum image_spectrum(const std::vector<double>& values, int width, int height);

/// The same P(k) by the direct O((W·H)²) sum, for tests of the FFT path.
std::vector<double> image_power_direct(const std::vector<double>& values, int width, int height);

/// The temporal spectrum of a sequence of F frames (each W × H values, e.g.
/// the luminance error of frame k of an animation): where each pixel's error
/// goes in time (Wolfe et al. 2022, spatiotemporal blue noise; Heitz &
/// Belcour 2019). Each pixel's series minus its own mean (its mean error over
/// the frames, the k = 0 term) is transformed over time, P_p(k) =
/// |X_p(k)|² / F, and the pixels' P_p(k) averaged and normalized by their
/// mean over k ≠ 0 (pooled over pixels), so that a series independent from
/// frame to frame (white in time) has E[P(k)] = 1 at every k ≠ 0.
struct TemporalSpectrum {
  int frames = 0, width = 0, height = 0;
  /// k / F for k = 1 … ⌊F/2⌋ (cycles per frame; k and F − k folded: the
  /// series are real).
  std::vector<double> frequency;
  std::vector<double> power;  ///< mean P(k) over the pixels, normalized as above
  /// Mean P over 0 < f < ⅛ cycle per frame: 1 white in time, < 1 when a
  /// pixel's error alternates from frame to frame (blue in time: frames
  /// averaged cancel), > 1 when it persists (a flicker-free but slowly
  /// converging, positively correlated sequence).
  double low_frequency_power = 0;
  /// Pooled lag-1 autocorrelation Σ_p Σ_t x_p(t)·x_p(t+1) / Σ_p Σ_t x_p(t)²
  /// of the centred series (t + 1 < F): about −1/F for independent frames
  /// (the centring), negative when consecutive frames compensate.
  double lag1_correlation = 0;
  double variance = 0;  ///< mean over pixels of each pixel's variance over the frames
};

/// The temporal spectrum of `frames` (each row-major, width × height,
/// finite). Throws stratum::invalid_argument for fewer than 9 frames (the
/// first frequency below ⅛ is 1/F), frames of another size than width ×
/// height, a non-finite value, and for frames constant in time.
TemporalSpectrum temporal_spectrum(const std::vector<std::vector<double>>& frames, int width, int height);

}  // namespace stratum::analysis
