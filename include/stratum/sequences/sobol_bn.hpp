#pragma once
/// sobol-bn: Owen-scrambled Sobol' per pixel whose Monte Carlo error is blue
/// noise in screen space, after Heitz, Belcour, Ostromoukhov, Coeurjolly and
/// Iehl 2019 ("A low-discrepancy sampler that distributes Monte Carlo errors
/// as a blue noise in screen space") and Belcour & Heitz 2021 ("Lessons
/// learned and improvements when building screen-space samplers with
/// blue-noise error distribution").
///
/// Of the papers' two per-pixel keys — scrambling keys (an XOR on the
/// samples) and ranking keys (which part of the sequence a pixel takes) —
/// sobol-bn uses the ranking: one Owen-scrambled (0,2)-sequence per dimension
/// pair is shared by the image, and pixel (x, y) takes the spp points of
/// index (block · spp + i), its block being its rank in a small optimized
/// tile (a permutation of the tile's S² pixels, wrapping over the image and
/// shifted by a seed-dependent offset; each tile of the image takes the next
/// S² blocks, tile t's points being those of tile 0 under another digital
/// shift, i.e. another scramble). The ranks were arranged by an optimizer
/// (analysis/blue_noise.hpp) so that, over test integrands and random
/// scrambles, the error of neighbouring pixels cancels: their blurred error
/// is small, i.e. its power lies at high frequencies. (XOR keys optimized the
/// same way made 1-spp error blue but did not carry over to integrands and
/// scrambles outside the training set at 4 spp and more; the ranks do,
/// because what they exploit — neighbours whose blocks together stratify —
/// holds under every scramble, as in Ahmed & Wonka's ZSobol.)
///
/// Each pixel's points are an aligned block of 2^m points of an
/// Owen-scrambled (0,2)-sequence when spp = 2^m: a (0,m,2)-net in every pair
/// (tested), and every point is uniform (unbiased, tested).
///
/// Dimensions after the tile's (pairs p ≥ dims / 2) are padded as OpenQMC's
/// domains are: each pixel and pair gets its own hashed Owen scramble and
/// takes points 0..spp−1, i.e. exactly the per-pixel decorrelated
/// Owen-Sobol' of `sobol` (white error there).
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "stratum/randomizers/base2.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/bits.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

/// A tile of per-pixel ranks: for pixel (x, y) of a size × size tile
/// (size a power of 2) and dimension pair p < dims / 2, the block
/// ranks[(y·size + x)·(dims / 2) + p] < size², each pair's ranks a
/// permutation. The generation parameters travel with it.
struct BlueNoiseTable {
  std::uint32_t size = 0;
  std::uint32_t dims = 0;        ///< coordinates covered: dims / 2 pairs
  std::uint32_t max_spp = 0;     ///< the optimizer's largest sample count
  std::uint32_t integrands = 0;  ///< test integrands per sample count
  std::uint32_t sweeps = 0;      ///< swap proposals per pixel
  std::uint64_t seed = 0;
  std::vector<std::uint16_t> ranks;

  std::uint32_t pairs() const noexcept { return dims / 2; }
  std::uint16_t rank(std::uint32_t x, std::uint32_t y, std::uint32_t pair) const noexcept {
    return ranks[(std::size_t{y} * size + x) * pairs() + pair];
  }
  bool operator==(const BlueNoiseTable&) const = default;
};

namespace blue_noise_detail {
inline constexpr char magic[8] = {'S', 'T', 'R', 'B', 'N', 'R', '0', '1'};
inline constexpr std::size_t header_bytes = 8 + 5 * 4 + 8;
inline void put(std::string& out, std::uint64_t v, int bytes) {
  for (int b = 0; b < bytes; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xffu));
}
inline std::uint64_t get(std::string_view in, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int b = 0; b < bytes; ++b) v |= std::uint64_t{static_cast<unsigned char>(in[at + b])} << (8 * b);
  return v;
}
}  // namespace blue_noise_detail

/// The file: "STRBNR01", then size, dims, max_spp, integrands, sweeps
/// (uint32), seed (uint64) and the ranks (uint16), all little-endian.
inline std::string serialize_blue_noise_table(const BlueNoiseTable& table) {
  using namespace blue_noise_detail;
  std::string out(magic, magic + 8);
  for (std::uint32_t v : {table.size, table.dims, table.max_spp, table.integrands, table.sweeps}) put(out, v, 4);
  put(out, table.seed, 8);
  for (std::uint16_t r : table.ranks) put(out, r, 2);
  return out;
}

