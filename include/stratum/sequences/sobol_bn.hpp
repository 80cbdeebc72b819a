#pragma once
/// sobol-bn: Owen-scrambled Sobol' per pixel whose Monte Carlo error is blue
/// noise in screen space, after Heitz, Belcour, Ostromoukhov, Coeurjolly and
/// Iehl 2019 ("A low-discrepancy sampler that distributes Monte Carlo errors
/// as a blue noise in screen space") and Belcour & Heitz 2021 ("Lessons
/// learned and improvements when building screen-space samplers with
/// blue-noise error distribution").
///
/// Every pixel takes the same Owen-scrambled (0,2)-sequence of a dimension
/// pair (one scramble per image, seed and pair) and XORs its own scrambling
/// key into the top 16 digits of each coordinate — the papers' "scrambling
/// keys" (Heitz et al. 2019; their ranking keys are not used: every pixel
/// takes its first spp points). The keys come from a small tile of pixels
/// (wrapping over the image, shifted by a seed-dependent offset) whose keys
/// were permuted among the pixels by an optimizer (analysis/blue_noise.hpp)
/// so that, over a set of test integrands, the error of neighbouring pixels
/// cancels: the blurred error is small, i.e. its power lies at high
/// frequencies.
///
/// A fixed XOR key after a random Owen scramble is again a nested uniform
/// scramble, so each point of each pixel stays uniform (unbiased, tested),
/// and a digital shift maps elementary boxes to elementary boxes, so each
/// pixel's first 2^m points stay a (0,m,2)-net in every pair (tested), as
/// with the per-pixel scrambles of `sobol`.
///
/// Dimensions after the tile's (pairs p ≥ dims / 2) are padded as OpenQMC's
/// domains are: each pixel and pair gets its own hashed Owen scramble and no
/// key, i.e. exactly the per-pixel decorrelated Owen-Sobol' of `sobol` (white
/// error there).
#include <array>
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

/// A tile of per-pixel scrambling keys: for pixel (x, y) of a size × size
/// tile, coordinate j < dims, the 16-bit key keys[(y·size + x)·dims + j].
/// The generation parameters travel with it (the file is self-describing).
struct BlueNoiseKeys {
  std::uint32_t size = 0;
  std::uint32_t dims = 0;
  std::uint32_t max_spp = 0;     ///< the optimizer's largest sample count
  std::uint32_t integrands = 0;  ///< test integrands per sample count
  std::uint32_t sweeps = 0;      ///< swap proposals per pixel
  std::uint64_t seed = 0;
  std::vector<std::uint16_t> keys;

  std::uint16_t key(std::uint32_t x, std::uint32_t y, std::uint32_t j) const noexcept {
    return keys[(std::size_t{y} * size + x) * dims + j];
  }
  bool operator==(const BlueNoiseKeys&) const = default;
};

namespace blue_noise_detail {
inline constexpr char magic[8] = {'S', 'T', 'R', 'B', 'N', 'K', '0', '1'};
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

/// The file: "STRBNK01", then size, dims, max_spp, integrands, sweeps
/// (uint32), seed (uint64) and the keys (uint16), all little-endian.
inline std::string serialize_blue_noise_keys(const BlueNoiseKeys& table) {
  using namespace blue_noise_detail;
  std::string out(magic, magic + 8);
  for (std::uint32_t v : {table.size, table.dims, table.max_spp, table.integrands, table.sweeps}) put(out, v, 4);
  put(out, table.seed, 8);
  for (std::uint16_t k : table.keys) put(out, k, 2);
  return out;
}

/// Parses serialize_blue_noise_keys' bytes; `source` names them in errors.
inline BlueNoiseKeys parse_blue_noise_keys(std::string_view bytes, const std::string& source) {
  using namespace blue_noise_detail;
  require(bytes.size() >= header_bytes && std::memcmp(bytes.data(), magic, 8) == 0, "table", source,
          "is not a blue-noise key table (stratum optimize blue-noise writes one)");
  BlueNoiseKeys table;
  table.size = static_cast<std::uint32_t>(get(bytes, 8, 4));
  table.dims = static_cast<std::uint32_t>(get(bytes, 12, 4));
  table.max_spp = static_cast<std::uint32_t>(get(bytes, 16, 4));
  table.integrands = static_cast<std::uint32_t>(get(bytes, 20, 4));
  table.sweeps = static_cast<std::uint32_t>(get(bytes, 24, 4));
  table.seed = get(bytes, 28, 8);
  require(table.size >= 1 && table.size <= 4096 && table.dims >= 2 && table.dims <= 64 && table.dims % 2 == 0,
          "table", source, "has a size outside [1, 4096] or dims not an even number in [2, 64]");
  const std::size_t count = std::size_t{table.size} * table.size * table.dims;
  require(bytes.size() == header_bytes + 2 * count, "table", source,
          "has " + std::to_string(bytes.size()) + " bytes; its header promises " +
              std::to_string(header_bytes + 2 * count));
  table.keys.resize(count);
  for (std::size_t i = 0; i < count; ++i) table.keys[i] = static_cast<std::uint16_t>(get(bytes, header_bytes + 2 * i, 2));
  return table;
}

/// The committed default tile (src/registry/blue_noise_default.cpp, embedded
/// from data/blue-noise/ at build time; docs/blue-noise.md gives the command
/// that regenerates it). Defined in stratum::registry.
const BlueNoiseKeys& default_blue_noise_keys();

class SobolBn {
 public:
  /// Pixels (x, y) of any image take the tile's keys at ((x + ox) mod size,
  /// (y + oy) mod size), (ox, oy) hashed from the seed.
  SobolBn(const BlueNoiseKeys& table, std::uint64_t seed) : table_(&table), seed_(seed), sobol_(&sobol_2d()) {
    const std::uint64_t h = hash64(seed, tag_offset);
    offset_x_ = static_cast<std::uint32_t>((h & 0xffffffffu) % table.size);
    offset_y_ = static_cast<std::uint32_t>((h >> 32) % table.size);
  }

