#pragma once
// The registry's points for one request, spelled as the sampler tests use it.
#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include "stratum/registry.hpp"

namespace stratum::testing {

inline PointSet sampler_points(const std::string& name, std::uint64_t n, unsigned d, const std::string& randomize,
                               std::uint64_t seed, std::uint64_t start = 0,
                               std::map<std::string, std::string> params = {}) {
  SamplerRequest request;
  request.n = n;
  request.d = d;
  request.randomize = randomize;
  request.seed = seed;
  request.start = start;
  request.params = std::move(params);
  return generate_points(name, request);
}

}  // namespace stratum::testing
