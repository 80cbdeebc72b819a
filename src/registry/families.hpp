#pragma once
/// The registry's sampler families, one source file each.
#include <vector>

#include "stratum/registry.hpp"

namespace stratum::registry_families {
std::vector<SamplerInfo> sequences();   // samplers_sequences.cpp
std::vector<SamplerInfo> patterns();    // samplers_patterns.cpp
std::vector<SamplerInfo> spacetime();   // samplers_spacetime.cpp
}  // namespace stratum::registry_families
