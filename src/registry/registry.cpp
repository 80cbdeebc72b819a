#include "stratum/registry.hpp"
#include "stratum/registry/generator_binder.hpp"

#include "stratum/memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <limits>
#include <sstream>

#include "families.hpp"
#include "support.hpp"
#include "stratum/util/error.hpp"

namespace stratum {

namespace {
struct RandomizerEntry {
  Randomizer randomizer;
  std::string_view name, description;
};
// Every randomizer: its value, its name and what it does.
constexpr RandomizerEntry randomizer_table[] = {
    {Randomizer::none, "none",
     "no randomization: the deterministic construction (or the pattern's own seeded randomness)"},
    {Randomizer::owen, "owen", "nested uniform scrambling (Owen 1995), exact, in the sequence's base"},
    {Randomizer::owen_hash, "owen-hash", "hash-based Owen scrambling (Burley 2020), base 2"},
    {Randomizer::xor_shift, "xor", "digital shift: XOR (base 2) or digit-wise addition mod b"},
    {Randomizer::lms, "lms",
     "random linear matrix scrambling plus digital shift (Matousek 1998; scipy's scramble=True for Sobol)"},
    {Randomizer::permute, "permute",
     "random digit permutations, one per digit position (Owen 2017, randomized Halton)"},
    {Randomizer::cp, "cp", "Cranley-Patterson rotation: add a random vector modulo 1 (Cranley, Patterson 1976)"},
};
}  // namespace

std::string_view randomizer_name(Randomizer randomizer) {
  for (const auto& entry : randomizer_table)
    if (entry.randomizer == randomizer) return entry.name;
  return "?";
}

Randomizer parse_randomizer(std::string_view name) {
  std::string names;
  for (const auto& entry : randomizer_table) {
    if (entry.name == name) return entry.randomizer;
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  }
  throw invalid_argument("randomize", name.empty() ? "''" : std::string(name), "the randomizers are " + names);
}

std::string_view randomizer_family_name(RandomizerFamily family) {
  switch (family) {
    case RandomizerFamily::base2_digits:
      return "base2-digits";
    case RandomizerFamily::base_b_digits:
      return "base-b-digits";
    case RandomizerFamily::rotation:
      return "rotation";
    case RandomizerFamily::seeded:
      return "seeded";
    case RandomizerFamily::seeded_owen_hash:
      return "seeded-owen-hash";
  }
  return "?";
}

std::vector<Randomizer> accepted_randomizers(const Randomization& randomization) {
  using enum Randomizer;
  std::vector<Randomizer> family;
  switch (randomization.family) {
    case RandomizerFamily::base2_digits:
      family = {owen_hash, none, owen, xor_shift, lms, cp};
      break;
    case RandomizerFamily::base_b_digits:
      family = {permute, none, owen, xor_shift, cp};
      break;
    case RandomizerFamily::rotation:
      family = {none, cp};
      break;
    case RandomizerFamily::seeded:
      family = {none};
      break;
    case RandomizerFamily::seeded_owen_hash:
      family = {owen_hash};
      break;
  }
  const auto place = std::find(family.begin(), family.end(), randomization.default_randomizer);
  if (place == family.end()) return {};  // a default outside the family: samplers() refuses the entry
  std::rotate(family.begin(), place, place + 1);
  return family;
}

const std::vector<std::pair<std::string, std::string>>& randomizers() {
  static const std::vector<std::pair<std::string, std::string>> list = [] {
    std::vector<std::pair<std::string, std::string>> names;
    for (const auto& entry : randomizer_table) names.emplace_back(entry.name, entry.description);
    return names;
  }();
  return list;
}

void PointGenerator::fill(std::uint64_t first, std::uint64_t count, double* out) const {
  for (std::uint64_t k = 0; k < count; ++k)
    for (unsigned j = 0; j < dimensions_; ++j) out[k * dimensions_ + j] = sample_(first + k, j);
}

const std::vector<SamplerInfo>& samplers() {
  static const std::vector<SamplerInfo> all = [] {
    std::vector<SamplerInfo> list;
    namespace f = registry_families;
    for (auto family :
         {f::sequences, f::sobol, f::pmj, f::lattices, f::patterns, f::poisson, f::blue_noise, f::spacetime}) {
      auto part = family();
      list.insert(list.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
    }
    for (SamplerInfo& sampler : list) {
      const std::vector<Randomizer> accepted = accepted_randomizers(sampler.randomization);
      if (accepted.empty())  // a programming error in an entry: fails every test at once
        throw std::logic_error(sampler.name + ": its default randomizer is not one of its family's");
      if (!sampler.generate && sampler.bind)  // sets filled from the generator, rows in parallel
        sampler.generate = [bind = sampler.bind](const SamplerRequest& request) {
          const PointGenerator generator = bind(request);
          return registry_support::fill_index_addressable(
              *request.n, request.d, request.threads,
              [&](std::uint64_t i, unsigned j) { return generator.sample(request.start + i, j); });
        };
      sampler.randomizers.clear();
      for (Randomizer r : accepted) sampler.randomizers.emplace_back(randomizer_name(r));
    }
    return list;
  }();
  return all;
}

const SamplerInfo& find_sampler(std::string_view name) {
  const auto& all = samplers();
  for (const auto& sampler : all)
    if (sampler.name == name) return sampler;
  std::string names;
  for (const auto& sampler : all) names += (names.empty() ? "" : ", ") + sampler.name;
  throw invalid_argument("sampler", std::string(name).empty() ? "''" : std::string(name),
                         "valid samplers are " + names);
}

std::uint64_t max_coordinates() { return memory_available() / sizeof(double); }

static std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::vector<std::string> property_words(const SamplerInfo& sampler) {
  const SamplerFlags& flags = sampler.flags;
  std::vector<std::string> words;
  if (flags.index_addressable) words.emplace_back("index-addressable");
  if (flags.progressive) words.emplace_back("progressive");
  if (flags.frames_continue) words.emplace_back(frames_continue_property);
  if (flags.self_randomized) words.emplace_back("self-randomized");
  if (flags.space_time) words.emplace_back("space-time pattern (x, y, t): render --time-pattern");
  if (flags.zero_two_net) words.emplace_back("(0,m,2)-net in base 2 in dimensions 0-1 at every n = 2^m");
  if (!flags.prefix_unbiased.empty())
    words.push_back("each point uniform on its own (" + join(flags.prefix_unbiased) + "): any prefix unbiased");
  words.insert(words.end(), sampler.properties.begin(), sampler.properties.end());
  return words;
}

bool prefix_unbiased(const SamplerInfo& sampler, std::string_view randomize) {
  const std::string_view resolved = randomize.empty() ? std::string_view(sampler.randomizers.front()) : randomize;
  const auto& list = sampler.flags.prefix_unbiased;
  return std::find(list.begin(), list.end(), resolved) != list.end();
}

std::string validate_request(const SamplerInfo& sampler, const SamplerRequest& request) {
  if (!request.n)
    require(sampler.n_optional && request.radius, "n", "(none)",
            sampler.n_optional ? "give n, or radius for a maximal set" : "n is required for " + sampler.name);
  if (request.n) require(*request.n >= 1, "n", *request.n, "must be a positive integer (" + sampler.counts + ")");
  require(
      request.d >= sampler.min_dim && request.d <= sampler.max_dim, "d", request.d,
      sampler.name + " supports d from " + std::to_string(sampler.min_dim) + " to " + std::to_string(sampler.max_dim));
  require(request.threads >= 1 && request.threads <= 1024, "threads", request.threads, "must be in [1, 1024]");
  if (request.radius)
    require(*request.radius > 0 && *request.radius <= 1, "radius", *request.radius, "must be in (0, 1]");
  if (request.start != 0)
    require(sampler.kind == "sequence" || sampler.flags.progressive || sampler.flags.frames_continue, "start",
            request.start,
            sampler.name +
                " is a finite pattern; only sequences, progressive samplers (random) and pixel samplers "
                "(zsobol, sobol-bn, pmj02-bn, lattice-bn: a later frame) can start past index 0");
  if (request.n)
    require(request.start <= ~std::uint64_t{0} - *request.n, "start", request.start, "start + n must fit in 64 bits");
  const std::string randomize = request.randomize.empty() ? sampler.randomizers.front() : request.randomize;
  if (std::find(sampler.randomizers.begin(), sampler.randomizers.end(), randomize) == sampler.randomizers.end())
    throw invalid_argument("randomize", randomize, sampler.name + " accepts " + join(sampler.randomizers));
  SamplerRequest bound = request;
  bound.values = bind_params(sampler.name, sampler.params, request.params);
  if (sampler.validate) sampler.validate(bound);
  if (const auto count = sampler.count(bound))  // the points themselves (a sampler's own buffers: its validate)
    require_memory(static_cast<double>(*count) * request.d * sizeof(double),
                   std::to_string(*count) + " x " + std::to_string(request.d) + " points of " + sampler.name);
  return randomize;
}

/// The request as the sampler's generate and bind read it: validated,
/// randomizer resolved, parameters bound.
static SamplerRequest resolved_request(const SamplerInfo& sampler, const SamplerRequest& request) {
  SamplerRequest resolved = request;
  resolved.randomize = validate_request(sampler, resolved);
  resolved.randomizer = parse_randomizer(resolved.randomize);
  resolved.values = bind_params(sampler.name, sampler.params, request.params);
  return resolved;
}

PointGenerator bind_generator(std::string_view name, const SamplerRequest& request) {
  const SamplerInfo& sampler = find_sampler(name);
  require(static_cast<bool>(sampler.bind), "sampler", sampler.name,
          "has no per-point generator: its points are made as a whole set (generate_points)");
  return sampler.bind(resolved_request(sampler, request));
}

GeneratorBinder::GeneratorBinder(std::string_view name, const SamplerRequest& request) : sampler_(&find_sampler(name)) {
  require(static_cast<bool>(sampler_->bind), "sampler", sampler_->name,
          "has no per-point generator: its points are made as a whole set (generate_points)");
  require(request.n.has_value(), "n", "(none)", "a generator binder needs the set's n");
  request_ = resolved_request(*sampler_, request);
  if (sampler_->seeded) seeded_ = sampler_->seeded(request_);
}

PointGenerator GeneratorBinder::bind(std::uint64_t seed, std::uint64_t start) {
  request_.seed = seed;
  request_.start = start;
  return sampler_->bind(request_);
}

SetBinder::SetBinder(std::string_view name, const SamplerRequest& request) : sampler_(&find_sampler(name)) {
  require(request.n.has_value(), "n", "(none)", "a set binder needs the set's n");
  request_ = resolved_request(*sampler_, request);
  // A whole set's state is its points 0 … n − 1: a request from another start reads sets (none such today).
  if (!sampler_->bind && sampler_->seeded && request_.start == 0) seeded_ = sampler_->seeded(request_);
}

PointSet SetBinder::generate(std::uint64_t seed) {
  request_.seed = seed;
  return sampler_->generate(request_);
}

PointSet generate_points(std::string_view name, const SamplerRequest& request) {
  const SamplerInfo& sampler = find_sampler(name);
  return sampler.generate(resolved_request(sampler, request));
}

}  // namespace stratum
