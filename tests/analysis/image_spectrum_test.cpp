// image_spectrum: the FFT path against the direct sum, Parseval's
// normalization, white noise at 1 and a high-pass-filtered noise at its
// closed-form low-frequency power (fixed seeds; tolerances of 5 standard
// errors of a mean of ~400 independent exponential periodogram values,
// two-sided p < 1e-6 each).
#include "stratum/analysis/image_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
