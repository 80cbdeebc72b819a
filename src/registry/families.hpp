#pragma once
/// The registry's sampler families, one source file each.
#include <vector>

#include "stratum/registry.hpp"

namespace stratum::registry_families {
std::vector<SamplerInfo> sequences();   // samplers_sequences.cpp: halton, hammersley
std::vector<SamplerInfo> sobol();       // samplers_sobol.cpp: sobol, zero-two (the (0,2)-sequence)
std::vector<SamplerInfo> pmj();         // samplers_pmj.cpp: pmj02
std::vector<SamplerInfo> lattices();    // samplers_lattices.cpp: fibonacci, lattice
std::vector<SamplerInfo> patterns();    // samplers_patterns.cpp: random, grid, jittered, n-rooks, ...
std::vector<SamplerInfo> poisson();     // samplers_poisson.cpp: poisson-disk, best-candidate
std::vector<SamplerInfo> blue_noise();  // samplers_blue_noise.cpp: sobol-bn, pmj02-bn, lattice-bn
std::vector<SamplerInfo> spacetime();   // samplers_spacetime.cpp: spacetime-random, -cook, -magic
}  // namespace stratum::registry_families
