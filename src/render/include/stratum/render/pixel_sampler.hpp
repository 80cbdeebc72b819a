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
/// get_2d_array(n) returns n points stratified among themselves, so the n
/// shadow rays of one eye ray are (LECTURE.md §2). For a progressive sampler
/// they continue the pixel's sequence of that array dimension (seed
/// hash(seed, pixel, array tag, dimension, continued tag)): sample s takes
/// its points s·n … s·n + n − 1, so the arrays of a pixel's samples (and of
/// its frames) together are the first spp·n points (sobol, pmj02: each array
/// an aligned block, itself a net, and all together one). Without that the
/// arrays of successive samples would be independent and the light
/// integral plain Monte Carlo whatever the sampler. A pattern draws a fresh
/// set per sample (the seed also hashes the sample index).
///
/// Frames (LECTURE.md §8, issue "blue-noise error in screen space and
/// time"): frame K of an animation continues each pixel's sequence. For a
/// progressive sampler (registry property "progressive": every prefix of its
/// randomized sequence is its set, e.g. sobol, halton, pmj02, random) frame K
/// takes the pixel's samples K·spp … (K+1)·spp − 1, so frames 0…K−1 together
/// are exactly the samples of one frame at K·spp (for sobol at K·spp = 2^m a
/// (0,m,2)-net in each dimension pair). The blue-noise pixel samplers
/// (property frames_continue_property: zsobol, sobol-bn, pmj02-bn,
/// lattice-bn) continue it too: frame K is the pixel's registry points from
/// start K·spp, the block of a neighbour in its aligned group, so frames
/// 0…2^k−1 stratify as one set of 2^k·spp while each frame keeps its blue
/// error in space (sequences/zsobol.hpp, ranked_blue_noise.hpp). Any other
/// sampler (a pattern: jittered, n-rooks…) draws frame K from seed
/// hash(seed, K): independent frames. Frame 0 is the render without frames,
/// bit for bit.
///
/// Time (LECTURE.md §8): with a time pattern (random, cook, magic-square),
/// film positions and times come together from the space-time sampler
/// spacetime-<pattern> (spp = m² strata, one time slot each); without one,
/// time is one more dimension of the sampler.
///
/// Direct paths: where the registry gives a sampler's sets under its
/// randomizer as keyed pairs (SamplerInfo::keyed_pairs: random, jittered,
/// pmj02 and sobol:owen-hash today; patterns/keyed_pairs.hpp), a draw computes
/// point `index` of the set from a key of its seed: no registry call, no
/// allocation, no choice by name, bit-identical to the registry's set (tested).
/// The seed hashing a pixel's draws share (pixel key, per-dimension seeds,
/// the array seeds' prefix) is done once per pixel. Where the registry gives
/// a sampler's sets as small per-seed tables (SamplerInfo::pair_tables:
/// halton under its default permute; registry/halton_pair_tables.hpp), the
/// pixel sampler builds per pixel and dimension, and per shadow-ray array,
/// only the digit permutations its points use, without allocation
/// (bit-identical to RandomDigitPermutations; spp and array
/// counts ≤ 2187, above which it builds RandomDigitPermutations). Where the
/// registry gives a SeededGenerator (SamplerInfo::seeded: faure and halton
/// under owen, the lattices, hammersley…, and patterns made as a whole set
/// whose state is their construction: n-rooks, multi-jittered,
/// latin-square), a set's seed is a few words written in place per pixel
/// and dimension and its points are read from them; other samplers with a
/// generator bind one per pixel and dimension, and the other whole-set
/// patterns generate each set once per pixel and dimension through a
/// SetBinder (the request validated once) and cache it.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "stratum/patterns/keyed_pairs.hpp"
#include "stratum/pixel/pixel_sampler.hpp"
#include "stratum/registry.hpp"
#include "stratum/registry/generator_binder.hpp"
#include "stratum/registry/halton_pair_tables.hpp"
#include "stratum/sequences/ranked_blue_noise.hpp"
#include "stratum/sequences/zsobol.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {

