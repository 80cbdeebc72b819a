#include "stratum/render/pixel_sampler.hpp"

#include "stratum/patterns/random.hpp"
#include "stratum/patterns/strata.hpp"
#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render {

namespace {
constexpr std::uint64_t tag_pixel = 0x5049'5845'4cULL;  // random-stream tags
constexpr std::uint64_t tag_array = 0x4152'5241'59ULL;
constexpr std::uint64_t tag_time = 0x5449'4d45ULL;
/// The key Jittered (patterns/jittered.hpp) derives from its seed.
constexpr std::uint64_t tag_jittered = 0x4a49545445524544ULL;

/// Sobol' (0,2)-sequence tables, shared by every pixel sampler.
const Sobol& sobol_2d() {
  static const Sobol sobol(2);
  return sobol;
}
}  // namespace

PixelSampler::PixelSampler(PixelSamplerSettings settings) : settings_(std::move(settings)) {
  require(settings_.spp >= 1, "spp", settings_.spp, "must be a positive integer");
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
  draw(settings_.sampler, settings_.spp, 2, 0);  // validates the sampler, randomizer and spp
  const std::string& r = settings_.randomize;
  const std::string& name = settings_.sampler;
  if (name == "random" && (r.empty() || r == "none")) fast_ = Fast::random;
  if (name == "sobol" && (r.empty() || r == "owen-hash")) fast_ = Fast::sobol_owen_hash;
  if (name == "jittered" && (r.empty() || r == "none")) fast_ = Fast::jittered;
  if (name == "pmj02" && (r.empty() || r == "none")) fast_ = Fast::pmj02;
  halton_permute_ = name == "halton" && (r.empty() || r == "permute");
  spp_root_ = integer_root(settings_.spp, 2);
}

PixelSampler::PixelSampler(const PixelSampler& other)
    : settings_(other.settings_), fast_(other.fast_), halton_permute_(other.halton_permute_),
      spacetime_(other.spacetime_), spp_root_(other.spp_root_) {}

bool PixelSampler::direct_for(std::uint64_t n) const noexcept {
  if (fast_ == Fast::none) return false;
  if (fast_ != Fast::jittered) return true;
  const std::uint64_t k = integer_root(n, 2);
  return k * k == n;  // otherwise the registry names the bad count
}

std::array<double, 2> PixelSampler::direct_point(std::uint64_t seed, std::uint64_t root,
                                                 std::uint64_t index) const noexcept {
  switch (fast_) {
    case Fast::random: {
      const RandomPattern random(seed);
      return {random.sample(index, 0), random.sample(index, 1)};
    }
    case Fast::sobol_owen_hash: {
      const HashOwenScrambler owen(seed);
      return {sobol_2d().sample(index, 0, owen), sobol_2d().sample(index, 1, owen)};
    }
    case Fast::jittered: {
      // Jittered(StrataShape::equal(n, 2), seed).sample(index, ·) without the
      // shape's vectors: cell (index mod k, index div k) of the k × k grid.
      const std::uint64_t k = root, key = hash64(seed, tag_jittered);
      return {cell_coordinate<double>(index % k, uniform01<double>(key, index, 0u), k),
              cell_coordinate<double>((index / k) % k, uniform01<double>(key, index, 1u), k)};
    }
    case Fast::pmj02: {
      const Pmj02 pmj(2, seed);
      return {pmj.sample(index, 0), pmj.sample(index, 1)};
    }
    case Fast::none: break;
  }
  return {0, 0};
}

PointSet PixelSampler::draw(const std::string& sampler, std::uint64_t n, unsigned d, std::uint64_t seed) const {
  // Direct paths, bit-identical to the registry's (tested): the registry call
  // validates and sets up bulk generation, microseconds per call, which
  // dominates when drawing a few points per pixel and dimension.
  if (sampler == settings_.sampler && d == 2 && direct_for(n)) {
    PointSet points{n, d, std::make_unique<double[]>(n * d)};
    const std::uint64_t root = integer_root(n, 2);
    for (std::uint64_t i = 0; i < n; ++i) {
      const auto p = direct_point(seed, root, i);
      points.data[2 * i] = p[0], points.data[2 * i + 1] = p[1];
    }
    return points;
  }
  if (sampler == settings_.sampler && d == 2 && halton_permute_) {
    // The registry's scrambler for these bases and indices, without its
    // request handling: each point straight from RandomDigitPermutations
    // (sample() equals the registry's tabulated fill bit for bit).
    const RandomDigitPermutations permutations(seed, {2, 3}, n - 1);
    PointSet points{n, d, std::make_unique<double[]>(n * d)};
    for (std::uint64_t i = 0; i < n; ++i)
      points.data[2 * i] = permutations.sample(i, 0), points.data[2 * i + 1] = permutations.sample(i, 1);
    return points;
  }
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.seed = seed;
  request.randomize = sampler == settings_.sampler ? settings_.randomize : "";
  return generate_points(sampler, request);
}

void PixelSampler::start_pixel_sample(std::uint32_t x, std::uint32_t y, std::uint32_t index) {
  const std::uint64_t key = hash64(settings_.seed, tag_pixel, x, y);
  if (key != pixel_key_ || first_pixel_) {
    pixel_key_ = key;
    first_pixel_ = false;
    for (auto& set : sets_) set.n = 0;  // stale: redrawn on first use
    if (!spacetime_.empty()) spacetime_set_ = draw(spacetime_, settings_.spp, 3, hash64(key, tag_time));
  }
  index_ = index % settings_.spp;
  dimension_ = 0;
}

const PointSet& PixelSampler::set_for(std::uint32_t dimension) {
  if (sets_.size() <= dimension) sets_.resize(dimension + 1);
  PointSet& set = sets_[dimension];
  if (set.n == 0) set = draw(settings_.sampler, settings_.spp, 2, hash64(pixel_key_, dimension));
  return set;
}

std::array<double, 2> PixelSampler::get_pixel_2d() {
  if (!spacetime_.empty()) return {spacetime_set_(index_, 0), spacetime_set_(index_, 1)};
  return get_2d();
}

double PixelSampler::get_time() {
  if (!spacetime_.empty()) return spacetime_set_(index_, 2);
  return get_1d();
}

std::array<double, 2> PixelSampler::get_2d() {
  const std::uint32_t dimension = dimension_++;
  if (fast_ != Fast::none) return direct_point(hash64(pixel_key_, dimension), spp_root_, index_);
  const PointSet& set = set_for(dimension);
  return {set(index_, 0), set(index_, 1)};
}

double PixelSampler::get_1d() { return get_2d()[0]; }

void PixelSampler::get_2d_array(std::uint32_t n, std::array<double, 2>* out) {
  const std::uint64_t seed = hash64(pixel_key_, tag_array, dimension_++, index_);
  if (n != array_n_) array_n_ = n, array_root_ = integer_root(n, 2);
  if (fast_ != Fast::none && (fast_ != Fast::jittered || array_root_ * array_root_ == n)) {
    for (std::uint32_t i = 0; i < n; ++i) out[i] = direct_point(seed, array_root_, i);
    return;
  }
  const PointSet set = draw(settings_.sampler, n, 2, seed);
  for (std::uint32_t i = 0; i < n; ++i) out[i] = {set(i, 0), set(i, 1)};
}

}  // namespace stratum::render
