#pragma once
/// Ranked blue-noise pixel samplers — sobol-bn, pmj02-bn, lattice-bn — whose
/// Monte Carlo error is blue noise in screen space, after Heitz, Belcour,
/// Ostromoukhov, Coeurjolly and Iehl 2019 ("A low-discrepancy sampler that
/// distributes Monte Carlo errors as a blue noise in screen space") and
/// Belcour & Heitz 2021 ("Lessons learned and improvements when building
/// screen-space samplers with blue-noise error distribution"), on three
/// bases as OpenQMC offers them (SobolBn, PmjBn, LatticeBn).
///
/// Of the papers' two per-pixel keys — scrambling keys (an XOR on the
/// samples) and ranking keys (which part of the sequence a pixel takes) —
/// these use the ranking: one randomized 2D base sequence per dimension pair
/// is shared by the image, and pixel (x, y) takes the spp points of index
/// (block · spp + i), its block being its rank in a small optimized tile (a
/// permutation of the tile's S² pixels, wrapping over the image and shifted
/// by a seed-dependent offset; each tile of the image takes the next S²
/// blocks). The ranks were arranged by an optimizer (analysis/blue_noise.hpp)
/// so that, over test integrands and random randomizations of the base, the
/// error of neighbouring pixels cancels: their blurred error is small, i.e.
/// its power lies at high frequencies. (XOR keys optimized the same way made
/// 1-spp error blue but did not carry over to integrands and scrambles
/// outside the training set at 4 spp and more; the ranks do, because what
/// they exploit — neighbours whose blocks together stratify — holds under
/// every randomization, as in Ahmed & Wonka's ZSobol.)
///
/// The bases, each a randomized sequence whose aligned blocks of 2^m points
/// are as well stratified as its first 2^m:
/// - sobol: Sobol' dimensions 0 and 1 under a hash-based Owen scramble per
///   coordinate. A pixel's block is a (0,m,2)-net in every pair (tested).
/// - pmj02: the digital (0,2)-sequence behind PMJ02 (generator matrices of
///   Stirling numbers mod 2, Helmer et al. 2021; sequences/pmj.hpp) under the
///   same hash-based Owen scramble: pmj02's kind of point sets (its stochastic
///   construction is an Owen scrambling of this sequence) at the cost of one
///   XOR per index bit instead of a hash per link of pmj02's chain. Again a
///   (0,m,2)-net per pixel and pair (tested).
/// - lattice: the extensible rank-1 lattice sequence frac(φ_2(k) g) of
///   sequences/lattice_sequence.hpp, pair p on components (2p, 2p + 1) of
///   its default generating vector, under a random shift (Cranley–Patterson
///   rotation) per coordinate. Since φ_2(b·2^m + i) = φ_2(i) + 2^-m φ_2(b),
///   a pixel's block is the 2^m-point lattice shifted: every pair of a pixel
///   together is one randomly shifted rank-1 lattice in all its dimensions,
///   Latin in each (tested). 16 pairs (32 dimensions) have their own
///   components; padding pairs past them reuse them at a per-pixel XOR ≥ 2
///   of the sample index, so no two pairs of one pixel have a constant
///   difference (at spp ≥ 4; two points in [0,1) always differ by a shift).
/// Every point is uniform, so each pixel's estimate is unbiased (tested).
///
/// Frames (LECTURE.md §8, "nearby in space, far in time"): a pixel's sample
/// n ≥ spp, of frame K = n / spp, is sample n mod spp of block (block XOR K).
/// The XOR maps every aligned group of 2^k ranks onto one, so each frame
/// keeps the tile's structure (the blocks of neighbours still stratify
/// together: blue error in space, and for the digital bases the same
/// distribution as frame 0, since XOR on the index is a digital shift that
/// Owen scrambling absorbs), and a pixel's frames 0..2^k − 1 are the 2^k
/// blocks of its aligned group: together a (0, m + k, 2)-net (a 2^k·spp-point
/// lattice), so averaged frames converge as one frame at 2^k·spp and
/// consecutive frames' errors cancel (blue in time).
///
/// Dimensions after the tile's (pairs p ≥ dims / 2) are padded as OpenQMC's
/// domains are: each pixel and pair gets its own hashed randomization and
/// takes points 0..spp−1, i.e. a per-pixel decorrelated randomized base
/// (white error there).
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "stratum/randomizers/base2.hpp"
#include "stratum/sequences/lattice_sequence.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/bits.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum {

