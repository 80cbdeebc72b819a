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

/// What a caller asks of a sampler.
struct SamplerRequest {
  std::optional<std::uint64_t> n;  ///< absent only where a sampler can choose (maximal Poisson disk)
  unsigned d = 2;
  std::uint64_t seed = 0;
  std::uint64_t start = 0;       ///< index of the first point (sequences only; scipy's fast_forward)
  std::string randomize;         ///< empty: the sampler's default
  std::optional<double> radius;  ///< Poisson disk and friends
  unsigned threads = 1;
  std::map<std::string, std::string> params;  ///< as text ("periodic=1"): every face passes it through unchanged
  /// `params` bound to the sampler's schema (parsed, checked, defaults
  /// filled in) by validate_request and generate_points; entries read
  /// their parameters here.
  ParamValues values{};
};

/// The property of pixel samplers (zsobol, sobol-bn, …) whose point set is
/// one pixel's spp samples and whose `start` continues that pixel's sequence
/// (render --frame K reads samples K·spp … (K+1)·spp − 1).
inline constexpr const char* frames_continue_property = "start continues the pixel's sequence (frames)";

struct SamplerInfo {
  std::string name;
  std::string kind;  ///< "sequence" (index-addressable) or "pattern" (finite set)
  std::string description;
  unsigned min_dim = 1;
  unsigned max_dim = 1;
  std::vector<std::string> properties;
  std::vector<std::string> randomizers;  ///< accepted values of --randomize; front() is the default
  std::string counts;                    ///< which n the sampler takes, in words
  bool n_optional = false;               ///< may n be left out (then `radius` decides)?
  std::vector<Param> params;             ///< the schema of `SamplerRequest::params`
  /// Checks the sampler-specific part of a request (n it can take, params);
  /// throws stratum::invalid_argument.
  std::function<void(const SamplerRequest&)> validate;
  /// Number of points the request will produce, known before generating
  /// (nullopt: only known after, as for a maximal Poisson-disk set).
  std::function<std::optional<std::uint64_t>(const SamplerRequest&)> count;
  /// Fills a validated request's points.
  std::function<PointSet(const SamplerRequest&)> generate;
};

/// Every randomizer name with a one-line description.
const std::vector<std::pair<std::string, std::string>>& randomizers();

/// Every sampler, in a stable order.
const std::vector<SamplerInfo>& samplers();

/// The sampler called `name`; throws invalid_argument listing the valid names.
const SamplerInfo& find_sampler(std::string_view name);
/// Whether the sampler lists `property` (e.g. "progressive", frames_continue_property).
bool has_property(const SamplerInfo& sampler, std::string_view property);

/// Validates a request (common checks, then the sampler's own) and throws
/// stratum::invalid_argument naming what is wrong; returns the resolved
/// randomizer name.
std::string validate_request(const SamplerInfo& sampler, const SamplerRequest& request);

/// Validates, then generates. The one entry point the faces call.
PointSet generate_points(std::string_view name, const SamplerRequest& request);

/// Largest number of coordinates (n × d) stratum will allocate now: the
/// memory guard's memory_available() (stratum/memory.hpp), in doubles.
std::uint64_t max_coordinates();

}  // namespace stratum