struct PixelSamplerSettings {
  std::string sampler = "sobol";
  std::string randomize;  ///< empty: the sampler's default
  std::uint64_t seed = 0;
  std::uint32_t spp = 16;    ///< samples per pixel
  std::string time_pattern;  ///< "", "random", "cook" or "magic-square"
  /// The image's larger side in pixels (render() sets it): zsobol orders the
  /// pixels along a Morton curve of this size. 0: one pixel.
  std::uint32_t resolution = 0;
  std::uint32_t frame = 0;  ///< the animation frame (see above); (frame + 1) · spp ≤ 2^32
  /// The sampler's parameters (its spec's KEY=VALUE items, as text): every
  /// set the sampler draws, pixel sets and shadow-ray arrays, is the
  /// registry's set under them. An image sampler's pixel and resolution are
  /// the renderer's and are refused.
  std::map<std::string, std::string> params{};
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
  // The draws: the direct paths inline (a few per camera ray, where a call
  // and a switch cost as much as the hashing), the others out of line.
  double get_1d() {
    if (keyed_) return keyed_point<1>(dimension_key(dimension_++), spp_root_, sequence_index_)[0];
    if (zsobol_) return zsobol_point(dimension_++)[0];
    if (ranked_bn_) return ranked_bn_point(dimension_++)[0];
    if (tables_direct_) return table_point(1)[0];
    return get_2d_slow(1)[0];
  }
  std::array<double, 2> get_2d() {
    if (keyed_) return keyed_point<2>(dimension_key(dimension_++), spp_root_, sequence_index_);
    if (zsobol_) return zsobol_point(dimension_++);
    if (ranked_bn_) return ranked_bn_point(dimension_++);
    if (tables_direct_) return table_point(2);
    return get_2d_slow();
  }
  /// The film position within the pixel, in [0,1)².
  std::array<double, 2> get_pixel_2d() {
    if (!has_spacetime_) return get_2d();
    return {spacetime_set_(index_, 0), spacetime_set_(index_, 1)};
  }
  /// The shutter fraction in [0,1).
  double get_time() {
    if (!has_spacetime_) return get_1d();
    return spacetime_set_(index_, 2);
  }
  /// n points stratified among themselves (n must be a count the sampler takes).
  void get_2d_array(std::uint32_t n, std::array<double, 2>* out) {
    if (tables_ && arrays_continue_ && continued_table_array(n, out)) return;  // this pixel's set, already built
    // seed = hash64(pixel_key_, tag_array, dimension, tag_continued or sequence_index_)
    const std::uint64_t seed =
        hash64_extend(array_prefix(dimension_++), arrays_continue_ ? tag_continued : sequence_index_);
    const std::uint64_t start = arrays_continue_ ? sequence_index_ * n : 0;  // < 2^64: both factors < 2^32
    if (n != array_n_) array_n_ = n, array_root_ = integer_root(n, 2);
    if (keyed_ && direct_for(n, array_root_)) {  // else the registry names the bad count
      const PairKey key = set_key(seed);
      return std::visit(
          [&](const auto& pairs) {
            for (std::uint32_t i = 0; i < n; ++i) out[i] = pairs.template point<2>(key, array_root_, start + i);
          },
          keyed_->pairs);
    }
    get_2d_array_slow(seed, dimension_ - 1, n, start, out);
  }

