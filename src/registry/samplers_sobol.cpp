/// Registry entries: Sobol sequence.
#include "families.hpp"
#include "support.hpp"

namespace stratum::registry_families {

std::vector<SamplerInfo> sobol() { return {}; }

}  // namespace stratum::registry_families