/// Parses serialize_blue_noise_table' bytes; `source` names them in errors.
inline BlueNoiseTable parse_blue_noise_table(std::string_view bytes, const std::string& source) {
  using namespace blue_noise_detail;
  require(bytes.size() >= header_bytes && std::memcmp(bytes.data(), magic, 8) == 0, "table", source,
          "is not a blue-noise rank table (stratum optimize blue-noise writes one)");
  BlueNoiseTable table;
  table.size = static_cast<std::uint32_t>(get(bytes, 8, 4));
  table.dims = static_cast<std::uint32_t>(get(bytes, 12, 4));
  table.max_spp = static_cast<std::uint32_t>(get(bytes, 16, 4));
  table.integrands = static_cast<std::uint32_t>(get(bytes, 20, 4));
  table.sweeps = static_cast<std::uint32_t>(get(bytes, 24, 4));
  table.seed = get(bytes, 28, 8);
  require(table.size >= 16 && table.size <= 256 && std::has_single_bit(table.size) && table.dims >= 2 &&
              table.dims <= 64 && table.dims % 2 == 0,
          "table", source, "has a size not a power of 2 in [16, 256] or dims not an even number in [2, 64]");
  const std::size_t pixels = std::size_t{table.size} * table.size, count = pixels * table.pairs();
  require(bytes.size() == header_bytes + 2 * count, "table", source,
          "has " + std::to_string(bytes.size()) + " bytes; its header promises " +
              std::to_string(header_bytes + 2 * count));
  table.ranks.resize(count);
  for (std::size_t i = 0; i < count; ++i)
    table.ranks[i] = static_cast<std::uint16_t>(get(bytes, header_bytes + 2 * i, 2));
  for (std::uint32_t p = 0; p < table.pairs(); ++p) {  // each pair's ranks: a permutation of the pixels
    std::vector<bool> seen(pixels, false);
    for (std::size_t i = 0; i < pixels; ++i) {
      const std::uint16_t r = table.ranks[i * table.pairs() + p];
      require(r < pixels && !seen[r], "table", source, "has ranks that are not a permutation of the tile's pixels");
      seen[r] = true;
    }
  }
  return table;
}

/// The committed default tile (src/registry/blue_noise_default.cpp, embedded
/// from data/blue-noise/ at build time; docs/blue-noise.md gives the command
/// that regenerates it). Defined in stratum::registry.
const BlueNoiseTable& default_blue_noise_table();

class SobolBn {
 public:
  /// The largest spp (the sequence index holds 24 bits of tile, 16 of rank
  /// and the sample's, and an array's, bits).
  static constexpr std::uint64_t max_samples_per_pixel = std::uint64_t{1} << 24;

  /// Pixels (x, y) of any image, spp samples each, take the tile's ranks at
  /// ((x + ox) mod size, (y + oy) mod size), (ox, oy) hashed from the seed.
  SobolBn(const BlueNoiseTable& table, std::uint64_t samples_per_pixel, std::uint64_t seed)
      : table_(&table), seed_(seed), spp_(samples_per_pixel), sobol_(&sobol_2d()) {
    require(samples_per_pixel >= 1 && samples_per_pixel <= max_samples_per_pixel, "n", samples_per_pixel,
            "sobol-bn takes 1 to 2^24 samples per pixel");
    const std::uint64_t h = hash64(seed, tag_offset);
    offset_x_ = static_cast<std::uint32_t>((h & 0xffffffffu) % table.size);
    offset_y_ = static_cast<std::uint32_t>((h >> 32) % table.size);
    log2_size_ = static_cast<unsigned>(std::countr_zero(table.size));
  }

  std::uint32_t table_pairs() const noexcept { return table_->pairs(); }
  const BlueNoiseTable& table() const noexcept { return *table_; }
  std::uint64_t samples_per_pixel() const noexcept { return spp_; }