/// The 2D base sequence a rank tile was optimized for.
enum class BlueNoiseBase : std::uint32_t { sobol = 0, pmj02 = 1, lattice = 2 };

inline const char* blue_noise_base_name(BlueNoiseBase base) noexcept {
  switch (base) {
    case BlueNoiseBase::pmj02:
      return "pmj02";
    case BlueNoiseBase::lattice:
      return "lattice";
    default:
      return "sobol";
  }
}

/// The base named `name` ("sobol", "pmj02", "lattice"); errors name `argument`.
inline BlueNoiseBase blue_noise_base_from(std::string_view name, const std::string& argument) {
  for (BlueNoiseBase base : {BlueNoiseBase::sobol, BlueNoiseBase::pmj02, BlueNoiseBase::lattice})
    if (name == blue_noise_base_name(base)) return base;
  throw invalid_argument(argument, std::string(name), "allowed: sobol, pmj02, lattice");
}

/// How the optimizer arranged a tile's ranks: Morton-structured (every aligned
/// 2^l × 2^l block of pixels holds 4^l consecutive ranks, as in ZSobol, only
/// the four ranks of each 2 × 2 block swapped) or free (any two pixels swapped).
enum class BlueNoiseStructure : std::uint32_t { free = 0, morton = 1 };

inline const char* blue_noise_structure_name(BlueNoiseStructure structure) noexcept {
  return structure == BlueNoiseStructure::morton ? "morton" : "free";
}

inline BlueNoiseStructure blue_noise_structure_from(std::string_view name, const std::string& argument) {
  if (name == "morton") return BlueNoiseStructure::morton;
  if (name == "free") return BlueNoiseStructure::free;
  throw invalid_argument(argument, std::string(name), "allowed: morton, free");
}

/// Coordinates a base's tile may cover: the lattice's 16 pairs of generator
/// components, 32 pairs otherwise.
inline std::uint32_t blue_noise_max_dims(BlueNoiseBase base) noexcept {
  return base == BlueNoiseBase::lattice ? std::uint32_t(LatticeSequence::default_generator.size()) : 64;
}

/// Point `sequence` of the randomized 2D base sequence of dimension pair
/// `pair`, as 64-bit binary fractions, under the randomization keys (kx, ky):
/// Owen-scramble keys (sobol), digit keys (pmj02) or shifts (lattice).
class RankedBase {
 public:
  explicit RankedBase(BlueNoiseBase base) : base_(base), sobol_(&Sobol::first_two()), pmj02_(&pmj02_tables()) {}
  BlueNoiseBase base() const noexcept { return base_; }

  std::array<std::uint64_t, 2> bits(std::uint32_t pair, std::uint64_t sequence, std::uint64_t kx,
                                    std::uint64_t ky) const noexcept {
    switch (base_) {
      case BlueNoiseBase::pmj02:
        return {reverse_bits64(HashOwenScrambler::Dimension(kx).scramble_reversed(pmj02_reversed(sequence, 0))),
                reverse_bits64(HashOwenScrambler::Dimension(ky).scramble_reversed(pmj02_reversed(sequence, 1)))};
      case BlueNoiseBase::lattice: {
        const auto& g = LatticeSequence::default_generator;
        const std::uint32_t c = (2 * pair) % std::uint32_t(g.size());
        const std::uint64_t phi = reverse_bits64(sequence);  // φ_2(sequence) · 2^64; products wrap mod 1
        return {phi * g[c] + kx, phi * g[c + 1] + ky};
      }
      default:
        return {reverse_bits64(HashOwenScrambler::Dimension(kx).scramble_reversed(sobol_->reversed_bits(sequence, 0))),
                reverse_bits64(HashOwenScrambler::Dimension(ky).scramble_reversed(sobol_->reversed_bits(sequence, 1)))};
    }
  }

