// image_spectrum: the FFT path against the direct sum, Parseval's
// normalization, white noise at 1 and a high-pass-filtered noise at its
// closed-form low-frequency power (fixed seeds; tolerances of 5 standard
// errors of a mean of ~400 independent exponential periodogram values,
// two-sided p < 1e-6 each).
#include "stratum/analysis/image_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace {

using stratum::analysis::image_spectrum;

/// Standard normal noise from the counter-based generator (Box–Muller).
std::vector<double> gaussian_noise(int width, int height, std::uint64_t seed) {
  std::vector<double> v(std::size_t(width) * std::size_t(height));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double u1 = 1 - stratum::uniform01(seed, i, 0), u2 = stratum::uniform01(seed, i, 1);
    v[i] = std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
  }
  return v;
}

TEST(ImageSpectrum, FftEqualsTheDirectSumForEvenAndOddSizes) {
  for (auto [w, h] : {std::pair{8, 6}, std::pair{7, 5}, std::pair{9, 12}}) {
    const auto values = gaussian_noise(w, h, 3);
    const auto fast = image_spectrum(values, w, h);
    const auto direct = stratum::analysis::image_power_direct(values, w, h);
    ASSERT_EQ(fast.power.size(), direct.size());
    for (std::size_t i = 0; i < direct.size(); ++i)
      EXPECT_NEAR(fast.power[i], direct[i], 1e-10 * (1 + direct[i])) << w << "x" << h << " bin " << i;
  }
}

TEST(ImageSpectrum, NormalizedToMeanOneAwayFromZeroWithAnEmptyZeroFrequency) {
  const int w = 20, h = 16;
  auto values = gaussian_noise(w, h, 4);
  for (double& v : values) v = 3 + 0.01 * v;  // offset and amplitude do not change the shape
  const auto s = image_spectrum(values, w, h);
  double sum = 0;
  for (double p : s.power) sum += p;
  EXPECT_NEAR(s.power[std::size_t(h / 2) * w + w / 2], 0.0, 1e-20);  // the mean is removed
  EXPECT_NEAR(sum / (w * h - 1), 1.0, 1e-12);
  const auto scaled = [&] {
    auto copy = values;
    for (double& v : copy) v *= 50;
    return image_spectrum(copy, w, h);
  }();
  for (std::size_t i = 0; i < s.power.size(); ++i) EXPECT_NEAR(scaled.power[i], s.power[i], 1e-9);
}

TEST(ImageSpectrum, WhiteNoiseHasLowFrequencyPowerOne) {
  const auto s = image_spectrum(gaussian_noise(128, 128, 5), 128, 128);
  // ~800 frequencies below 1/8 cycle per pixel, ~400 independent (Hermitian pairs): sd ≈ 0.05
  EXPECT_NEAR(s.low_frequency_power, 1.0, 0.25);
  ASSERT_EQ(s.radial_power.size(), 64u);
  EXPECT_NEAR(s.radial_frequency.front(), 1.0 / 128, 1e-15);
  EXPECT_NEAR(s.radial_frequency.back(), 0.5, 1e-15);
  double mean = 0;
  for (double p : s.radial_power) mean += p / 64;
  EXPECT_NEAR(mean, 1.0, 0.1);
}