  /// What the draws of one pixel in one dimension pair need: the two Owen
  /// scrambles and the pixel's first sequence index (block · spp).
  struct PixelPair {
    HashOwenScrambler::Dimension x{0}, y{0};
    std::uint64_t first = 0;
  };
  /// A table pair's image-wide scrambles (derived from (seed, pair)).
  PixelPair shared_pair(std::uint32_t p) const noexcept {
    return {HashOwenScrambler::Dimension(hash64(seed_, tag_scramble, p, 0)),
            HashOwenScrambler::Dimension(hash64(seed_, tag_scramble, p, 1))};
  }
  /// Pair p of pixel (x, y) from the pair's shared scrambles (shared_pair(p)).
  PixelPair pixel_pair(std::uint32_t x, std::uint32_t y, std::uint32_t p, const PixelPair& shared) const noexcept {
    if (p >= table_pairs()) {  // padding: a per-pixel Owen scramble, points 0..spp−1
      const std::uint64_t h = hash64(seed_, tag_padding, x, y, p);
      return {HashOwenScrambler::Dimension(hash64(h, 0)), HashOwenScrambler::Dimension(hash64(h, 1))};
    }
    const std::uint64_t sx = std::uint64_t{x} + offset_x_, sy = std::uint64_t{y} + offset_y_;
    const std::uint64_t mask = table_->size - 1;
    // The tile's place (12 bits per axis, wrapping), Morton-interleaved, above the rank.
    const std::uint64_t tile = interleave((sx >> log2_size_) & 0xfffu) | interleave((sy >> log2_size_) & 0xfffu) << 1;
    const std::uint64_t block =
        tile << (2 * log2_size_) | table_->rank(std::uint32_t(sx & mask), std::uint32_t(sy & mask), p);
    PixelPair out = shared;
    out.first = block * spp_;
    return out;
  }
  PixelPair pixel_pair(std::uint32_t x, std::uint32_t y, std::uint32_t p) const noexcept {
    return pixel_pair(x, y, p, shared_pair(p));
  }

  /// Point `sequence` of a pair: Sobol' dimensions 0 and 1, scrambled.
  std::array<double, 2> point_at(std::uint64_t sequence, const PixelPair& pair) const noexcept {
    return {bits_to_double(reverse_bits64(pair.x.scramble_reversed(sobol_->reversed_bits(sequence, 0)))),
            bits_to_double(reverse_bits64(pair.y.scramble_reversed(sobol_->reversed_bits(sequence, 1))))};
  }
  /// Sample `index` < spp of a pixel's pair.
  std::array<double, 2> point(std::uint64_t index, const PixelPair& pair) const noexcept {
    return point_at(pair.first + index, pair);
  }
  /// Point j of an array of n points belonging to sample `index` (the n
  /// shadow rays of an eye ray): the pixel's arrays together are its block
  /// of spp · n points, so they stratify across its samples.
  std::array<double, 2> array_point(std::uint64_t index, std::uint64_t n, std::uint64_t j,
                                    const PixelPair& pair) const noexcept {
    return point_at((pair.first + index) * n + j, pair);
  }
  /// Coordinates (2p, 2p + 1) of sample `index` of pixel (x, y).
  std::array<double, 2> sample_2d(std::uint32_t x, std::uint32_t y, std::uint64_t index,
                                  std::uint32_t p) const noexcept {
    return point(index, pixel_pair(x, y, p));
  }

 private:
  static constexpr std::uint64_t tag_offset = 0x626e'6f66'6673ULL;  // "bnoffs"
  static constexpr std::uint64_t tag_scramble = 0x626e'7363'72ULL;  // "bnscr"
  static constexpr std::uint64_t tag_padding = 0x626e'7061'64ULL;   // "bnpad"
  static const Sobol& sobol_2d() {
    static const Sobol sobol(2);
    return sobol;
  }
  /// The bits of v (< 2^16) at even positions.
  static constexpr std::uint64_t interleave(std::uint64_t v) noexcept {
    v = (v | (v << 8)) & 0x00ff00ffULL;
    v = (v | (v << 4)) & 0x0f0f0f0fULL;
    v = (v | (v << 2)) & 0x33333333ULL;
    v = (v | (v << 1)) & 0x55555555ULL;
    return v;
  }

  const BlueNoiseTable* table_;
  std::uint64_t seed_;
  std::uint64_t spp_;
  const Sobol* sobol_;
  std::uint32_t offset_x_ = 0, offset_y_ = 0;
  unsigned log2_size_ = 0;
};

}  // namespace stratum
