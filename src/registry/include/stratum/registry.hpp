#pragma once
/// The registry of samplers: every sampler with its name, description,
/// dimensions, properties, accepted randomizers and parameters. The CLI, the
/// Python package, the tests and the benchmarks all iterate over it; adding a
/// sampler is one entry in the fitting family file src/registry/samplers_*.cpp
/// (the families are listed in src/registry/families.hpp). Warps, measures and
/// integrands have lists of their own (warp_registry.hpp, analysis/measures.hpp,
/// analysis/integrands.hpp).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stratum/registry/params.hpp"
#include "stratum/util/point_set.hpp"

namespace stratum {

struct KeyedPairs;       // stratum/patterns/keyed_pairs.hpp
class HaltonPairTables;  // stratum/registry/halton_pair_tables.hpp
class ZSobol;            // stratum/sequences/zsobol.hpp
struct BlueNoiseTable;   // stratum/sequences/ranked_blue_noise.hpp

/// Every randomizer as a value: a generator switches on it once (one
/// switch per construction), the faces spell it by randomizer_name.
enum class Randomizer { none, owen, owen_hash, xor_shift, lms, permute, cp };

/// The structure of a sampler's construction, which decides the
/// randomizers that keep it (accepted_randomizers): the randomizers a
/// sampler accepts follow from its family, never from a list of its own.
enum class RandomizerFamily {
  /// A digital construction in base 2 (Sobol'): owen-hash, owen, xor and lms
  /// act on its binary digits and keep its nets; cp rotates it.
  base2_digits,
  /// Digits in a base b (radical inverses, Faure): permute, owen and xor act
  /// on its base-b digits and keep its elementary intervals; cp rotates it.
  base_b_digits,
  /// No digit structure (lattices, grids, Kronecker): cp, a rotation modulo 1.
  rotation,
  /// Its construction draws from the seed already (jittered, Poisson disk,
  /// PMJ): a rotation would break its strata, so none.
  seeded,
  /// A pixel sampler whose construction includes Owen hash scrambling
  /// (zsobol, the ranked blue-noise samplers): owen-hash.
  seeded_owen_hash,
};

/// How a sampler is randomized: its family and its default randomizer.
struct Randomization {
  RandomizerFamily family = RandomizerFamily::seeded;
  Randomizer default_randomizer = Randomizer::none;
};

/// The name the faces use ("owen-hash", "xor", …).
std::string_view randomizer_name(Randomizer randomizer);
/// The randomizer called `name`; throws invalid_argument naming "randomize" and listing the names.
Randomizer parse_randomizer(std::string_view name);
/// The family's name in listings ("base2-digits", "base-b-digits", "rotation", "seeded", "seeded-owen-hash").
std::string_view randomizer_family_name(RandomizerFamily family);
/// The randomizers `randomization`'s family accepts, its default first.
std::vector<Randomizer> accepted_randomizers(const Randomization& randomization);

/// What a caller asks of a sampler.
struct SamplerRequest {
  std::optional<std::uint64_t> n;  ///< absent only where a sampler can choose (maximal Poisson disk)
  unsigned d = 2;
  std::uint64_t seed = 0;
  std::uint64_t start = 0;  ///< index of the first point (sequences only; scipy's fast_forward)
  std::string randomize;    ///< empty: the sampler's default
  /// `randomize` resolved (the default where empty) by validate_request
  /// and generate_points; generators switch on it.
  Randomizer randomizer = Randomizer::none;
  std::optional<double> radius;  ///< Poisson disk and friends
  unsigned threads = 1;
  std::map<std::string, std::string> params;  ///< as text ("periodic=1"): every face passes it through unchanged
  /// `params` bound to the sampler's schema (parsed, checked, defaults
  /// filled in) by validate_request and generate_points; entries read
  /// their parameters here.
  ParamValues values{};
};

/// What code may rely on about a sampler: typed flags, queried without
/// string matching (DESIGN.md); SamplerInfo::properties says the rest in
/// words. Each flag is checked against the sampler's points by
/// tests/registry/sampler_flags_test.cpp.
struct SamplerFlags {
  /// Point i is computed alone from (seed, i, dimension), without its predecessors.
  bool index_addressable = false;
  /// Every prefix of the randomized sequence is the sampler's set of that
  /// size, so `start` continues it: points [start, start + n) of a seed are
  /// rows start … start + n − 1 of the set of start + n points.
  bool progressive = false;
  /// A pixel sampler (one pixel's spp samples: zsobol, sobol-bn, …) whose
  /// `start` continues that pixel's sequence (render --frame K reads samples
  /// K·spp … (K+1)·spp − 1).
  bool frames_continue = false;
  /// Its construction draws from the seed: even under randomizer none, a
  /// new seed gives a new set (jittered, pmj02, zsobol, …; n-queens where
  /// its search, not the formula, places the queens). Without the flag the
  /// construction is deterministic and only a randomizer uses the seed.
  bool self_randomized = false;
  /// Dimensions 0 and 1 form a (0,m,2)-net in base 2 at every n = 2^m (one
  /// point in every elementary interval of area 1/n), under each randomizer
  /// it accepts but cp (a rotation breaks the intervals).
  bool zero_two_net = false;
  /// An (x, y, t) pattern whose third coordinate is time (spacetime-random,
  /// -cook, -magic): the renderer takes it as a time pattern, not as a pixel sampler.
  bool space_time = false;
  /// The randomizers under which each point is uniform in [0,1)^d on its own,
  /// so a prefix of a pixel's set is an unbiased estimate (Owen 1997): the
  /// renderer's equal-time passes may stop a progressive set anywhere. Listed
  /// where the renderer relies on it.
  std::vector<std::string> prefix_unbiased{};
};

/// An index-addressable sampler bound to one request (dimensions, seed,
/// randomizer, parameters): the core construction composed with its
/// randomizer, a value that draws coordinate `dim` of point `index` alone.
/// The renderer draws through it; the registry fills sets from it (unless
/// an engine, Sobol's block walk, fills faster: then they are tested equal).
class PointGenerator {
 public:
  using Sample = std::function<double(std::uint64_t index, unsigned dim)>;
  PointGenerator() = default;
  PointGenerator(unsigned dimensions, Sample sample) : dimensions_(dimensions), sample_(std::move(sample)) {}
  double sample(std::uint64_t index, unsigned dim) const { return sample_(index, dim); }
  unsigned dimensions() const noexcept { return dimensions_; }
  /// out[k·d + j] = sample(first + k, j) for k < count and j < d.
  void fill(std::uint64_t first, std::uint64_t count, double* out) const;
  explicit operator bool() const noexcept { return static_cast<bool>(sample_); }