  /// The sampler as a spec (docs/samplers.md): NAME(KEY=VALUE,…):RANDOMIZER, as given.
  std::string spec() const;
  /// Point set `dimension` of a pixel, as drawn (for tests): the registry's
  /// points for seed hash(pixel key, dimension).
  PointSet draw_for_test(std::uint64_t n, std::uint64_t seed) const { return draw(settings_.sampler, n, 2, seed); }
  /// The seed of a pixel's set (for tests; plain hash64, independent of the
  /// cached hash chain the draws use): get_2d/get_1d set `dimension` of pixel
  /// (x, y) for the settings' seed, and the get_2d_array set of its sample
  /// `index` (a pattern's) or of every sample (a progressive sampler's: pass
  /// tag_continued as the index).
  static std::uint64_t set_seed_for_test(std::uint64_t seed, std::uint32_t x, std::uint32_t y,
                                         std::uint32_t dimension) noexcept;
  static std::uint64_t array_seed_for_test(std::uint64_t seed, std::uint32_t x, std::uint32_t y,
                                           std::uint32_t dimension, std::uint64_t index) noexcept;
  /// The last link of a progressive sampler's array seeds: above 2^32, so no sample index equals it.
  static constexpr std::uint64_t tag_continued = pixel::tag_continued;
  /// Whether draws take the direct path (see above).
  bool direct() const noexcept { return keyed_.has_value(); }

  std::uint32_t samples_per_pixel() const noexcept { return settings_.spp; }
  const PixelSamplerSettings& settings() const noexcept { return settings_; }

 private:
  const PointSet& set_for(std::uint32_t dimension);
  /// A sampler with a per-point generator (SamplerInfo::bind) off the direct
  /// paths draws through it (set_binder_ is set): per pixel and dimension the
  /// generator bound to the seed set_for would use, read at the sample's index
  /// (the same points: the registry fills its sets from the generator or is tested equal to it).
  std::vector<PointGenerator> generators_;  ///< this pixel's, by dimension (empty: not bound yet)
  const PointGenerator& generator_for(std::uint32_t dimension);
  /// Where the binder's sampler has a SeededGenerator (SamplerInfo::seeded:
  /// base-b owen, …; pixel_seeded_), no generator is bound: per dimension (and per continued
  /// array dimension) the state of the set's seed, written in place when the
  /// pixel changes (a few hashes, no allocation) and read per point.
  struct SeededState {
    std::vector<std::uint64_t> words;
    std::uint64_t stamp = 0;   ///< the pixel it was seeded for (pixel_stamp_)
    unsigned coordinates = 0;  ///< the coordinates seeded
  };
  std::vector<SeededState> seeded_sets_;
  /// The pixel sets' SeededGenerator: set_binder_'s, or set_maker_'s (a
  /// pattern made as a whole set whose state is its construction), or null.
  std::shared_ptr<const SeededGenerator> pixel_seeded_;
  std::vector<std::uint64_t> seeded_scratch_;  ///< a per-sample array's state
  std::vector<double> seeded_points_;          ///< an array's points as SeededGenerator::points writes them
  /// out[i] = point start + i of a seeded state (i < n).
  void seeded_array(const SeededGenerator& generator, const std::uint64_t* state, std::uint64_t start, std::uint32_t n,
                    std::array<double, 2>* out);
  /// seeded_array of this sample's own set of `seed`, its state written into seeded_scratch_.
  void seeded_sample_array(const SeededGenerator& generator, std::uint64_t seed, std::uint64_t start, std::uint32_t n,
                           std::array<double, 2>* out);
  /// The request for `n` points from `start` of the pixel sampler's set with
  /// `seed` (its randomizer, its dimensions).
  SamplerRequest set_request(std::uint64_t seed, std::uint64_t n, std::uint64_t start) const;
  /// The generators' requests, validated once: the pixel sets' (n = spp;
  /// set where the sampler draws through its generator), and the shadow-ray
  /// arrays' for the last array count.
  std::optional<GeneratorBinder> set_binder_, array_binder_;
  /// Samplers without a generator (or a direct path) make each set whole:
  /// their requests validated once (SetBinder), the pixel sets' and the
  /// per-sample arrays' (for the last array count), then generated per seed,
  /// or seeded in place where the SetBinder has a SeededGenerator (n-rooks,
  /// multi-jittered, latin-square: the set's construction as its state).
  std::optional<SetBinder> set_maker_, array_maker_;
  /// A progressive sampler's shadow-ray arrays through its generator: one
  /// seed per pixel and array dimension (tag_continued) for all its samples,
  /// so the generator is bound once per pixel and dimension, not per sample,
  /// for (offset + spp)·n ≤ continued_max_points points (the binder's request
  /// covers them all; beyond, or where its memory check refuses them, a
  /// binding per sample as for a pattern). Never allocates those points.
  struct ContinuedArray {
    PointGenerator generator;
    std::vector<std::uint64_t>
        seeded;               ///< the seed's state instead of the generator, where the binder has a SeededGenerator
    std::uint64_t stamp = 0;  ///< the pixel it was bound for (pixel_stamp_)
    std::uint32_t n = 0;      ///< points per array
  };
  std::vector<ContinuedArray> continued_arrays_;
  std::optional<GeneratorBinder> continued_binder_;
  std::uint64_t refused_ = 0;  ///< a point count whose request the memory check refused (0: none)
  static constexpr std::uint64_t continued_max_points = std::uint64_t{1} << 16;  // ≤ 1.5 MiB by the request's check
  /// Points start … start + n − 1 of the sampler's set for `seed` (start > 0: progressive samplers only).
  PointSet draw(const std::string& sampler, std::uint64_t n, unsigned d, std::uint64_t seed,
                std::uint64_t start = 0) const;
  /// get_2d off the direct, zsobol and ranked paths (pair tables, registry sets); `coordinates` 1: only the first is
  /// used.
  std::array<double, 2> get_2d_slow(unsigned coordinates = 2);
  void get_2d_array_slow(std::uint64_t seed, std::uint32_t dimension, std::uint32_t n, std::uint64_t start,
                         std::array<double, 2>* out);

