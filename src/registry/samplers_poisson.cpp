/// Registry entries: Poisson-disk and best-candidate patterns.
#include "families.hpp"
#include "support.hpp"

namespace stratum::registry_families {

std::vector<SamplerInfo> poisson() { return {}; }

}  // namespace stratum::registry_families