TEST(ImageSpectrum, HighPassNoiseMatchesItsTransferFunction) {
  const int n = 128;
  const auto white = gaussian_noise(n, n, 6);
  // y = x − (sum of the 4 periodic neighbours)/4: H(f) = 1 − (cos 2πfx + cos 2πfy)/2.
  std::vector<double> blue(white.size());
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const auto at = [&](int i, int j) { return white[std::size_t((j + n) % n) * n + std::size_t((i + n) % n)]; };
      blue[std::size_t(y) * n + std::size_t(x)] =
          at(x, y) - (at(x - 1, y) + at(x + 1, y) + at(x, y - 1) + at(x, y + 1)) / 4;
    }
  double all = 0, low = 0;
  int all_count = 0, low_count = 0;
  for (int ky = -n / 2; ky < n / 2; ++ky)
    for (int kx = -n / 2; kx < n / 2; ++kx) {
      if (kx == 0 && ky == 0) continue;
      const double fx = double(kx) / n, fy = double(ky) / n;
      const double h = 1 - (std::cos(2 * std::numbers::pi * fx) + std::cos(2 * std::numbers::pi * fy)) / 2;
      all += h * h, ++all_count;
      if (std::hypot(fx, fy) < 0.125) low += h * h, ++low_count;
    }
  const double expected = (low / low_count) / (all / all_count);
  const auto s = image_spectrum(blue, n, n);
  EXPECT_LT(expected, 0.1);
  EXPECT_NEAR(s.low_frequency_power, expected, 0.25 * expected);
}

TEST(ImageSpectrum, RefusesWhatHasNoSpectrum) {
  EXPECT_THROW(image_spectrum(std::vector<double>(16, 2.0), 4, 4), stratum::invalid_argument);
  EXPECT_THROW(image_spectrum(std::vector<double>(9, 1.0), 3, 3), stratum::invalid_argument);
  EXPECT_THROW(image_spectrum(std::vector<double>(15, 1.0), 4, 4), stratum::invalid_argument);
  auto values = gaussian_noise(4, 4, 1);
  values[5] = std::nan("");
  try {
    image_spectrum(values, 4, 4);
    FAIL() << "a NaN pixel was accepted";
  } catch (const stratum::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pixel 5"), std::string::npos) << e.what();
  }
}

/// F frames of width × height standard normal noise, independent in time.
std::vector<std::vector<double>> white_frames(int frames, int width, int height, std::uint64_t seed) {
  std::vector<std::vector<double>> out;
  for (int t = 0; t < frames; ++t) out.push_back(gaussian_noise(width, height, seed + std::uint64_t(t) * 1000003));
  return out;
}

TEST(TemporalSpectrum, EqualsTheDirectSumOverTimeForEvenAndOddFrameCounts) {
  for (int f : {9, 16}) {
    const int w = 3, h = 2;
    auto frames = white_frames(f, w, h, 21);
    for (auto& frame : frames) frame[4] *= 5;  // pixels of unequal variance: the pooling shows
    const auto s = stratum::analysis::temporal_spectrum(frames, w, h);
    // Direct: Σ_p |Σ_t x_p(t) e^{−2πikt/F}|², x centred per pixel, normalized by the pooled mean over k ≠ 0.
    std::vector<double> power(std::size_t(f), 0.0);
    double total = 0, lag = 0, sum2 = 0;
    for (int p = 0; p < w * h; ++p) {
      double mean = 0;
      for (int t = 0; t < f; ++t) mean += frames[std::size_t(t)][std::size_t(p)] / f;
      for (int k = 0; k < f; ++k) {
        std::complex<double> x = 0;
        for (int t = 0; t < f; ++t)
          x += (frames[std::size_t(t)][std::size_t(p)] - mean) *
               std::exp(std::complex<double>(0, -2 * std::numbers::pi * k * t / f));
        power[std::size_t(k)] += std::norm(x) / f;
        if (k) total += std::norm(x) / f;
      }
      for (int t = 0; t < f; ++t) {
        const double x = frames[std::size_t(t)][std::size_t(p)] - mean;
        sum2 += x * x;
        if (t + 1 < f) lag += x * (frames[std::size_t(t + 1)][std::size_t(p)] - mean);
      }
    }
    ASSERT_EQ(s.power.size(), std::size_t(f / 2));
    for (int k = 1; k <= f / 2; ++k) {
      EXPECT_NEAR(s.frequency[std::size_t(k - 1)], double(k) / f, 1e-15);
      const double expected = power[std::size_t(k)] / (total / (f - 1));
      EXPECT_NEAR(s.power[std::size_t(k - 1)], expected, 1e-10 * (1 + expected)) << "F " << f << " k " << k;
    }
    EXPECT_NEAR(s.lag1_correlation, lag / sum2, 1e-12);
    EXPECT_NEAR(s.variance, sum2 / (w * h * f), 1e-12);
    EXPECT_NEAR(s.low_frequency_power, s.power[0], 1e-15);  // 0 < k/F < 1/8: k = 1 only, for F = 9 and 16
  }
}

