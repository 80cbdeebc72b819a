#pragma once
/// Candidate points of Bridson's dart throwing (Bridson 2007, "Fast Poisson
/// disk sampling in arbitrary dimensions"): offsets uniform by volume in the
/// annulus r ≤ |offset| < 2r around an active sample, from counter-based
/// random words (SplitMix64 finalizer, stratum/util/hash.hpp), so that a
/// candidate depends only on (seed, step, index). Used by the Poisson-disk
/// engine (poisson_disk_grid.hpp); in the plane, the inner loop of the whole
/// sampler, hence the branch-free 2D version.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "stratum/util/hash.hpp"

namespace stratum::poisson_detail {

// Random-stream tags keeping the phases apart.
inline constexpr std::uint64_t tag_first = 0x5044'4649'5253'54ULL;
inline constexpr std::uint64_t tag_pick = 0x5044'5049'434bULL;
inline constexpr std::uint64_t tag_candidate = 0x5044'4341'4e44ULL;
inline constexpr std::uint64_t tag_dart = 0x5044'4441'5254ULL;

/// Candidate `candidate` of a Bridson step keyed by `key`: an offset uniform
/// (by volume) in the annulus r ≤ |offset| < 2r. Random words come from a
/// SplitMix64 stream, 2^16 words per candidate. d ≤ 4: rejection from the
/// cube [-2r, 2r)^d with 32-bit coordinates (acceptance 0.75, 0.59, 0.46,
/// 0.29; no transcendental functions); d ≥ 5: a Gaussian direction
/// (Box-Muller) and the inverse-CDF radius.
inline void annulus_offset(unsigned d, double r, std::uint64_t key, unsigned candidate, double* offset) {
  std::uint64_t counter = key + (std::uint64_t{candidate} << 16) * 0x9e3779b97f4a7c15ULL;
  auto word = [&counter] { return mix64(counter += 0x9e3779b97f4a7c15ULL); };
  const double r2 = r * r;
  if (d <= 4) {
    for (unsigned attempt = 0; attempt < 4096; ++attempt) {
      double sum = 0;
      for (unsigned j = 0; j < d; j += 2) {
        const std::uint64_t bits = word();
        offset[j] = (static_cast<double>(bits >> 32) * 0x1.0p-30 - 2.0) * r;
        if (j + 1 < d) offset[j + 1] = (static_cast<double>(bits & 0xffffffffu) * 0x1.0p-30 - 2.0) * r;
      }
      for (unsigned j = 0; j < d; ++j) sum += offset[j] * offset[j];
      if (sum >= r2 && sum < 4 * r2) return;
    }
    for (unsigned j = 0; j < d; ++j) offset[j] = j == 0 ? r : 0.0;  // probability < 0.71^4096
    return;
  }
  double norm2 = 0;
  for (unsigned j = 0; j < d; j += 2) {
    const double rho = std::sqrt(-2.0 * std::log(1.0 - bits_to_double(word())));
    const double angle = 2 * std::numbers::pi * bits_to_double(word());
    offset[j] = rho * std::cos(angle);
    if (j + 1 < d) offset[j + 1] = rho * std::sin(angle);
  }
  for (unsigned j = 0; j < d; ++j) norm2 += offset[j] * offset[j];
  const double annulus_ratio = std::pow(2.0, static_cast<double>(d)) - 1.0;
  const double distance = r * std::pow(1.0 + annulus_ratio * bits_to_double(word()), 1.0 / d);
  const double scale = norm2 > 0 ? distance / std::sqrt(norm2) : 0.0;
  for (unsigned j = 0; j < d; ++j) offset[j] *= scale;
}

/// 256 unit vectors at angles 2πk/256, interleaved (cos, sin).
inline const std::array<double, 512>& unit_circle_256() {
  static const std::array<double, 512> table = [] {
    std::array<double, 512> values{};
    for (std::size_t k = 0; k < 256; ++k) {
      values[2 * k] = std::cos(2 * std::numbers::pi * static_cast<double>(k) / 256);
      values[2 * k + 1] = std::sin(2 * std::numbers::pi * static_cast<double>(k) / 256);
    }
    return values;
  }();
  return table;
}

/// The 2D candidate of annulus_offset from a single 64-bit word, without
/// branches or calls (Bridson's inner loop in the plane): angle
/// 2π(k + δ)/256 from a table of 256 unit vectors turned by δ (Taylor series
/// of cos and sin, exact to double rounding for |2πδ/256| < 0.025), radius
/// r·sqrt(1 + 3u), uniform by area in [r, 2r). 8 bits pick the sector, 28
/// the turn and 28 the radius.
inline void annulus_offset_2d(double r, std::uint64_t key, unsigned candidate, double* offset,
                              const std::array<double, 512>& circle = unit_circle_256()) noexcept {
  const std::uint64_t bits = mix64(key + (std::uint64_t{candidate} + 1) * 0x9e3779b97f4a7c15ULL);
  const std::size_t sector = bits >> 56;
  const double t = static_cast<double>((bits >> 28) & 0xfffffffu) * 0x1.0p-28 * (2 * std::numbers::pi / 256);
  const double u = static_cast<double>(bits & 0xfffffffu) * 0x1.0p-28;
  const double t2 = t * t;
  const double cos_t = 1 - t2 * 0.5 * (1 - t2 * (1.0 / 12) * (1 - t2 * (1.0 / 30)));
  const double sin_t = t * (1 - t2 * (1.0 / 6) * (1 - t2 * (1.0 / 20) * (1 - t2 * (1.0 / 42))));
  const double distance = r * std::sqrt(1 + 3 * u);
  const double c = circle[2 * sector], s = circle[2 * sector + 1];
  offset[0] = distance * (c * cos_t - s * sin_t);
  offset[1] = distance * (s * cos_t + c * sin_t);
}

/// unit_circle_256 rounded to float.
inline const std::array<float, 512>& unit_circle_256_float() {
  static const std::array<float, 512> table = [] {
    std::array<float, 512> values{};
    for (std::size_t k = 0; k < 512; ++k) values[k] = static_cast<float>(unit_circle_256()[k]);
    return values;
  }();
  return table;
}

/// Eight lanes of floats (GCC/Clang vector extensions: one AVX register,
/// or two SSE registers where AVX is not enabled).
using floats8 = float __attribute__((vector_size(32)));

/// Candidates first .. first + 7 of annulus_offset_2d, approximated in
/// float from the same random words: a screen that rejects candidates
/// surely too close to a sample, not the candidates themselves. Each
/// 28-bit field keeps its top 23 bits (a float in [1, 2) built from them;
/// error below 2^-23), the table is rounded to float, the series stops at
/// t^4 and t^5 (remainders below 10^-12 for |t| < 2π/256), and the root
/// is two Newton steps for 1/√s from the classic bit-level first guess
/// (Lomont 2003, "Fast inverse square root"; 3.5% off, then 2·10^-3, then
/// 5·10^-6): relative error below 10^-5 in all (tested).
/// Always inlined, so that it takes its caller's instruction set.
[[gnu::always_inline]] inline void annulus_offsets_2d_float(float r, std::uint64_t key, unsigned first, floats8& x,
                                                            floats8& y, const std::array<float, 512>& circle) noexcept {
  using words8 = std::uint32_t __attribute__((vector_size(32)));
  words8 high = {}, low = {};
  floats8 c = {}, s = {};
  for (unsigned lane = 0; lane < 8; ++lane) {
    const std::uint64_t bits = mix64(key + (std::uint64_t{first + lane} + 1) * 0x9e3779b97f4a7c15ULL);
    const std::size_t sector = bits >> 56;
    high[lane] = static_cast<std::uint32_t>(bits >> 32);
    low[lane] = static_cast<std::uint32_t>(bits);
    c[lane] = circle[2 * sector];
    s[lane] = circle[2 * sector + 1];
  }
  // Fields: turn = bits 55..28, radius = bits 27..0 (as annulus_offset_2d).
  const words8 one = {0x3f800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u,
                      0x3f800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u};
  const floats8 t = ((floats8)(one | ((high >> 1) & 0x7fffffu)) - 1) * static_cast<float>(2 * std::numbers::pi / 256);
  const floats8 u = (floats8)(one | ((low >> 5) & 0x7fffffu)) - 1;
  const floats8 square = 1 + 3 * u;
  floats8 inverse = (floats8)(0x5f3759dfu - ((words8)square >> 1));
  for (int newton = 0; newton < 2; ++newton) inverse *= 1.5f - 0.5f * square * inverse * inverse;
  const floats8 distance = r * (square * inverse), t2 = t * t;
  const floats8 cos_t = 1 - t2 * (0.5f - t2 * (1.0f / 24));
  const floats8 sin_t = t * (1 - t2 * (1.0f / 6) * (1 - t2 * (1.0f / 20)));
  x = distance * (c * cos_t - s * sin_t);
  y = distance * (s * cos_t + c * sin_t);
}

}  // namespace stratum::poisson_detail