 private:
  unsigned dimensions_ = 0;
  Sample sample_;
};

/// A request's generator for many seeds, where binding one per seed would
/// cost more than its few points (a renderer's set per pixel and
/// dimension): what does not depend on the seed is built once, a seed's
/// state is `state_words()` 64-bit words that `seed` writes into the
/// caller's storage (no allocation, but for latin-square's symbol
/// coordinate: its square's scratch), and `point` reads a point from it. Its
/// points equal those of the request's PointGenerator bound to that seed, or
/// for a pattern made as a whole set its generate's (tested), which remain
/// the general paths.
class SeededGenerator {
 public:
  virtual ~SeededGenerator() = default;
  virtual std::size_t state_words() const noexcept = 0;
  /// The state of `seed` for coordinates 0 … coordinates − 1 (the others' words are left as they are).
  virtual void seed(std::uint64_t seed, unsigned coordinates, std::uint64_t* state) const noexcept = 0;
  /// out[j] = coordinate j of point `index`, for j < coordinates, from a state `seed` wrote for them.
  virtual void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
                     double* out) const noexcept = 0;
  /// Points first … first + count − 1 (point k's coordinates at out + k·coordinates): one call for an array.
  virtual void points(const std::uint64_t* state, std::uint64_t first, std::uint64_t count, unsigned coordinates,
                      double* out) const noexcept {
    for (std::uint64_t k = 0; k < count; ++k) point(state, first + k, coordinates, out + k * coordinates);
  }
};

/// The words SamplerInfo::properties uses for SamplerFlags, in listings.
inline constexpr const char* frames_continue_property = "start continues the pixel's sequence (frames)";

