#pragma once
/// One request's generator for many seeds: the request is validated once
/// (counts, dimensions, randomizer, parameters, memory: none of which
/// depends on the seed), then bind(seed, start) binds the sampler's
/// generator for that seed without the request handling again, about a
/// microsecond less per set. A renderer binds a set per pixel and dimension
/// (pbrt-v4 likewise reseeds one sampler object per pixel sample). Points
/// equal bind_generator's for the same request and seed (tested).
#include <cstdint>
#include <memory>
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
  /// The request's SeededGenerator, built with the binder, where the
  /// sampler has one (SamplerInfo::seeded), else nullptr: bind's points
  /// for any seed without a binding per seed.
  const std::shared_ptr<const SeededGenerator>& seeded() const noexcept { return seeded_; }

 private:
  const SamplerInfo* sampler_;
  SamplerRequest request_;  ///< resolved: randomizer and parameters bound
  std::shared_ptr<const SeededGenerator> seeded_;
};

/// One request's point sets for many seeds, for every sampler (those made
/// as a whole set too): validated once like GeneratorBinder, then
/// generate(seed) makes the set of that seed with the sampler's own
/// generate, without the request handling (name lookup, validation,
/// parameter binding, memory check) that generate_points repeats per call,
/// most of the cost of a small set. Points equal generate_points' (tested).
class SetBinder {
 public:
  /// Validates `request` (its seed aside: n, d, start, randomizer, parameters) for sampler `name`; throws
  /// invalid_argument as generate_points does.
  SetBinder(std::string_view name, const SamplerRequest& request);
  /// The validated request's set for this seed.
  PointSet generate(std::uint64_t seed);
  std::uint64_t count() const noexcept { return *request_.n; }
  unsigned dimensions() const noexcept { return request_.d; }
  /// Where a sampler made as a whole set (no SamplerInfo::bind) has a
  /// SeededGenerator (SamplerInfo::seeded) and the request starts at 0, the
  /// request's, built with the binder, else nullptr: generate's points for any seed, written into the
  /// caller's state without a set's allocation.
  const std::shared_ptr<const SeededGenerator>& seeded() const noexcept { return seeded_; }

 private:
  const SamplerInfo* sampler_;
  SamplerRequest request_;  ///< resolved: randomizer and parameters bound
  std::shared_ptr<const SeededGenerator> seeded_;
};

}  // namespace stratum
