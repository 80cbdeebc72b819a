#pragma once
/// Pixel sampling for a renderer: the shape of pbrt-v4's Sampler (Pharr,
/// Jakob, Humphreys 2023, "Physically Based Rendering", 4th ed., §8.3) —
/// start a pixel sample, then draw 1D and 2D values, the film position and
/// arrays of n points stratified among themselves — over any of the core's
/// index-addressable 2D set techniques (pixel/set_techniques.hpp).
///
/// One class per render, chosen once: PixelSampler<Technique> is a template,
/// so a draw is one inlined path with no virtual call, no allocation, no
/// exception and no choice by name. Its state is 32 bytes (a pointer to the
/// render's read-only Shared, the pixel's hash, the sample's index and the
/// next dimension): trivially copyable, one per thread or GPU lane.
///
/// How a pixel's draws are decorrelated ("padded" dimensions, as pbrt's
/// PaddedSobolSampler): the pixel's key is hash64(seed, tag_pixel, x, y);
/// each 2D dimension d of the pixel is its own set of spp points, the
/// technique's set of seed hash64(pixel key, d), and sample i of the pixel
/// takes point i of every such set. So two dimensions, or two pixels, never
/// share a scramble, and each pixel's set of one dimension has the
/// technique's property (a (0,m,2)-net for Sobol' at spp = 2^m, one point in
/// each of the k × k strata for jittered at spp = k²). get_1d takes the first
/// coordinate of the next 2D dimension.
///
/// Arrays (get_2d_array, the n shadow rays of one eye ray, LECTURE.md §2):
/// the n points are the technique's set of seed hash64(pixel key, tag_array,
/// d, ·), stratified among themselves. A progressive technique (its sets are
/// prefixes of one randomized sequence) continues the pixel's sequence:
/// sample s takes points s·n … s·n + n − 1 of the one set of seed
/// hash64(pixel key, tag_array, d, tag_continued), so the arrays of a pixel's
/// samples together are its first spp·n points (for Sobol' an aligned block
/// each, all together one net); a pattern draws a fresh set per sample (the
/// seed's last counter is the sample's index).
///
/// Frames (an animation, LECTURE.md §8): for a progressive technique frame K
/// continues each pixel's sequence — its samples are K·spp … (K+1)·spp − 1,
/// so frames 0 … K−1 together are one frame at K·spp; a pattern draws frame
/// K from seed hash64(seed, tag_frame, K) (independent frames). Frame 0 is
/// the render without frames, bit for bit.
///
/// These are the sets stratum's renderer draws (tests/render/core_draws_test.cpp)
/// and the registry's points of the same sampler for those seeds
/// (tests/pixel/set_techniques_test.cpp).
#include <array>
#include <cstdint>
#include <optional>

#include "stratum/util/hash.hpp"
#include "stratum/util/host_device.hpp"

namespace stratum::pixel {

/// Random-stream tags of the pixel sampler's seeds.
inline constexpr std::uint64_t tag_pixel = 0x5049'5845'4cULL;
inline constexpr std::uint64_t tag_array = 0x4152'5241'59ULL;
inline constexpr std::uint64_t tag_frame = 0x4652'414d'45ULL;
/// The last counter of a progressive technique's array seeds: above 2^32, so no sample index equals it.
inline constexpr std::uint64_t tag_continued = 0x434f'4e54'494e'5545ULL;

/// The seed of pixel (x, y)'s set of 2D dimension d (for tests and other implementations).
STRATUM_HOST_DEVICE constexpr std::uint64_t set_seed(std::uint64_t seed, std::uint32_t x, std::uint32_t y,
                                                     std::uint32_t dimension) noexcept {
  return hash64(hash64(seed, tag_pixel, x, y), dimension);
}
/// The seed of pixel (x, y)'s array set of dimension d for sample `index` (a
/// pattern's) or for every sample (a progressive technique's: index = tag_continued).
STRATUM_HOST_DEVICE constexpr std::uint64_t array_seed(std::uint64_t seed, std::uint32_t x, std::uint32_t y,
                                                       std::uint32_t dimension, std::uint64_t index) noexcept {
  return hash64(hash64(seed, tag_pixel, x, y), tag_array, dimension, index);
}

/// What a render's pixel samplers share, read-only: the technique (with its
/// tables by pointer) and the frame. Made once on the host (make validates),
/// then passed by pointer to every thread or copied to a device.
template <class Technique>
struct Shared {
  Technique technique;
  typename Technique::Shape shape;  ///< the technique's set of spp points
  std::uint64_t seed = 0;           ///< the frame's seed (see above)
  std::uint64_t offset = 0;         ///< the frame's first sample in each pixel's sequence
  std::uint32_t spp = 1;