 private:
  /// Per coordinate, the XORs of the generator columns 0–7 and 8–15 of every
  /// byte value (as Sobol's tables): a 16-bit index is two look-ups.
  struct Pmj02Tables {
    std::array<std::array<std::uint64_t, 512>, 2> low{};
    Pmj02Tables() {
      for (unsigned c = 0; c < 2; ++c)
        for (unsigned byte = 0; byte < 2; ++byte)
          for (unsigned value = 1; value < 256; ++value)
            low[c][256 * byte + value] =
                low[c][256 * byte + (value & (value - 1))] ^
                Pmj02::generator_column(c, 8 * byte + static_cast<unsigned>(std::countr_zero(value)));
    }
  };
  static const Pmj02Tables& pmj02_tables() {
    static const Pmj02Tables tables;
    return tables;
  }
  /// The unscrambled digital PMJ02 point's coordinate, digits reversed (first
  /// digit in bit 0): the XOR of the generator columns of the index's bits.
  std::uint64_t pmj02_reversed(std::uint64_t index, unsigned coordinate) const noexcept {
    const std::array<std::uint64_t, 512>& low = pmj02_->low[coordinate];
    std::uint64_t word = low[index & 0xff] ^ low[256 + ((index >> 8) & 0xff)];
    for (std::uint64_t rest = index >> 16 << 16; rest != 0; rest &= rest - 1)
      word ^= Pmj02::generator_column(coordinate, static_cast<unsigned>(std::countr_zero(rest)));
    return word;
  }
  BlueNoiseBase base_;
  const Sobol* sobol_;
  const Pmj02Tables* pmj02_;
};

/// A tile of per-pixel ranks: for pixel (x, y) of a size × size tile
/// (size a power of 2) and dimension pair p < dims / 2, the block
/// ranks[(y·size + x)·(dims / 2) + p] < size², each pair's ranks a
/// permutation. The generation parameters travel with it.
struct BlueNoiseTable {
  BlueNoiseBase base = BlueNoiseBase::sobol;
  BlueNoiseStructure structure = BlueNoiseStructure::free;
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
inline constexpr char magic_v1[8] = {'S', 'T', 'R', 'B', 'N', 'R', '0', '1'};
inline constexpr char magic[8] = {'S', 'T', 'R', 'B', 'N', 'R', '0', '2'};
inline constexpr std::size_t fields_bytes = 5 * 4 + 8;  // size … seed
inline void put(std::string& out, std::uint64_t v, int bytes) {
  for (int b = 0; b < bytes; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xffu));
}
inline std::uint64_t get(std::string_view in, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int b = 0; b < bytes; ++b) v |= std::uint64_t{static_cast<unsigned char>(in[at + b])} << (8 * b);
  return v;
}
}  // namespace blue_noise_detail

/// The file: "STRBNR02", then base (uint32: 0 sobol, 1 pmj02, 2 lattice),
/// structure (uint32: 0 free, 1 morton), size, dims, max_spp, integrands,
/// sweeps (uint32), seed (uint64) and the ranks (uint16), all little-endian.
/// ("STRBNR01" files, without base and structure, are free sobol tiles and
/// are still read.)
inline std::string serialize_blue_noise_table(const BlueNoiseTable& table) {
  using namespace blue_noise_detail;
  std::string out(magic, magic + 8);
  put(out, static_cast<std::uint32_t>(table.base), 4);
  put(out, static_cast<std::uint32_t>(table.structure), 4);
  for (std::uint32_t v : {table.size, table.dims, table.max_spp, table.integrands, table.sweeps}) put(out, v, 4);
  put(out, table.seed, 8);
  for (std::uint16_t r : table.ranks) put(out, r, 2);
  return out;
}