  /// zsobol (sequences/zsobol.hpp): one sequence over the image, so the
  /// draws need the pixel and the image size, not a per-pixel set; the
  /// pairs' keys depend on (seed, dimension) only and are derived once.
  std::optional<ZSobol> zsobol_;
  std::vector<ZSobol::Pair> zsobol_pairs_;
  /// Per dimension: the pixel's permuted digits, valid when its stamp is this
  /// pixel's, and those of its 16 × 16 block of pixels (render's tile), valid
  /// for the block in zsobol_blocks_: a tile's pixels share all digits above
  /// the block's 4 levels, computed once per tile.
  std::vector<std::uint64_t> zsobol_pixel_digits_, zsobol_stamps_, zsobol_block_digits_, zsobol_blocks_;
  std::uint64_t pixel_stamp_ = 0;
  static constexpr unsigned zsobol_block_levels = 4;
  /// The sequence index of this pixel's current sample in `dimension`'s pair.
  /// Sample `index_` of this pixel in `dimension`'s pair (its sequence index
  /// under the pixel's digit permutations): a table read once the pixel's
  /// digits of that pair are built (zsobol_index_miss, once per pixel and pair).
  std::uint64_t zsobol_index(std::uint32_t dimension) {
    if (dimension < zsobol_stamps_.size() && zsobol_stamps_[dimension] == pixel_stamp_ &&
        settings_.spp <= zsobol_table_max) [[likely]]
      return zsobol_pixel_digits_[dimension] | zsobol_sample_digits_[std::size_t{dimension} * settings_.spp + index_];
    return zsobol_index_miss(dimension);
  }
  std::uint64_t zsobol_index_miss(std::uint32_t dimension);
  std::array<double, 2> zsobol_point(std::uint32_t dimension) {
    const std::uint64_t sequence = zsobol_index(dimension);  // before the pair: it may add the pair
    return zsobol_->point(sequence, zsobol_pairs_[dimension]);
  }
  /// Up to this spp, the permuted digits of a pixel's samples are tabled per
  /// pixel and pair (ZSobol::sample_digit_table: 5 hashes at 16 spp instead of 32).
  static constexpr std::uint32_t zsobol_table_max = 256;
  std::vector<std::uint64_t> zsobol_sample_digits_;  ///< [dimension · spp + sample], valid with the pair's stamp

