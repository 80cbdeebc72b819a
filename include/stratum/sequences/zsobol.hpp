#pragma once
/// ZSobol: a pixel sampler whose Monte Carlo error is blue noise in screen
/// space (Ahmed & Wonka 2020, "Screen-space blue-noise diffusion of Monte
/// Carlo sampling error via hierarchical ordering of pixels"; the sampler
/// pbrt-v4 ships as ZSobolSampler).
///
/// One Owen-scrambled Sobol' (0,2)-sequence is shared by the whole image:
/// pixel (x, y) takes the spp = 2^L consecutive points of index
/// (morton(x, y) · 2^L + i), so four neighbouring pixels (a quad of the
/// Morton curve) together hold an aligned block of 4·spp points, sixteen
/// pixels one of 16·spp, and so on: together they are nets, so their errors
/// partly cancel between neighbours — the error is pushed to high
/// frequencies. The Morton order alone would leave visible structure (the
/// same offsets repeat in every quad), so each base-4 digit of the index is
/// permuted by one of the 24 permutations of {0, 1, 2, 3}, chosen by a hash
/// of the higher digits (the quad it lies in) and the dimension: a random
/// hierarchical ordering of the pixels, independent per dimension.
///
/// Per pixel the points are still an aligned block of 2^L points of the
/// sequence (the permutation maps the digits of the sample index within the
/// pixel's own block), so each pixel keeps Sobol's stratification ((0, L, 2)
/// net per pair of dimensions), and Owen scrambling makes every point
/// uniform: unbiased (tested).
///
/// Dimensions come in pairs, as the renderer's draws do: pair p takes Sobol'
/// dimensions 0 and 1 with their own digit permutations and their own Owen
/// scramble, keyed by (seed, p), as pbrt's padded dimensions are.
///
/// Frames (LECTURE.md §8, "nearby in space, far in time"): a pixel's sample
/// n ≥ spp belongs to frame K = n / spp, which reads the sequence as frame 0
/// does with the Morton code of every pixel XORed with K (its digits beyond
/// the image's levels placed above the index, unpermuted): each frame is a
/// ZSobol image of its own (the XOR maps aligned blocks of pixels onto aligned
/// blocks, so the error stays blue in space), and a pixel's frames 0..2^k − 1
/// together are the aligned block of 2^k·spp points its 2^k nearest pixels
/// of the hierarchy hold in frame 0: a (0, L + k, 2)-net, so averaged frames
/// converge as one frame at 2^k·spp, and consecutive frames' errors cancel
/// (blue in time). The price: averaged over 4^j frames, the 2^j × 2^j pixels
/// of a block share one point set (their averaged error is correlated).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

#include "stratum/randomizers/base2.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

class ZSobol {
 public:
  /// The largest image side (pixels), and spp = 2^L with L ≤ max_log2_spp:
  /// 2·14 + 24 = 52 bits of sequence index, every one a distinct double.
  static constexpr std::uint32_t max_resolution = 16384;
  static constexpr unsigned max_log2_spp = 24;

  /// An image whose larger side is `resolution` pixels, spp samples per
  /// pixel (a power of 2), scrambled by `seed`.
  ZSobol(std::uint32_t resolution, std::uint64_t samples_per_pixel, std::uint64_t seed)
      : seed_(seed), sobol_(&Sobol::first_two()) {
    require(resolution >= 1 && resolution <= max_resolution, "resolution", resolution,
            "must be in [1, 16384] (the image's larger side in pixels)");
    require(samples_per_pixel >= 1 && std::has_single_bit(samples_per_pixel) &&
                samples_per_pixel <= (std::uint64_t{1} << max_log2_spp),
            "n", samples_per_pixel, "zsobol takes a power of 2 samples per pixel, at most 2^24");
    log2_spp_ = static_cast<unsigned>(std::countr_zero(samples_per_pixel));
    pixel_levels_ = static_cast<unsigned>(std::bit_width(resolution - 1u));
    index_bits_ = 2 * pixel_levels_ + log2_spp_;
  }

  std::uint64_t samples_per_pixel() const noexcept { return std::uint64_t{1} << log2_spp_; }
  unsigned index_bits() const noexcept { return index_bits_; }

  /// What a dimension pair's draws share: the key of its digit permutations
  /// and its two Owen scrambles (derived from (seed, pair) alone, so the
  /// renderer derives them once per render).
  struct Pair {
    std::uint64_t key = 0;
    HashOwenScrambler::Dimension x{0}, y{0};
  };
  Pair pair(std::uint32_t p) const noexcept {
    const std::uint64_t key = hash64(seed_, p, 0x7a736f626f6cULL /* "zsobol" */);
    return {key, HashOwenScrambler::Dimension(hash64(key, 0)), HashOwenScrambler::Dimension(hash64(key, 1))};
  }

