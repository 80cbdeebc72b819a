/// Registry entries: rank-1 lattices.
#include "families.hpp"
#include "support.hpp"

namespace stratum::registry_families {

std::vector<SamplerInfo> lattices() { return {}; }

}  // namespace stratum::registry_families
