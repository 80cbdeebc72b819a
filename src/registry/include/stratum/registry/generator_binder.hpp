#pragma once
/// One request's generator for many seeds: the request is validated once
/// (counts, dimensions, randomizer, parameters, memory: none of which
/// depends on the seed), then bind(seed, start) binds the sampler's
/// generator for that seed without the request handling again, about a
/// microsecond less per set. A renderer binds a set per pixel and dimension
/// (pbrt-v4 likewise reseeds one sampler object per pixel sample). Points
/// equal bind_generator's for the same request and seed (tested).
#include <cstdint>
#include <string_view>

#include "stratum/registry.hpp"

namespace stratum {

class GeneratorBinder {
 public:
  /// Validates `request` (its seed aside) for sampler `name`; throws
  /// invalid_argument as bind_generator does.
  GeneratorBinder(std::string_view name, const SamplerRequest& request);
  /// The generator of the validated request with this seed, and this start
  /// where the sampler continues a sequence (start + n must fit in 64 bits,
  /// and a finite pattern's start is 0: the caller's contract, not checked).
  PointGenerator bind(std::uint64_t seed, std::uint64_t start);
  std::uint64_t count() const noexcept { return *request_.n; }

 private:
  const SamplerInfo* sampler_;
  SamplerRequest request_;  ///< resolved: randomizer and parameters bound
};

}  // namespace stratum