/// Parses serialize_blue_noise_table' bytes; `source` names them in errors.
inline BlueNoiseTable parse_blue_noise_table(std::string_view bytes, const std::string& source) {
  using namespace blue_noise_detail;
  const bool v1 = bytes.size() >= 8 && std::memcmp(bytes.data(), magic_v1, 8) == 0;
  const bool v2 = bytes.size() >= 16 && std::memcmp(bytes.data(), magic, 8) == 0;
  const std::size_t header_bytes = 8 + (v2 ? 8 : 0) + fields_bytes;
  require((v1 || v2) && bytes.size() >= header_bytes, "table", source,
          "is not a blue-noise rank table (stratum optimize blue-noise writes one)");
  BlueNoiseTable table;
  std::size_t at = 8;
  if (v2) {
    const std::uint64_t base = get(bytes, at, 4);
    require(base <= 2, "table", source, "has base " + std::to_string(base) + " (allowed: 0 sobol, 1 pmj02, 2 lattice)");
    table.base = static_cast<BlueNoiseBase>(base);
    const std::uint64_t structure = get(bytes, at + 4, 4);
    require(structure <= 1, "table", source,
            "has structure " + std::to_string(structure) + " (allowed: 0 free, 1 morton)");
    table.structure = static_cast<BlueNoiseStructure>(structure);
    at += 8;
  }
  table.size = static_cast<std::uint32_t>(get(bytes, at, 4));
  table.dims = static_cast<std::uint32_t>(get(bytes, at + 4, 4));
  table.max_spp = static_cast<std::uint32_t>(get(bytes, at + 8, 4));
  table.integrands = static_cast<std::uint32_t>(get(bytes, at + 12, 4));
  table.sweeps = static_cast<std::uint32_t>(get(bytes, at + 16, 4));
  table.seed = get(bytes, at + 20, 8);
  const std::uint32_t max_dims = blue_noise_max_dims(table.base);
  require(table.size >= 16 && table.size <= 256 && std::has_single_bit(table.size) && table.dims >= 2 &&
              table.dims <= max_dims && table.dims % 2 == 0,
          "table", source,
          "has a size not a power of 2 in [16, 256] or dims not an even number in [2, " + std::to_string(max_dims) +
              "] (its base: " + blue_noise_base_name(table.base) + ")");
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

/// The committed default tile of a base (src/registry/blue_noise_default.cpp,
/// embedded from data/blue-noise/ at build time; docs/blue-noise.md gives the
/// commands that regenerate them).
const BlueNoiseTable& default_blue_noise_table(BlueNoiseBase base = BlueNoiseBase::sobol);

class RankedBlueNoise {
 public:
  /// The largest spp (the sequence index holds 24 bits of tile, 16 of rank
  /// and the sample's, and an array's, bits).
  static constexpr std::uint64_t max_samples_per_pixel = std::uint64_t{1} << 24;

  /// Pixels (x, y) of any image, spp samples each, take the tile's ranks at
  /// ((x + ox) mod size, (y + oy) mod size), (ox, oy) hashed from the seed;
  /// the points are those of the tile's base.
  RankedBlueNoise(const BlueNoiseTable& table, std::uint64_t samples_per_pixel, std::uint64_t seed)
      : table_(&table), seed_(seed), spp_(samples_per_pixel), base_(table.base) {
    require(samples_per_pixel >= 1 && samples_per_pixel <= max_samples_per_pixel, "n", samples_per_pixel,
            std::string(blue_noise_base_name(table.base)) + "-bn takes 1 to 2^24 samples per pixel");
    const std::uint64_t h = hash64(seed, tag_offset);
    offset_x_ = static_cast<std::uint32_t>((h & 0xffffffffu) % table.size);
    offset_y_ = static_cast<std::uint32_t>((h >> 32) % table.size);
    log2_size_ = static_cast<unsigned>(std::countr_zero(table.size));
  }

  std::uint32_t table_pairs() const noexcept { return table_->pairs(); }
  const BlueNoiseTable& table() const noexcept { return *table_; }
  BlueNoiseBase base() const noexcept { return base_.base(); }
  std::uint64_t samples_per_pixel() const noexcept { return spp_; }

  /// What the draws of one pixel in one dimension pair need: the pair, its
  /// two randomization keys, the pixel's first sequence index (block · spp)
  /// and the XOR on the sample index (lattice padding past its generator).
  struct PixelPair {
    std::uint64_t kx = 0, ky = 0;
    std::uint64_t first = 0;  ///< block · spp
    std::uint64_t index_xor = 0;
    std::uint32_t pair = 0;
    std::uint64_t block = 0;
  };
  /// A table pair's image-wide keys (derived from (seed, pair)).
  PixelPair shared_pair(std::uint32_t p) const noexcept {
    return {hash64(seed_, tag_scramble, p, 0), hash64(seed_, tag_scramble, p, 1), 0, 0, p};
  }
  /// Pair p of pixel (x, y) from the pair's shared keys (shared_pair(p)).
  PixelPair pixel_pair(std::uint32_t x, std::uint32_t y, std::uint32_t p, const PixelPair& shared) const noexcept {
    if (p >= table_pairs()) {  // padding: a per-pixel randomization, points 0..spp−1
      const std::uint64_t h = hash64(seed_, tag_padding, x, y, p);
      // Lattice pairs past the generator's components: an XOR of at least 2 (XOR 1
      // flips φ_2's first digit, a shift by 1/2), so the samples meet the lattice
      // points of the pair that first used the components in another pairing.
      const bool reused = base() == BlueNoiseBase::lattice && 2 * p >= LatticeSequence::default_generator.size();
      const std::uint64_t span = std::bit_ceil(spp_);
      return {hash64(h, 0), hash64(h, 1), 0, reused && span > 2 ? 2 + hash64(h, 2) % (span - 2) : 0, p};
    }
    const std::uint64_t sx = std::uint64_t{x} + offset_x_, sy = std::uint64_t{y} + offset_y_;
    const std::uint64_t mask = table_->size - 1;
    // The tile's place (12 bits per axis, wrapping), Morton-interleaved, above the rank.
    const std::uint64_t tile = interleave((sx >> log2_size_) & 0xfffu) | interleave((sy >> log2_size_) & 0xfffu) << 1;
    const std::uint64_t block =
        tile << (2 * log2_size_) | table_->rank(std::uint32_t(sx & mask), std::uint32_t(sy & mask), p);
    PixelPair out = shared;
    out.block = block;
    out.first = block * spp_;
    // Each pixel and pair reads its block in its own order (an XOR of the sample
    // index, which keeps every 2^k prefix an aligned sub-block): otherwise sample
    // i would take the same place in its block in every pair of every pixel, a
    // pairing shared by the whole image whose error does not cancel between
    // neighbours (measured: white error at 16 spp and blotches at 32). The
    // lattice keeps its order: its pairs are one rank-1 lattice jointly.
    if (std::has_single_bit(spp_) && base() != BlueNoiseBase::lattice)
      out.index_xor = hash64(seed_, tag_shuffle, x, y, p) & (spp_ - 1);
    return out;
  }
  PixelPair pixel_pair(std::uint32_t x, std::uint32_t y, std::uint32_t p) const noexcept {
    return pixel_pair(x, y, p, shared_pair(p));
  }

  /// Point `sequence` of a pair's randomized base sequence.
  std::array<double, 2> point_at(std::uint64_t sequence, const PixelPair& pair) const noexcept {
    const std::array<std::uint64_t, 2> b = base_.bits(pair.pair, sequence, pair.kx, pair.ky);
    return {bits_to_double(b[0]), bits_to_double(b[1])};
  }
  /// The sequence index of sample `index` of a pixel's pair (index ≥ spp:
  /// frame index / spp, see above).
  std::uint64_t sequence_index(std::uint64_t index, const PixelPair& pair) const noexcept {
    if (index < spp_) return pair.first + (index ^ pair.index_xor);
    const std::uint64_t frame = index / spp_;
    return (pair.block ^ frame) * spp_ + ((index - frame * spp_) ^ pair.index_xor);
  }
  /// Sample `index` of a pixel's pair.
  std::array<double, 2> point(std::uint64_t index, const PixelPair& pair) const noexcept {
    return point_at(sequence_index(index, pair), pair);
  }
  /// Point j of an array of n points belonging to sample `index` (the n
  /// shadow rays of an eye ray): the pixel's arrays together are its block
  /// of spp · n points, so they stratify across its samples.
  std::array<double, 2> array_point(std::uint64_t index, std::uint64_t n, std::uint64_t j,
                                    const PixelPair& pair) const noexcept {
    return point_at(sequence_index(index, pair) * n + j, pair);
  }
  /// Coordinates (2p, 2p + 1) of sample `index` of pixel (x, y).
  std::array<double, 2> sample_2d(std::uint32_t x, std::uint32_t y, std::uint64_t index,
                                  std::uint32_t p) const noexcept {
    return point(index, pixel_pair(x, y, p));
  }

 private:
  static constexpr std::uint64_t tag_offset = 0x626e'6f66'6673ULL;   // "bnoffs"
  static constexpr std::uint64_t tag_scramble = 0x626e'7363'72ULL;   // "bnscr"
  static constexpr std::uint64_t tag_padding = 0x626e'7061'64ULL;    // "bnpad"
  static constexpr std::uint64_t tag_shuffle = 0x626e'7368'7566ULL;  // "bnshuf"
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
  RankedBase base_;
  std::uint32_t offset_x_ = 0, offset_y_ = 0;
  unsigned log2_size_ = 0;
};

}  // namespace stratum