  /// The sequence index of sample `index` of pixel (x, y) in a dimension
  /// pair: the Morton index with each base-4 digit permuted by a hash of the
  /// digits above it (and of its level and the pair); `index` ≥ spp is
  /// sample index mod spp of frame index / spp (see above). The digits above
  /// the sample index's depend on the pixel and frame alone: pixel_digits,
  /// which a renderer computes once per pixel and pair.
  std::uint64_t sequence_index(std::uint32_t x, std::uint32_t y, std::uint64_t index, const Pair& pair) const noexcept {
    const std::uint64_t frame = index >> log2_spp_, sample = index & (samples_per_pixel() - 1);
    return sample_digits(x, y, pixel_digits(x, y, pair, frame), sample, pair, frame);
  }
  /// The permuted digits of the pixel's part of the index (bits ≥ L) in a frame.
  std::uint64_t pixel_digits(std::uint32_t x, std::uint32_t y, const Pair& pair,
                             std::uint64_t frame = 0) const noexcept {
    return high(frame) | permute_digits(code(x, y, frame) << log2_spp_, pair, int(index_bits_) - 2, int(log2_spp_));
  }
  /// The part of pixel_digits shared by the aligned 2^k × 2^k block of
  /// pixels holding (x, y): its digits above the block's own k levels.
  std::uint64_t block_digits(std::uint32_t x, std::uint32_t y, const Pair& pair, unsigned k,
                             std::uint64_t frame = 0) const noexcept {
    return high(frame) |
           permute_digits(code(x, y, frame) << log2_spp_, pair, int(index_bits_) - 2, int(log2_spp_ + 2 * k));
  }
  /// pixel_digits from the block's digits (block_digits(x, y, pair, k, frame)):
  /// only the k levels inside the block are permuted here.
  std::uint64_t pixel_digits(std::uint32_t x, std::uint32_t y, const Pair& pair, std::uint64_t block, unsigned k,
                             std::uint64_t frame = 0) const noexcept {
    const int top = std::min(int(log2_spp_ + 2 * k), int(index_bits_)) - 2;
    return block | permute_digits(code(x, y, frame) << log2_spp_, pair, top, int(log2_spp_));
  }
  /// pixel_digits(x, y, pair, frame) with the permuted digits of sample `index` < spp below them.
  std::uint64_t sample_digits(std::uint32_t x, std::uint32_t y, std::uint64_t pixel_part, std::uint64_t index,
                              const Pair& pair, std::uint64_t frame = 0) const noexcept {
    const std::uint64_t m = code(x, y, frame) << log2_spp_ | index;
    const unsigned low = index_bits_ & 1u;  // an odd number of bits: the lowest is a base-2 digit
    std::uint64_t out = pixel_part | permute_digits(m, pair, int(log2_spp_) - 2, int(low));
    if (low) out |= (m & 1u) ^ (mix64((m >> 1) ^ pair.key ^ 0x6c6f77ULL) >> 63);
    return out;
  }

  /// sample_digits(x, y, 0, i, pair, frame) for every sample i < spp of a
  /// pixel at once, into out[0 … spp): the digits of one level share a
  /// permutation per value of the digits above them, so the table costs about
  /// spp/3 hashes (5 at 16 spp) instead of one per digit of every sample (32);
  /// a renderer fills it once per pixel and pair.
  void sample_digit_table(std::uint32_t x, std::uint32_t y, const Pair& pair, std::uint64_t frame,
                          std::uint64_t* out) const noexcept {
    const std::uint64_t spp = samples_per_pixel(), pixel = code(x, y, frame) << log2_spp_;
    for (std::uint64_t i = 0; i < spp; ++i) out[i] = 0;
    const unsigned low = index_bits_ & 1u;
    for (int shift = int(log2_spp_) - 2; shift >= int(low); shift -= 2) {
      const std::uint64_t span = std::uint64_t{1} << shift;  // indices sharing one digit value below a prefix
      for (std::uint64_t prefix = 0; prefix < (spp >> (shift + 2)); ++prefix) {
        const std::uint64_t above = (pixel | (prefix << (shift + 2))) >> (shift + 2);
        const auto& permutation = permutation_of(above, pair, shift);
        std::uint64_t* block = out + (prefix << (shift + 2));
        for (std::uint64_t digit = 0; digit < 4; ++digit)
          for (std::uint64_t rest = 0; rest < span; ++rest)
            block[(digit << shift) | rest] |= std::uint64_t{permutation[digit]} << shift;
      }
    }
    if (low)
      for (std::uint64_t i = 0; i < spp; i += 2) {
        const std::uint64_t flip = mix64(((pixel | i) >> 1) ^ pair.key ^ 0x6c6f77ULL) >> 63;
        out[i] |= flip, out[i + 1] |= 1u ^ flip;
      }
  }

