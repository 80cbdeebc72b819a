#pragma once
/// The renderer's sampler: pbrt-v4's interface (start_pixel_sample, get_1d,
/// get_2d, get_pixel_2d; Pharr, Jakob, Humphreys 2023, "Physically Based
/// Rendering", 4th ed., §8.3) over any sampler of stratum's registry.
///
/// Dimensions are "padded" as in pbrt's PaddedSobolSampler: each 2D
/// dimension of a pixel is its own point set of spp points, drawn from the
/// registry sampler with a seed hashed from (seed, pixel, dimension), so a
/// sequence randomized per pixel and dimension (owen, owen-hash, xor, cp…)
/// gives independent scrambles, and a pattern (jittered, n-rooks…) a fresh
/// pattern. Sample `index` of the pixel takes point `index` of each set.
/// get_2d_array(n) returns n points of their own set, keyed also by the
/// sample index, so the n shadow rays of one eye ray are stratified among
/// themselves (LECTURE.md §2).
///
/// Time (LECTURE.md §8): with a time pattern (random, cook, magic-square),
/// film positions and times come together from the space-time sampler
/// spacetime-<pattern> (spp = m² strata, one time slot each); without one,
/// time is one more dimension of the sampler.
///
/// Direct paths: for random, sobol (owen-hash), jittered and pmj02 (their
/// default randomizers) a draw computes point `index` of the set straight
/// from the index-addressable core generators (sequences/, patterns/): no
/// registry call, no allocation, bit-identical to the registry's set (tested).
/// Other samplers draw each set through the registry once per pixel and
/// dimension and cache it; halton (permute) builds the same sets with its
/// scrambler directly, skipping the registry's request handling.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "stratum/registry.hpp"

namespace stratum::render {

struct PixelSamplerSettings {
  std::string sampler = "sobol";
  std::string randomize;    ///< empty: the sampler's default
  std::uint64_t seed = 0;
  std::uint32_t spp = 16;   ///< samples per pixel
  std::string time_pattern;  ///< "", "random", "cook" or "magic-square"
};

class PixelSampler {
 public:
  /// Validates the settings (sampler name, randomizer, that it accepts
  /// spp points in 2D, the time pattern and spp = m²) and throws
  /// stratum::invalid_argument naming what is wrong.
  explicit PixelSampler(PixelSamplerSettings settings);
  /// A fresh sampler with the same (already validated) settings, without the
  /// registry calls of validation: render() makes one per tile this way.
  PixelSampler(const PixelSampler& other);
  PixelSampler& operator=(const PixelSampler&) = delete;

  void start_pixel_sample(std::uint32_t x, std::uint32_t y, std::uint32_t index);
  double get_1d();
  std::array<double, 2> get_2d();
  /// The film position within the pixel, in [0,1)².
  std::array<double, 2> get_pixel_2d();
  /// The shutter fraction in [0,1).
  double get_time();
  /// n points stratified among themselves (n must be a count the sampler takes).
  void get_2d_array(std::uint32_t n, std::array<double, 2>* out);

  /// Point set `dimension` of a pixel, as drawn (for tests): the registry's
  /// points for seed hash(pixel key, dimension).
  PointSet draw_for_test(std::uint64_t n, std::uint64_t seed) const { return draw(settings_.sampler, n, 2, seed); }
  /// Whether draws take the direct path (see above).
  bool direct() const noexcept { return fast_ != Fast::none; }

  std::uint32_t samples_per_pixel() const noexcept { return settings_.spp; }
  const PixelSamplerSettings& settings() const noexcept { return settings_; }

 private:
  const PointSet& set_for(std::uint32_t dimension);
  PointSet draw(const std::string& sampler, std::uint64_t n, unsigned d, std::uint64_t seed) const;
  /// Point `index` of the n-point 2D set that draw(settings_.sampler, n, 2,
  /// seed) returns, computed alone (direct paths only; jittered needs n = k²
  /// and takes k = root, computed once per count rather than per point).
  std::array<double, 2> direct_point(std::uint64_t seed, std::uint64_t root, std::uint64_t index) const noexcept;
  /// Whether the direct path can produce an n-point set.
  bool direct_for(std::uint64_t n) const noexcept;

  PixelSamplerSettings settings_;
  enum class Fast { none, random, sobol_owen_hash, jittered, pmj02 };
  Fast fast_ = Fast::none;  ///< a direct path for the common samplers
  bool halton_permute_ = false;  ///< halton's sets built by RandomDigitPermutations directly (cached as other sets)
  std::string spacetime_;  ///< the space-time sampler, or empty
  std::uint64_t pixel_key_ = 0;
  bool first_pixel_ = true;
  std::uint64_t spp_root_ = 0;               ///< ⌊√spp⌋ (jittered's strata per axis)
  std::uint32_t array_n_ = 0;                ///< the last get_2d_array count …
  std::uint64_t array_root_ = 0;             ///< … and ⌊√n⌋
  std::uint32_t index_ = 0;
  std::uint32_t dimension_ = 0;
  std::vector<PointSet> sets_;  ///< this pixel's point sets, by dimension (cache)
  PointSet spacetime_set_;
};

}  // namespace stratum::render