  /// sobol-bn, pmj02-bn, lattice-bn (sequences/ranked_blue_noise.hpp): the tile's pairs share one randomization
  /// per render (derived once); per pixel and dimension its keyed pair, valid
  /// when its stamp is this pixel's.
  std::optional<RankedBlueNoise> ranked_bn_;
  std::shared_ptr<const BlueNoiseTable> ranked_tile_;  ///< ranked_bn_'s tile (the committed one or a table file)
  std::vector<RankedBlueNoise::PixelPair> ranked_bn_shared_, ranked_bn_pixel_;
  std::vector<std::uint64_t> ranked_bn_stamps_;
  const RankedBlueNoise::PixelPair& ranked_bn_pair(std::uint32_t dimension) {
    if (dimension < ranked_bn_stamps_.size() && ranked_bn_stamps_[dimension] == pixel_stamp_) [[likely]]
      return ranked_bn_pixel_[dimension];
    return ranked_bn_pair_miss(dimension);
  }
  /// ranked_bn_pair the first time a pixel draws from `dimension`'s pair (once per pixel and pair).
  const RankedBlueNoise::PixelPair& ranked_bn_pair_miss(std::uint32_t dimension);
  std::array<double, 2> ranked_bn_point(std::uint32_t dimension) {
    return ranked_bn_->point(sequence_index_, ranked_bn_pair(dimension));
  }

  /// Sets built per seed into small tables (SamplerInfo::pair_tables: halton
  /// under permute), where the registry gives them: per pixel and dimension
  /// (and per shadow-ray array dimension, for all the pixel's samples) the
  /// table of the points the pixel uses, up to HaltonPairTables::max_points.
  std::optional<HaltonPairTables> tables_;
  bool tables_direct_ = false;                     ///< tables_ and offset_ + spp ≤ max_points
  std::vector<HaltonPairTables::Set> table_sets_;  ///< this pixel's get_2d sets, by dimension (cache)
  struct TableArraySet {
    HaltonPairTables::Set set;
    std::uint64_t stamp = 0;  ///< the pixel it was built for (pixel_stamp_)
    std::uint32_t n = 0;      ///< points per array
  };
  std::vector<TableArraySet> table_array_sets_;  ///< this pixel's continued get_2d_array sets, by dimension
  /// get_2d/get_1d's point from this pixel's table of the dimension (built on first use: table_point_miss).
  std::array<double, 2> table_point(unsigned coordinates) {
    const std::uint32_t dimension = dimension_++;
    if (dimension < table_sets_.size() && table_sets_[dimension].coordinates >= coordinates) [[likely]]
      return HaltonPairTables::point(table_sets_[dimension], sequence_index_);
    return table_point_miss(dimension, coordinates);
  }
  std::array<double, 2> table_point_miss(std::uint32_t dimension, unsigned coordinates);
  /// The n points of this sample's continued array from this pixel's built
  /// set of the dimension, if built (true); false: nothing drawn, the caller builds it.
  bool continued_table_array(std::uint32_t n, std::array<double, 2>* out) {
    if (dimension_ >= table_array_sets_.size()) return false;
    const TableArraySet& cached = table_array_sets_[dimension_];
    if (cached.stamp != pixel_stamp_ || cached.n != n) return false;
    ++dimension_;
    const std::uint64_t start = sequence_index_ * n;
    for (std::uint32_t i = 0; i < n; ++i) out[i] = HaltonPairTables::point(cached.set, start + i);
    return true;
  }

  static constexpr std::uint64_t tag_array = pixel::tag_array;  ///< get_2d_array's random-stream tag

