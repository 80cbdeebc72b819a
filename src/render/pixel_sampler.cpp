#include "stratum/render/pixel_sampler.hpp"

#include <algorithm>
#include <bit>

#include "stratum/patterns/random.hpp"
#include "stratum/patterns/strata.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/memory.hpp"
#include "stratum/registry/spec.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/real.hpp"

namespace stratum::render {

namespace {
// The pixel, frame and array tags are the core pixel sampler's (stratum/pixel/pixel_sampler.hpp): one seeding scheme.
using pixel::tag_frame;
using pixel::tag_pixel;
constexpr std::uint64_t tag_time = 0x5449'4d45ULL;  // random-stream tag of the time patterns

}  // namespace

std::uint64_t PixelSampler::set_seed_for_test(std::uint64_t seed, std::uint32_t x, std::uint32_t y,
                                              std::uint32_t dimension) noexcept {
  return pixel::set_seed(seed, x, y, dimension);
}

std::uint64_t PixelSampler::array_seed_for_test(std::uint64_t seed, std::uint32_t x, std::uint32_t y,
                                                std::uint32_t dimension, std::uint64_t index) noexcept {
  return pixel::array_seed(seed, x, y, dimension, index);
}

PixelSampler::PixelSampler(PixelSamplerSettings settings) : settings_(std::move(settings)) {
  require(settings_.spp >= 1, "spp", settings_.spp, "must be a positive integer");
  const std::uint64_t max_frame = (std::uint64_t{1} << 32) / settings_.spp - 1;
  require(settings_.frame <= max_frame, "frame", settings_.frame,
          "must be in [0, " + std::to_string(max_frame) + "] at spp " + std::to_string(settings_.spp) +
              " ((frame + 1) * spp <= 2^32)");
  if (!settings_.time_pattern.empty()) {
    if (settings_.time_pattern == "random") spacetime_ = "spacetime-random";
    else if (settings_.time_pattern == "cook") spacetime_ = "spacetime-cook";
    else if (settings_.time_pattern == "magic-square") spacetime_ = "spacetime-magic";
    else throw invalid_argument("time-pattern", settings_.time_pattern, "allowed: random, cook, magic-square");
    try {
      draw(spacetime_, settings_.spp, 3, 0);  // validates spp = m² (and magic-square's orders)
    } catch (const invalid_argument& e) {
      throw invalid_argument("spp", std::to_string(settings_.spp),
                             "time-pattern " + settings_.time_pattern + " needs spp = m^2 strata (" + e.what() + ")");
    }
  }
  const std::string& r = settings_.randomize;
  const std::string& name = settings_.sampler;
  const SamplerInfo& info = find_sampler(name);
  if (info.flags.space_time)
    throw invalid_argument("sampler", spec(),
                           "is a space-time pattern (x, y, t) that draws film positions and times together: give it "
                           "as --time-pattern random, cook or magic-square (Python time_pattern=) beside a pixel "
                           "sampler");
  if (info.zsobol_image || info.ranked_image)
    for (const char* own : {"pixel", "resolution"})
      if (settings_.params.contains(own))
        throw invalid_argument("sampler", spec(),
                               std::string(own) + " is the renderer's own for an image sampler (it draws every pixel " +
                                   "of the image, whose size it knows): leave it out");
  // A sampler defined from 3 dimensions on (latin-square: an orthogonal
  // array, every 2D projection one point per cell) gives each pair its first two.
  sampler_dims_ = std::max(2u, info.min_dim);
  draw(settings_.sampler, settings_.spp, 2, 0);  // validates the sampler, randomizer and spp
  const bool continues = info.flags.progressive || info.flags.frames_continue;
  offset_ = continues ? std::uint64_t{settings_.frame} * settings_.spp : 0;
  arrays_continue_ = info.flags.progressive;
  seed_ = continues || settings_.frame == 0 ? settings_.seed : hash64(settings_.seed, tag_frame, settings_.frame);
  const Randomizer randomizer = r.empty() ? info.randomization.default_randomizer : parse_randomizer(r);
  // The keyed pairs and pair tables draw the default parameters' sets; with
  // parameters the sets come from the registry's generators.
  const bool defaults = settings_.params.empty();
  if (info.keyed_pairs && defaults) keyed_ = info.keyed_pairs(randomizer);
  if (info.pair_tables && defaults) tables_ = info.pair_tables(randomizer);
  has_spacetime_ = !spacetime_.empty();
  tables_direct_ = tables_ && offset_ + settings_.spp <= HaltonPairTables::max_points;
  if (info.bind && !keyed_ && !tables_) set_binder_.emplace(name, set_request(seed_, settings_.spp, offset_));
  if (!info.bind && !keyed_ && !tables_ && !info.zsobol_image && !info.ranked_image)
    set_maker_.emplace(name, set_request(seed_, settings_.spp, offset_));
  pixel_seeded_ = set_binder_ ? set_binder_->seeded() : set_maker_ ? set_maker_->seeded() : nullptr;
  spp_root_ = integer_root(settings_.spp, 2);
  if (info.zsobol_image) zsobol_.emplace(info.zsobol_image(std::max(1u, settings_.resolution), settings_.spp, seed_));
  if (info.ranked_image) {
    SamplerRequest request = set_request(seed_, settings_.spp, 0);  // validated above
    request.values = bind_params(name, info.params, request.params);
    ranked_tile_ = info.ranked_image(request);
    ranked_bn_.emplace(*ranked_tile_, settings_.spp, seed_);
  }
}

PixelSampler::PixelSampler(const PixelSampler& other) : settings_(other.settings_) {
  // The validated choices and per-render constants; the caches start empty.
  keyed_ = other.keyed_, tables_ = other.tables_, tables_direct_ = other.tables_direct_;
  set_binder_ = other.set_binder_, array_binder_ = other.array_binder_, continued_binder_ = other.continued_binder_;
  set_maker_ = other.set_maker_, array_maker_ = other.array_maker_, pixel_seeded_ = other.pixel_seeded_;
  refused_ = other.refused_;
  arrays_continue_ = other.arrays_continue_, sampler_dims_ = other.sampler_dims_;
  spacetime_ = other.spacetime_;
  has_spacetime_ = other.has_spacetime_, spp_root_ = other.spp_root_;
  seed_ = other.seed_, offset_ = other.offset_;
  zsobol_ = other.zsobol_, zsobol_pairs_ = other.zsobol_pairs_;
  ranked_bn_ = other.ranked_bn_, ranked_bn_shared_ = other.ranked_bn_shared_, ranked_tile_ = other.ranked_tile_;
}

std::string PixelSampler::spec() const {
  return format_sampler_spec({settings_.sampler, settings_.params, settings_.randomize});
}

PointSet PixelSampler::draw(const std::string& sampler, std::uint64_t n, unsigned d, std::uint64_t seed,
                            std::uint64_t start) const {
  // Direct paths, bit-identical to the registry's (tested): the registry call
  // validates and sets up bulk generation, microseconds per call, which
  // dominates when drawing a few points per pixel and dimension.
  if (sampler == settings_.sampler && d == 2) {
    // The n-point 2D set whose point i is point(start + i).
    const auto set_of = [n, start](auto point) {
      PointSet points{n, 2, std::make_unique<double[]>(n * 2)};
      for (std::uint64_t i = 0; i < n; ++i) {
        const std::array<double, 2> p = point(start + i);
        points.data[2 * i] = p[0], points.data[2 * i + 1] = p[1];
      }
      return points;
    };
    if (const std::uint64_t root = integer_root(n, 2); direct_for(n, root)) {  // else the registry names the bad count
      const PairKey key = set_key(seed);
      return set_of([&](std::uint64_t i) { return keyed_point<2>(key, root, i); });
    }
    if (tables_) {
      PointSet points{n, 2, std::make_unique<double[]>(n * 2)};
      tables_->fill(seed, start, n, points.data.get());
      return points;
    }
  }
  if (sampler == settings_.sampler) {
    SamplerRequest request = set_request(seed, n, start);
    request.d = std::max(d, sampler_dims_);
    return generate_points(sampler, request);
  }
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  request.start = start;
  return generate_points(sampler, request);
}

void PixelSampler::start_pixel_sample(std::uint32_t x, std::uint32_t y, std::uint32_t index) {
  if (first_pixel_ || x != pixel_x_ || y != pixel_y_) {
    const std::uint64_t key = hash64(seed_, tag_pixel, x, y);
    pixel_key_ = key, pixel_x_ = x, pixel_y_ = y;
    first_pixel_ = false;
    ++pixel_stamp_;  // zsobol's per-pixel digits are stale
    pixel_mix_ = hash64(key);
    array_mix_ = hash64_extend(pixel_mix_, tag_array);
    dimension_valid_ = array_valid_ = 0;
    for (auto& set : sets_) set.n = 0;  // stale: redrawn on first use
    for (auto& generator : generators_) generator = {};
    for (auto& set : table_sets_) set.coordinates = 0;
    if (!spacetime_.empty()) {
      // A frame's own time pattern also where the pixel key is every frame's (progressive samplers).
      const std::uint64_t time_seed =
          settings_.frame == 0 ? hash64(key, tag_time) : hash64(key, tag_time, settings_.frame);
      spacetime_set_ = draw(spacetime_, settings_.spp, 3, time_seed);
    }
  }
  index_ = index < settings_.spp ? index : index % settings_.spp;  // no division in the usual case
  sequence_index_ = offset_ + index_;
  dimension_ = 0;
}

const PointSet& PixelSampler::set_for(std::uint32_t dimension) {
  if (sets_.size() <= dimension) sets_.resize(dimension + 1);
  PointSet& set = sets_[dimension];
  if (set.n != 0) return set;
  const std::uint64_t seed = hash64_extend(pixel_mix_, dimension);
  set = keyed_ || tables_ ? draw(settings_.sampler, settings_.spp, 2, seed, offset_) : set_maker_->generate(seed);
  return set;
}

SamplerRequest PixelSampler::set_request(std::uint64_t seed, std::uint64_t n, std::uint64_t start) const {
  SamplerRequest request;
  request.n = n;
  request.d = sampler_dims_;
  request.seed = seed;
  request.start = start;
  request.randomize = settings_.randomize;
  request.params = settings_.params;
  return request;
}

const PointGenerator& PixelSampler::generator_for(std::uint32_t dimension) {
  if (generators_.size() <= dimension) generators_.resize(dimension + 1);
  PointGenerator& generator = generators_[dimension];
  if (!generator) generator = set_binder_->bind(hash64_extend(pixel_mix_, dimension), offset_);
  return generator;
}

std::uint64_t PixelSampler::zsobol_index_miss(std::uint32_t dimension) {
  while (zsobol_pairs_.size() <= dimension) zsobol_pairs_.push_back(zsobol_->pair(std::uint32_t(zsobol_pairs_.size())));
  if (zsobol_stamps_.size() <= dimension) {
    zsobol_stamps_.resize(dimension + 1, 0), zsobol_pixel_digits_.resize(dimension + 1);
    zsobol_blocks_.resize(dimension + 1, ~std::uint64_t{0}), zsobol_block_digits_.resize(dimension + 1);
  }
  const ZSobol::Pair& pair = zsobol_pairs_[dimension];
  if (zsobol_stamps_[dimension] != pixel_stamp_) {
    const std::uint64_t block =
        (std::uint64_t{pixel_y_ >> zsobol_block_levels} << 32) | (pixel_x_ >> zsobol_block_levels);
    if (zsobol_blocks_[dimension] != block) {
      zsobol_block_digits_[dimension] =
          zsobol_->block_digits(pixel_x_, pixel_y_, pair, zsobol_block_levels, settings_.frame);
      zsobol_blocks_[dimension] = block;
    }
    zsobol_pixel_digits_[dimension] = zsobol_->pixel_digits(pixel_x_, pixel_y_, pair, zsobol_block_digits_[dimension],
                                                            zsobol_block_levels, settings_.frame);
    if (settings_.spp <= zsobol_table_max) {
      const std::size_t first = std::size_t{dimension} * settings_.spp;
      if (zsobol_sample_digits_.size() < first + settings_.spp) zsobol_sample_digits_.resize(first + settings_.spp);
      zsobol_->sample_digit_table(pixel_x_, pixel_y_, pair, settings_.frame, zsobol_sample_digits_.data() + first);
    }
    zsobol_stamps_[dimension] = pixel_stamp_;
  }
  if (settings_.spp <= zsobol_table_max)
    return zsobol_pixel_digits_[dimension] | zsobol_sample_digits_[std::size_t{dimension} * settings_.spp + index_];
  return zsobol_->sample_digits(pixel_x_, pixel_y_, zsobol_pixel_digits_[dimension], index_, pair, settings_.frame);
}

const RankedBlueNoise::PixelPair& PixelSampler::ranked_bn_pair_miss(std::uint32_t dimension) {
  while (ranked_bn_shared_.size() <= dimension)
    ranked_bn_shared_.push_back(ranked_bn_->shared_pair(std::uint32_t(ranked_bn_shared_.size())));
  if (ranked_bn_stamps_.size() <= dimension)
    ranked_bn_stamps_.resize(dimension + 1, 0), ranked_bn_pixel_.resize(dimension + 1);
  if (ranked_bn_stamps_[dimension] != pixel_stamp_) {
    ranked_bn_pixel_[dimension] = ranked_bn_->pixel_pair(pixel_x_, pixel_y_, dimension, ranked_bn_shared_[dimension]);
    ranked_bn_stamps_[dimension] = pixel_stamp_;
  }
  return ranked_bn_pixel_[dimension];
}

std::array<double, 2> PixelSampler::table_point_miss(std::uint32_t dimension, unsigned coordinates) {
  if (table_sets_.size() <= dimension) table_sets_.resize(dimension + 1);
  HaltonPairTables::Set& set = table_sets_[dimension];
  tables_->build(hash64_extend(pixel_mix_, dimension), offset_ + settings_.spp, set, coordinates);
  return HaltonPairTables::point(set, sequence_index_);
}

std::array<double, 2> PixelSampler::get_2d_slow(unsigned coordinates) {
  if (pixel_seeded_) {
    const SeededGenerator& generator = *pixel_seeded_;
    const std::uint32_t dimension = dimension_++;
    if (seeded_sets_.size() <= dimension) seeded_sets_.resize(dimension + 1);
    SeededState& state = seeded_sets_[dimension];
    if (state.stamp != pixel_stamp_ || state.coordinates < coordinates) {
      state.words.resize(generator.state_words());
      generator.seed(hash64_extend(pixel_mix_, dimension), coordinates, state.words.data());  // hash64(key, dim)
      state.stamp = pixel_stamp_, state.coordinates = coordinates;
    }
    std::array<double, 2> point{0.0, 0.0};
    generator.point(state.words.data(), sequence_index_, coordinates, point.data());
    return point;
  }
  if (set_binder_) {
    const PointGenerator& generator = generator_for(dimension_++);
    return {generator.sample(sequence_index_, 0), coordinates > 1 ? generator.sample(sequence_index_, 1) : 0.0};
  }
  const PointSet& set = set_for(dimension_++);
  return {set(index_, 0), set(index_, 1)};
}

void PixelSampler::get_2d_array_slow(std::uint64_t seed, std::uint32_t dimension, std::uint32_t n, std::uint64_t start,
                                     std::array<double, 2>* out) {
  if (zsobol_ && std::has_single_bit(n)) {  // other counts: the registry names the bad count below
    const std::uint64_t sequence = zsobol_index(dimension);
    const auto k = static_cast<unsigned>(std::countr_zero(n));
    for (std::uint32_t i = 0; i < n; ++i) out[i] = zsobol_->array_point(sequence, k, i, zsobol_pairs_[dimension]);
    return;
  }
  if (ranked_bn_) {  // the pixel's arrays together are its block of spp · n points
    const RankedBlueNoise::PixelPair& pair = ranked_bn_pair(dimension);
    for (std::uint32_t i = 0; i < n; ++i) out[i] = ranked_bn_->array_point(sequence_index_, n, i, pair);
    return;
  }
  if (tables_ && arrays_continue_ && (offset_ + settings_.spp) * n <= HaltonPairTables::max_points) {
    // Every sample of the pixel reads the same continued set (its seed ends
    // in tag_continued): built once per pixel and array dimension, for all
    // the pixel's arrays, instead of once per sample.
    if (table_array_sets_.size() <= dimension) table_array_sets_.resize(dimension + 1);
    TableArraySet& cached = table_array_sets_[dimension];
    if (cached.stamp != pixel_stamp_ || cached.n != n) {
      tables_->build(seed, (offset_ + settings_.spp) * n, cached.set);
      cached.stamp = pixel_stamp_, cached.n = n;
    }
    for (std::uint32_t i = 0; i < n; ++i) out[i] = HaltonPairTables::point(cached.set, start + i);
    return;
  }
  if (tables_) {  // a set per sample (a frame whose arrays pass max_points)
    std::vector<double> points(2 * std::size_t{n});
    tables_->fill(seed, start, n, points.data());
    for (std::uint32_t i = 0; i < n; ++i) out[i] = {points[2 * i], points[2 * i + 1]};
    return;
  }
  const std::uint64_t continued_points = (offset_ + settings_.spp) * std::uint64_t{n};  // indices 0 … this − 1
  if (set_binder_ && arrays_continue_ && continued_points <= continued_max_points && continued_points != refused_) {
    if (continued_arrays_.size() <= dimension) continued_arrays_.resize(dimension + 1);
    ContinuedArray& cached = continued_arrays_[dimension];
    if (cached.stamp != pixel_stamp_ || cached.n != n) {
      if (!continued_binder_ || continued_binder_->count() != continued_points) {
        try {
          continued_binder_.emplace(settings_.sampler, set_request(seed, continued_points, 0));
        } catch (const memory_error&) {  // the request's memory check under a low limit: bind per sample
          continued_binder_.reset(), refused_ = continued_points;
          return get_2d_array_slow(seed, dimension, n, start, out);
        }
      }
      if (const auto& seeded = continued_binder_->seeded()) {
        cached.seeded.resize(seeded->state_words());
        seeded->seed(seed, 2, cached.seeded.data());
      } else {
        cached.generator = continued_binder_->bind(seed, 0);
      }
      cached.stamp = pixel_stamp_, cached.n = n;
    }
    if (const auto& seeded = continued_binder_->seeded())
      return seeded_array(*seeded, cached.seeded.data(), start, n, out);
    const PointGenerator& generator = cached.generator;
    for (std::uint32_t i = 0; i < n; ++i) out[i] = {generator.sample(start + i, 0), generator.sample(start + i, 1)};
    return;
  }
  if (set_binder_) {
    if (!array_binder_ || array_binder_->count() != n)
      array_binder_.emplace(settings_.sampler, set_request(seed, n, start));
    if (const auto& seeded = array_binder_->seeded())  // a set per sample, seeded in place
      return seeded_sample_array(*seeded, seed, start, n, out);
    const PointGenerator generator = array_binder_->bind(seed, start);
    for (std::uint32_t i = 0; i < n; ++i) out[i] = {generator.sample(start + i, 0), generator.sample(start + i, 1)};
    return;
  }
  const bool made_whole = start == 0 && !keyed_ && !tables_;  // a pattern's set per sample, through its SetBinder
  if (made_whole && (!array_maker_ || array_maker_->count() != n))
    array_maker_.emplace(settings_.sampler, set_request(seed, n, 0));
  if (made_whole && array_maker_->seeded())  // the set's state written in place (n-rooks: its permutations)
    return seeded_sample_array(*array_maker_->seeded(), seed, 0, n, out);
  const PointSet set =  // points start … start + n − 1
      made_whole ? array_maker_->generate(seed) : draw(settings_.sampler, n, 2, seed, start);
  for (std::uint32_t i = 0; i < n; ++i) out[i] = {set(i, 0), set(i, 1)};
}

void PixelSampler::seeded_sample_array(const SeededGenerator& generator, std::uint64_t seed, std::uint64_t start,
                                       std::uint32_t n, std::array<double, 2>* out) {
  seeded_scratch_.resize(generator.state_words());
  generator.seed(seed, 2, seeded_scratch_.data());
  seeded_array(generator, seeded_scratch_.data(), start, n, out);
}

void PixelSampler::seeded_array(const SeededGenerator& generator, const std::uint64_t* state, std::uint64_t start,
                                std::uint32_t n, std::array<double, 2>* out) {
  seeded_points_.resize(2 * std::size_t{n});
  generator.points(state, start, n, 2, seeded_points_.data());
  for (std::uint32_t i = 0; i < n; ++i) out[i] = {seeded_points_[2 * i], seeded_points_[2 * i + 1]};
}

}  // namespace stratum::render
