/// image_spectrum.hpp: a 2D FFT (rows, then columns) with kissfft's
/// header-only C++ template in double precision.
#include "stratum/analysis/image_spectrum.hpp"

#include <kissfft/kissfft.hh>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "stratum/util/error.hpp"

namespace stratum::analysis {

namespace {

using Complex = std::complex<double>;

/// The values minus their mean (throws for what image_spectrum refuses).
std::vector<double> centred(const std::vector<double>& values, int width, int height, double* variance) {
  require(width >= 4 && width <= 16384, "width", width, "must be in [4, 16384]");
  require(height >= 4 && height <= 16384, "height", height, "must be in [4, 16384]");
  require(values.size() == std::size_t(width) * std::size_t(height), "values", values.size(),
          "must hold width × height = " + std::to_string(std::size_t(width) * std::size_t(height)) + " values");
  double mean = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    require(std::isfinite(values[i]), "values", values[i], "must be finite (pixel " + std::to_string(i) + ")");
    mean += values[i];
  }
  mean /= double(values.size());
  std::vector<double> out(values.size());
  double sum2 = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    out[i] = values[i] - mean;
    sum2 += out[i] * out[i];
  }
  *variance = sum2 / double(values.size());
  require(*variance > 0, "values", "a constant image", "has no spectrum (every frequency but 0 is empty)");
  return out;
}

/// Folded index of DFT bin k of n: k ≥ ⌈n/2⌉ are the negative frequencies k − n.
int folded(int k, int n) { return k < (n + 1) / 2 ? k : k - n; }

}  // namespace

ImageSpectrum image_spectrum(const std::vector<double>& values, int width, int height) {
  ImageSpectrum result;
  const std::vector<double> x = centred(values, width, height, &result.variance);
  result.width = width;
  result.height = height;
  const std::size_t w = std::size_t(width), h = std::size_t(height);
  std::vector<Complex> grid(w * h), line(std::max(w, h)), transformed(std::max(w, h));
  for (std::size_t i = 0; i < w * h; ++i) grid[i] = x[i];
  const kissfft<double> rows(w, false), columns(h, false);
  for (std::size_t y = 0; y < h; ++y) {
    rows.transform(grid.data() + y * w, transformed.data());
    std::copy(transformed.begin(), transformed.begin() + std::ptrdiff_t(w), grid.begin() + std::ptrdiff_t(y * w));
  }
  for (std::size_t kx = 0; kx < w; ++kx) {
    for (std::size_t y = 0; y < h; ++y) line[y] = grid[y * w + kx];
    columns.transform(line.data(), transformed.data());
    for (std::size_t y = 0; y < h; ++y) grid[y * w + kx] = transformed[y];
  }
  // P(k) = |F(k)|² / (W·H), divided by its mean over k ≠ 0, which by Parseval is W·H·σ²/(W·H − 1).
  const double cells = double(w * h), scale = (cells - 1) / (cells * cells * result.variance);
  result.power.assign(w * h, 0.0);
  const int rings = std::min(width, height) / 2;
  std::vector<double> ring_sum(std::size_t(rings), 0.0);
  std::vector<std::size_t> ring_count(std::size_t(rings), 0);
  double low_sum = 0;
  std::size_t low_count = 0;
  const double ring_width = 1.0 / std::min(width, height);
  for (std::size_t ky = 0; ky < h; ++ky)
    for (std::size_t kx = 0; kx < w; ++kx) {
      const int fx = folded(int(kx), width), fy = folded(int(ky), height);
      const double p = std::norm(grid[ky * w + kx]) * scale;
      result.power[std::size_t(fy + height / 2) * w + std::size_t(fx + width / 2)] = p;
      if (fx == 0 && fy == 0) continue;
      const double f = std::hypot(double(fx) / width, double(fy) / height);
      if (f < 0.125) low_sum += p, ++low_count;
      const auto ring = static_cast<std::size_t>(std::lround(f / ring_width));  // ring b ≥ 1 at slot b − 1
      if (ring >= 1 && ring <= ring_sum.size()) ring_sum[ring - 1] += p, ++ring_count[ring - 1];
    }
  for (int b = 0; b < rings; ++b) {
    result.radial_frequency.push_back((b + 1) * ring_width);
    result.radial_power.push_back(ring_count[std::size_t(b)]
                                      ? ring_sum[std::size_t(b)] / double(ring_count[std::size_t(b)])
                                      : std::numeric_limits<double>::quiet_NaN());
  }
  result.low_frequency_power = low_count ? low_sum / double(low_count) : std::numeric_limits<double>::quiet_NaN();
  return result;
}