  /// The sampler's sets as keyed pairs (patterns/keyed_pairs.hpp), where the
  /// registry gives them for its randomizer: the direct path. Point `index`
  /// of the 2D set of seed s is keyed_point(set_key(s), ⌊√n⌋, index).
  std::optional<KeyedPairs> keyed_;
  PairKey set_key(std::uint64_t seed) const noexcept {
    return std::visit([seed](const auto& pairs) { return pairs.key(seed); }, keyed_->pairs);
  }
  template <int coordinates>
  std::array<double, 2> keyed_point(PairKey key, std::uint64_t root, std::uint64_t index) const noexcept {
    return std::visit([&](const auto& pairs) { return pairs.template point<coordinates>(key, root, index); },
                      keyed_->pairs);
  }
  /// set_key of this pixel's get_2d set `dimension`, seed hash64(pixel_key_, dimension) (cached per pixel).
  PairKey dimension_key(std::uint32_t dimension) noexcept {
    const std::uint32_t bit = dimension < cached_dimensions ? 1u << dimension : 0u;
    if (dimension_valid_ & bit) return dimension_keys_[dimension];
    const PairKey key = set_key(hash64_extend(pixel_mix_, dimension));
    if (bit) dimension_keys_[dimension] = key, dimension_valid_ |= bit;
    return key;
  }
  /// hash64(pixel_key_, tag_array, dimension, ·)'s chain up to the last link's mix (cached per pixel).
  std::uint64_t array_prefix(std::uint32_t dimension) noexcept {
    const std::uint32_t bit = dimension < cached_dimensions ? 1u << dimension : 0u;
    if (array_valid_ & bit) return array_prefixes_[dimension];
    const std::uint64_t prefix = hash64_extend(array_mix_, dimension);
    if (bit) array_prefixes_[dimension] = prefix, array_valid_ |= bit;
    return prefix;
  }
  /// Whether the direct path can produce an n-point set (root = ⌊√n⌋).
  bool direct_for(std::uint64_t n, std::uint64_t root) const noexcept {
    return keyed_ && std::visit([&](const auto& pairs) { return pairs.takes(n, root); }, keyed_->pairs);
  }

  PixelSamplerSettings settings_;
  bool arrays_continue_ = false;  ///< a progressive sampler: get_2d_array continues the pixel's sequence (above)
  unsigned sampler_dims_ = 2;     ///< the dimensions of the sampler's sets (2, or its smallest: latin-square's 3)
  std::string spacetime_;         ///< the space-time sampler, or empty
  bool has_spacetime_ = false;
  std::uint64_t pixel_key_ = 0;
  std::uint32_t pixel_x_ = 0, pixel_y_ = 0;
  bool first_pixel_ = true;
  /// Per-pixel caches of the seed hashing that all samples of a pixel share
  /// (direct paths): hash64's first mix of the pixel key, of its array tag,
  /// and per dimension (bit set in the masks when valid) the set keys and array prefixes.
  static constexpr std::uint32_t cached_dimensions = 32;
  std::uint64_t pixel_mix_ = 0, array_mix_ = 0;
  std::uint32_t dimension_valid_ = 0, array_valid_ = 0;
  std::array<PairKey, cached_dimensions> dimension_keys_{};
  std::array<std::uint64_t, cached_dimensions> array_prefixes_{};
  std::uint64_t spp_root_ = 0;    ///< ⌊√spp⌋ (jittered's strata per axis)
  std::uint32_t array_n_ = 0;     ///< the last get_2d_array count …
  std::uint64_t array_root_ = 0;  ///< … and ⌊√n⌋
  /// The frame's seed: settings_.seed for frame 0 and for progressive
  /// samplers, hash(seed, frame) otherwise; and the index of the frame's
  /// first sample in each pixel's sequence (frame · spp for progressive samplers, else 0).
  std::uint64_t seed_ = 0, offset_ = 0;
  std::uint32_t index_ = 0;           ///< the sample within the frame, < spp
  std::uint64_t sequence_index_ = 0;  ///< offset_ + index_: the sample in the pixel's sequence
  std::uint32_t dimension_ = 0;
  std::vector<PointSet> sets_;  ///< this pixel's point sets, by dimension (cache)
  PointSet spacetime_set_;
};

}  // namespace stratum::render