  /// The Shared of a render: spp samples a pixel, frame `frame` of seed
  /// `seed`. Host only: nullopt where the technique cannot make a set of spp
  /// points or (frame + 1)·spp passes 2^32.
  static std::optional<Shared> make(const Technique& technique, std::uint32_t spp, std::uint64_t seed,
                                    std::uint32_t frame = 0) {
    if (spp == 0 || !technique.takes(spp)) return std::nullopt;
    if ((std::uint64_t{frame} + 1) * spp > (std::uint64_t{1} << 32)) return std::nullopt;
    return Shared{technique, technique.shape(spp),
                  Technique::progressive || frame == 0 ? seed : hash64(seed, tag_frame, frame),
                  Technique::progressive ? std::uint64_t{frame} * spp : 0, spp};
  }
};

template <class Technique>
class PixelSampler {
 public:
  using Point = std::array<double, 2>;

  STRATUM_HOST_DEVICE explicit PixelSampler(const Shared<Technique>* shared) noexcept : shared_(shared) {}

  /// Sample `index` (< spp; larger values wrap) of pixel (x, y) of the frame.
  STRATUM_HOST_DEVICE void start_pixel_sample(std::uint32_t x, std::uint32_t y, std::uint32_t index) noexcept {
    pixel_mix_ = hash64(hash64(shared_->seed, tag_pixel, x, y));  // hash64(key, c) = hash64_extend(pixel_mix_, c)
    const std::uint32_t spp = shared_->spp;
    sample_ = shared_->offset + (index < spp ? index : index % spp);
    dimension_ = 0;
  }

  STRATUM_HOST_DEVICE double get_1d() noexcept { return draw<1>()[0]; }
  STRATUM_HOST_DEVICE Point get_2d() noexcept { return draw<2>(); }
  /// The film position within the pixel, in [0,1)²: the first 2D dimension.
  STRATUM_HOST_DEVICE Point get_pixel_2d() noexcept { return draw<2>(); }

  /// n points stratified among themselves (see above); n must be a count the
  /// technique takes (Technique::takes, checked on the host).
  STRATUM_HOST_DEVICE void get_2d_array(std::uint32_t n, Point* out) noexcept {
    const Technique& technique = shared_->technique;
    const std::uint64_t prefix = hash64_extend(hash64_extend(pixel_mix_, tag_array), dimension_++);
    const std::uint64_t seed = hash64_extend(prefix, Technique::progressive ? tag_continued : sample_);
    const std::uint64_t start = Technique::progressive ? sample_ * n : 0;  // < 2^64: both factors < 2^32
    const typename Technique::Shape shape = technique.shape(n);
    const typename Technique::Key key = technique.key(shape, seed);
    for (std::uint32_t i = 0; i < n; ++i) out[i] = technique.template point<2>(key, shape, start + i);
  }

  /// The sample's index in its pixel's sequence (frame · spp + index for a progressive technique).
  STRATUM_HOST_DEVICE std::uint64_t sequence_index() const noexcept { return sample_; }
  STRATUM_HOST_DEVICE std::uint32_t dimension() const noexcept { return dimension_; }
  STRATUM_HOST_DEVICE const Shared<Technique>& shared() const noexcept { return *shared_; }

 private:
  template <int coordinates>
  STRATUM_HOST_DEVICE Point draw() noexcept {
    const Technique& technique = shared_->technique;
    const typename Technique::Key key = technique.key(shared_->shape, hash64_extend(pixel_mix_, dimension_++));
    return technique.template point<coordinates>(key, shared_->shape, sample_);
  }

  const Shared<Technique>* shared_;
  std::uint64_t pixel_mix_ = 0;  ///< hash64 of the pixel's key: a set's seed is one mix away
  std::uint64_t sample_ = 0;
  std::uint32_t dimension_ = 0;
};

}  // namespace stratum::pixel