  std::uint32_t table_pairs() const noexcept { return table_->dims / 2; }
  const BlueNoiseKeys& table() const noexcept { return *table_; }

  /// What the draws of one pixel in one dimension pair need: the two Owen
  /// scrambles and the two keys (placed on the top 16 digits).
  struct PixelPair {
    HashOwenScrambler::Dimension x{0}, y{0};
    std::uint64_t key_x = 0, key_y = 0;
  };
  /// A table pair's image-wide scrambles (derived from (seed, pair)).
  PixelPair shared_pair(std::uint32_t p) const noexcept {
    return {HashOwenScrambler::Dimension(hash64(seed_, tag_scramble, p, 0)),
            HashOwenScrambler::Dimension(hash64(seed_, tag_scramble, p, 1))};
  }
  /// Pair p of pixel (x, y) from the pair's shared scrambles (shared_pair(p)).
  PixelPair pixel_pair(std::uint32_t x, std::uint32_t y, std::uint32_t p, const PixelPair& shared) const noexcept {
    if (p >= table_pairs()) {  // padding: a per-pixel Owen scramble, no key
      const std::uint64_t h = hash64(seed_, tag_padding, x, y, p);
      return {HashOwenScrambler::Dimension(hash64(h, 0)), HashOwenScrambler::Dimension(hash64(h, 1))};
    }
    const std::uint32_t tx = static_cast<std::uint32_t>((std::uint64_t{x} + offset_x_) % table_->size);
    const std::uint32_t ty = static_cast<std::uint32_t>((std::uint64_t{y} + offset_y_) % table_->size);
    PixelPair out = shared;
    out.key_x = std::uint64_t{table_->key(tx, ty, 2 * p)} << 48;
    out.key_y = std::uint64_t{table_->key(tx, ty, 2 * p + 1)} << 48;
    return out;
  }
  PixelPair pixel_pair(std::uint32_t x, std::uint32_t y, std::uint32_t p) const noexcept {
    return pixel_pair(x, y, p, shared_pair(p));
  }

  /// Point `index` of a pixel's pair: Sobol' dimensions 0 and 1, scrambled, keyed.
  std::array<double, 2> point(std::uint64_t index, const PixelPair& pair) const noexcept {
    return {bits_to_double(reverse_bits64(pair.x.scramble_reversed(sobol_->reversed_bits(index, 0))) ^ pair.key_x),
            bits_to_double(reverse_bits64(pair.y.scramble_reversed(sobol_->reversed_bits(index, 1))) ^ pair.key_y)};
  }
  /// Coordinates (2p, 2p + 1) of sample `index` of pixel (x, y).
  std::array<double, 2> sample_2d(std::uint32_t x, std::uint32_t y, std::uint64_t index, std::uint32_t p) const noexcept {
    return point(index, pixel_pair(x, y, p));
  }

 private:
  static constexpr std::uint64_t tag_offset = 0x626e'6f66'6673ULL;    // "bnoffs"
  static constexpr std::uint64_t tag_scramble = 0x626e'7363'72ULL;    // "bnscr"
  static constexpr std::uint64_t tag_padding = 0x626e'7061'64ULL;     // "bnpad"
  static const Sobol& sobol_2d() {
    static const Sobol sobol(2);
    return sobol;
  }

  const BlueNoiseKeys* table_;
  std::uint64_t seed_;
  const Sobol* sobol_;
  std::uint32_t offset_x_ = 0, offset_y_ = 0;
};

}  // namespace stratum