struct SamplerInfo {
  std::string name;
  std::string kind;  ///< "sequence" (index-addressable) or "pattern" (finite set)
  std::string description;
  unsigned min_dim = 1;
  unsigned max_dim = 1;
  SamplerFlags flags{};
  std::vector<std::string> properties;  ///< in words, beside the flags (listings: property_words)
  Randomization randomization{};        ///< decides `randomizers`
  std::string counts;                   ///< which n the sampler takes, in words
  bool n_optional = false;              ///< may n be left out (then `radius` decides)?
  std::vector<Param> params;            ///< the schema of `SamplerRequest::params`
  /// Checks the sampler-specific part of a request (n it can take, params);
  /// throws stratum::invalid_argument.
  std::function<void(const SamplerRequest&)> validate;
  /// Number of points the request will produce, known before generating
  /// (nullopt: only known after, as for a maximal Poisson-disk set).
  std::function<std::optional<std::uint64_t>(const SamplerRequest&)> count;
  /// Fills a validated request's points.
  std::function<PointSet(const SamplerRequest&)> generate;
  /// The request's generator, for every index-addressable sampler (and
  /// patterns whose points are computed alone once the set is built):
  /// without `generate`, the registry fills sets from it.
  std::function<PointGenerator(const SamplerRequest&)> bind{};
  /// The request's generator as a SeededGenerator, where the sampler has
  /// one under the request's randomizer (else nullptr): GeneratorBinder
  /// builds it once, and the renderer draws its sets through it. A pattern
  /// made as a whole set (no bind) may have one too, whose state is the
  /// set's construction (n-rooks: its permutations): SetBinder builds it.
  std::function<std::shared_ptr<const SeededGenerator>(const SamplerRequest&)> seeded{};
  /// Its 2D sets under a randomizer as keyed pairs (patterns/keyed_pairs.hpp:
  /// points from a key of the seed, no setup per set), where it has them,
  /// else nullopt: how the renderer draws a set per pixel and dimension.
  std::function<std::optional<KeyedPairs>(Randomizer)> keyed_pairs{};
  /// Its 2D sets (default parameters) under a randomizer built per seed into
  /// small tables (halton under permute: HaltonPairTables), else nullopt.
  std::function<std::optional<HaltonPairTables>(Randomizer)> pair_tables{};
  /// A screen-space pixel sampler's image sampler (its draws need the pixel,
  /// not a set per pixel): zsobol's Morton-ordered sequence for an image whose
  /// larger side is `resolution`, for spp samples a pixel and a seed; or a
  /// ranked blue-noise sampler's rank tile for a validated request with its
  /// parameters bound (the committed tile, or the one its `table` names),
  /// over which the renderer builds RankedBlueNoise(tile, spp, seed). Absent
  /// elsewhere.
  std::function<ZSobol(std::uint32_t resolution, std::uint64_t spp, std::uint64_t seed)> zsobol_image{};
  std::function<std::shared_ptr<const BlueNoiseTable>(const SamplerRequest&)> ranked_image{};
  /// The accepted values of --randomize, front() the default: derived from
  /// `randomization` when the registry is built (accepted_randomizers).
  std::vector<std::string> randomizers{};
};

/// Every randomizer name with a one-line description.
const std::vector<std::pair<std::string, std::string>>& randomizers();

/// Every sampler, in a stable order.
const std::vector<SamplerInfo>& samplers();

/// The sampler called `name`; throws invalid_argument listing the valid names.
const SamplerInfo& find_sampler(std::string_view name);
/// The sampler's flags in words, then its other properties: what the
/// listings (`stratum samplers`, Python's samplers()) print.
std::vector<std::string> property_words(const SamplerInfo& sampler);
/// Whether a randomizer (empty: the sampler's default) keeps each point uniform (SamplerFlags::prefix_unbiased).
bool prefix_unbiased(const SamplerInfo& sampler, std::string_view randomize);

/// Validates a request (common checks, then the sampler's own) and throws
/// stratum::invalid_argument naming what is wrong; returns the resolved
/// randomizer name.
std::string validate_request(const SamplerInfo& sampler, const SamplerRequest& request);

/// Validates, then generates. The one entry point the faces call.
PointSet generate_points(std::string_view name, const SamplerRequest& request);

/// Validates, then binds the sampler's generator (the sampler must have
/// one: SamplerInfo::bind; else invalid_argument naming "sampler").
PointGenerator bind_generator(std::string_view name, const SamplerRequest& request);

/// Largest number of coordinates (n × d) stratum will allocate now: the
/// memory guard's memory_available() (stratum/memory.hpp), in doubles.
std::uint64_t max_coordinates();

}  // namespace stratum