std::vector<double> image_power_direct(const std::vector<double>& values, int width, int height) {
  double variance = 0;
  const std::vector<double> x = centred(values, width, height, &variance);
  const std::size_t w = std::size_t(width), h = std::size_t(height);
  const double cells = double(w * h), scale = (cells - 1) / (cells * cells * variance);
  std::vector<double> power(w * h);
  for (int fy = -height / 2; fy < (height + 1) / 2; ++fy)
    for (int fx = -width / 2; fx < (width + 1) / 2; ++fx) {
      Complex sum = 0;
      for (std::size_t y = 0; y < h; ++y)
        for (std::size_t k = 0; k < w; ++k) {
          const double phase =
              -2 * std::numbers::pi * (double(fx) * double(k) / width + double(fy) * double(y) / height);
          sum += x[y * w + k] * std::exp(Complex(0, phase));
        }
      power[std::size_t(fy + height / 2) * w + std::size_t(fx + width / 2)] = std::norm(sum) * scale;
    }
  return power;
}

TemporalSpectrum temporal_spectrum(const std::vector<std::vector<double>>& frames, int width, int height) {
  require(frames.size() >= 9 && frames.size() <= 65536, "frames", frames.size(),
          "must be 9 to 65536 frames (the lowest frequency 1/F must lie below 1/8 cycle per frame)");
  require(width >= 1 && height >= 1 && std::size_t(width) * std::size_t(height) <= std::size_t(1) << 28, "size",
          std::to_string(width) + "x" + std::to_string(height), "must be at least 1x1 and at most 2^28 pixels");
  const std::size_t f = frames.size(), pixels = std::size_t(width) * std::size_t(height);
  for (std::size_t t = 0; t < f; ++t) {
    require(frames[t].size() == pixels, "frames",
            "frame " + std::to_string(t) + " of " + std::to_string(frames[t].size()) + " values",
            "must hold width × height = " + std::to_string(pixels) + " values, as every frame");
    for (std::size_t i = 0; i < pixels; ++i)
      require(std::isfinite(frames[t][i]), "frames", frames[t][i],
              "must be finite (frame " + std::to_string(t) + ", pixel " + std::to_string(i) + ")");
  }
  TemporalSpectrum result;
  result.frames = int(f);
  result.width = width;
  result.height = height;
  const std::size_t bins = f / 2;
  std::vector<double> sum(bins, 0.0);
  std::vector<Complex> series(f), transformed(f);
  const kissfft<double> transform(f, false);
  double sum2 = 0, lag1 = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    double mean = 0;
    for (std::size_t t = 0; t < f; ++t) mean += frames[t][i];
    mean /= double(f);
    for (std::size_t t = 0; t < f; ++t) {
      series[t] = frames[t][i] - mean;
      sum2 += std::norm(series[t]);
      if (t > 0) lag1 += series[t - 1].real() * series[t].real();
    }
    transform.transform(series.data(), transformed.data());
    // Bin k ≥ 1 folds k and F − k (equal for a real series); at k = F/2 (F even) one term.
    for (std::size_t k = 1; k <= bins; ++k)
      sum[k - 1] +=
          2 * k == f ? std::norm(transformed[k]) : (std::norm(transformed[k]) + std::norm(transformed[f - k])) / 2;
  }
  require(sum2 > 0, "frames", "frames constant in time",
          "have no temporal spectrum (every pixel's series is constant)");
  // Σ_{k≠0} |X_p(k)|² = F Σ_t x_p(t)² (Parseval), so the pooled mean of P over k ≠ 0 is sum2 / (pixels·(F − 1)).
  const double scale = double(f - 1) / (double(f) * sum2);
  double low = 0;
  std::size_t low_count = 0;
  for (std::size_t k = 1; k <= bins; ++k) {
    result.frequency.push_back(double(k) / double(f));
    result.power.push_back(sum[k - 1] * scale);
    if (8 * k < f) {
      // both k and F − k count, as in the image's mean over frequencies
      low += result.power.back();
      ++low_count;
    }
  }
  result.low_frequency_power = low / double(low_count);
  result.lag1_correlation = lag1 / sum2;
  result.variance = sum2 / (double(pixels) * double(f));
  return result;
}

}  // namespace stratum::analysis