  /// Point `sequence` of a pair: Sobol' dimensions 0 and 1 with the pair's Owen scrambles.
  std::array<double, 2> point(std::uint64_t sequence, const Pair& pair) const noexcept {
    return {sobol_->sample(sequence, 0, pair.x), sobol_->sample(sequence, 1, pair.y)};
  }

  /// Coordinates (2p, 2p + 1) of sample `index` of pixel (x, y), p = pair.
  std::array<double, 2> sample_2d(std::uint32_t x, std::uint32_t y, std::uint64_t index,
                                  std::uint32_t p) const noexcept {
    const Pair keys = pair(p);
    return point(sequence_index(x, y, index, keys), keys);
  }

  /// Point j of an array of 2^k points belonging to one sample (the n
  /// shadow rays of an eye ray): index sequence · 2^k + j of the pair's
  /// sequence, so the array is an aligned block (stratified among itself)
  /// and neighbouring pixels' arrays are neighbouring blocks.
  std::array<double, 2> array_point(std::uint64_t sequence, unsigned k, std::uint64_t j,
                                    const Pair& pair) const noexcept {
    return point((sequence << k) | j, pair);
  }

 private:
  static constexpr std::uint64_t morton(std::uint32_t x, std::uint32_t y) noexcept {
    return interleave(x) | (interleave(y) << 1);
  }
  /// A pixel's code in a frame: its Morton index XOR the frame's low digits,
  /// the frame's digits past the image's levels above it.
  std::uint64_t code(std::uint32_t x, std::uint32_t y, std::uint64_t frame) const noexcept {
    const std::uint64_t mask = (std::uint64_t{1} << (2 * pixel_levels_)) - 1;
    return (morton(x, y) ^ (frame & mask)) | (frame & ~mask);
  }
  /// The frame's digits past the image's levels, placed above the index (unpermuted).
  std::uint64_t high(std::uint64_t frame) const noexcept { return (frame >> (2 * pixel_levels_)) << index_bits_; }
  /// The base-4 digits of m at shifts top, top − 2, … ≥ bottom, each
  /// permuted by one of the 24 permutations, picked by a hash of the digits
  /// above it, its level and the pair (Lemire's multiply-shift instead of a
  /// modulo: a division per digit would cost more than the hash).
  static std::uint64_t permute_digits(std::uint64_t m, const Pair& pair, int top, int bottom) noexcept {
    std::uint64_t out = 0;
    for (int shift = top; shift >= bottom; shift -= 2)
      out |= std::uint64_t{permutation_of(m >> (shift + 2), pair, shift)[(m >> shift) & 3u]} << shift;
    return out;
  }
  /// The permutation of the digit at `shift` whose higher digits are `above` (m >> (shift + 2)).
  static const std::array<std::uint8_t, 4>& permutation_of(std::uint64_t above, const Pair& pair, int shift) noexcept {
    const std::uint64_t h = mix64(above ^ pair.key ^ (std::uint64_t(shift) << 58));
    return permutations()[((h >> 32) * 24) >> 32];
  }
  /// The bits of v at even positions (x → x0 0 x1 0 …), for 16-bit v.
  static constexpr std::uint64_t interleave(std::uint64_t v) noexcept {
    v &= 0xffffu;
    v = (v | (v << 8)) & 0x00ff00ffULL;
    v = (v | (v << 4)) & 0x0f0f0f0fULL;
    v = (v | (v << 2)) & 0x33333333ULL;
    v = (v | (v << 1)) & 0x55555555ULL;
    return v;
  }
  /// The 24 permutations of {0, 1, 2, 3} in lexicographic order.
  static const std::array<std::array<std::uint8_t, 4>, 24>& permutations() noexcept {
    static constexpr auto table = [] {
      std::array<std::array<std::uint8_t, 4>, 24> all{};
      std::array<std::uint8_t, 4> p{0, 1, 2, 3};
      for (auto& entry : all) {
        entry = p;
        std::next_permutation(p.begin(), p.end());
      }
      return all;
    }();
    return table;
  }

  std::uint64_t seed_;
  const Sobol* sobol_;
  unsigned log2_spp_ = 0;
  unsigned pixel_levels_ = 0;
  unsigned index_bits_ = 0;
};

}  // namespace stratum