TEST(TemporalSpectrum, IndependentFramesAreWhiteInTime) {
  // 4096 pixels × 3 bins below 1/8 (F = 32): ~12000 exponential periodogram
  // values, sd of their mean ≈ 0.01; 0.05 is 5 sd. The lag-1 correlation of
  // centred independent series is −1/F on average, sd ≈ 1/√(4096·31) ≈ 0.003.
  const auto s = stratum::analysis::temporal_spectrum(white_frames(32, 64, 64, 31), 64, 64);
  EXPECT_NEAR(s.low_frequency_power, 1.0, 0.05);
  EXPECT_NEAR(s.lag1_correlation, -1.0 / 32, 0.015);
  EXPECT_NEAR(s.variance, 31.0 / 32, 0.03);
  for (double p : s.power) EXPECT_NEAR(p, 1.0, 0.1);  // each bin: 4096 values (2 at k < 16), sd ≤ 0.016
}

TEST(TemporalSpectrum, DifferencedNoiseMatchesItsTransferFunction) {
  // x(t) = w(t) − w(t − 1 mod F): |H(k)|² = 2 − 2 cos(2πk/F), mean 2F/(F − 1)
  // over k ≠ 0, so E[P(k)] ≈ (2 − 2 cos(2πk/F))·(F − 1)/(2F): blue in time.
  const int f = 32, n = 64;
  const auto white = white_frames(f, n, n, 41);
  std::vector<std::vector<double>> blue(std::size_t(f), std::vector<double>(std::size_t(n * n)));
  for (int t = 0; t < f; ++t)
    for (std::size_t p = 0; p < std::size_t(n * n); ++p)
      blue[std::size_t(t)][p] = white[std::size_t(t)][p] - white[std::size_t((t + f - 1) % f)][p];
  const auto s = stratum::analysis::temporal_spectrum(blue, n, n);
  double low = 0;
  for (int k = 1; k <= 3; ++k) {
    const double expected = (2 - 2 * std::cos(2 * std::numbers::pi * k / f)) * (f - 1) / (2.0 * f);
    low += expected / 3;
    EXPECT_NEAR(s.power[std::size_t(k - 1)], expected, 0.1 * expected) << "k " << k;
  }
  EXPECT_LT(low, 0.1);
  EXPECT_NEAR(s.low_frequency_power, low, 0.1 * low);
  EXPECT_NEAR(s.lag1_correlation, -0.5 * (f - 1) / f, 0.02);  // E[x(t)x(t+1)] = −σ², E[x²] = 2σ²
}

TEST(TemporalSpectrum, RefusesWhatHasNoTemporalSpectrum) {
  using stratum::analysis::temporal_spectrum;
  EXPECT_THROW(temporal_spectrum(white_frames(8, 4, 4, 1), 4, 4), stratum::invalid_argument);
  EXPECT_THROW(temporal_spectrum(std::vector<std::vector<double>>(9, std::vector<double>(16, 2.0)), 4, 4),
               stratum::invalid_argument);
  auto frames = white_frames(9, 4, 4, 1);
  frames[3].pop_back();
  EXPECT_THROW(temporal_spectrum(frames, 4, 4), stratum::invalid_argument);
  frames = white_frames(9, 4, 4, 1);
  frames[6][2] = std::nan("");
  try {
    temporal_spectrum(frames, 4, 4);
    FAIL() << "a NaN value was accepted";
  } catch (const stratum::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("frame 6, pixel 2"), std::string::npos) << e.what();
  }
}

}  // namespace
