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

}  // namespace stratum::analysis
